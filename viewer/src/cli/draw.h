// What the commands that draw share: the picture's title and the scene's options.
#pragma once

#include "options.h"

#include "kerf/converter/pipeline.h"
#include "kerf/render/scene.h"
#include "ui/overlay.h"

#include <optional>
#include <string>

namespace kerf::cli {

/// Title (the file's name) and subtitle (dialect, moves, errors and warnings) of a picture.
ui::Annotation annotationOf(const std::string& input, const converter::Pipeline& pipeline);

render::SceneOptions sceneOptionsOf(const MeshOptions& mesh);

}  // namespace kerf::cli

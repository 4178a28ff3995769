// The drawing module (libkerf-draw.so, cli/draw_module.h): the commands that draw, and what they
// share (the picture's title and the scene's options).
#pragma once

#include "commands.h"
#include "options.h"

#include "kerf/converter/pipeline.h"
#include "kerf/render/scene.h"
#include "ui/overlay.h"
#include "ui/picture.h"

#include <optional>
#include <string>

namespace kerf::cli {

/// Title (the file's name) and subtitle (dialect, moves, errors and warnings) of a picture.
ui::Annotation annotationOf(const std::string& input, const converter::Pipeline& pipeline);

render::SceneOptions sceneOptionsOf(const MeshOptions& mesh);
/// --show guides can be drawn (a taper program whose guide heights are known); false after saying why.
bool guidesShowable(const converter::Pipeline& p, const render::SceneOptions& so);

/// --color-by deviation: the part edge coloured by its deviation from --drawing, on a ramp up to
/// twice the tolerance or the worst deviation, whichever is larger, and the legend's range; false
/// (said) without --drawing.
bool colourByDeviation(const converter::Pipeline& pipeline, render::SceneOptions& options, ui::Annotation& legend);

/// The scene of a picture as `kerf render` draws it, coloured by `colourBy` ("slope", "pass",
/// "deviation"; else plain): `so` and `request`'s colouring and annotation filled to match.
/// Nothing, after saying why, when the colouring or --show cannot be had.
std::optional<render::Scene> pictureScene(const converter::Pipeline& pipeline, const std::string& file,
                                          const MeshOptions& mesh, const std::string& colourBy,
                                          ui::PictureRequest& request, render::SceneOptions& so);

/// The first move on `line`; nothing after saying, for `option`, that no move is programmed there
/// and which lines nearest have one (a comment, a blank, past the end is said, not ignored).
std::optional<std::size_t> moveOnLine(const converter::Pipeline& pipeline, std::size_t line, const std::string& option);

int drawRender(const RenderArgs& args);
int drawView(const ViewArgs& args);
int drawExportMesh(const ExportArgs& args);
int drawExportPage(const ExportArgs& args);
std::size_t drawReportPictures(const ReportArgs& args);

}  // namespace kerf::cli

// A block's construction (converter/report/construction.h) as lines, dots and labels to draw on
// top of the scene: `kerf render --explain-line N` and the window's selected block.
#pragma once

#include "kerf/converter/report/construction.h"
#include "kerf/render/scene.h"

#include <vector>

namespace kerf::render {

struct ConstructionScene {
  LineSet lines;                     ///< solid marks (one "move": moveFirst {0, size})
  LineSet dashed;                    ///< the bisector, the programmed segment, the +X ray
  std::vector<Marker> points;        ///< centres, start and end: a dot each (label empty: said by `labels`)
  std::vector<Marker> labels;        ///< each mark's label at its anchor (sizePixels 0: no dot)
  std::vector<std::string> caption;  ///< the block, its words and modes: a box in the picture's corner
};

/// The marks at their planes' heights (a taper move's upper side at planes.upper), arcs within
/// `tolerance` mm. `captionLines` caps the caption (0: none).
ConstructionScene constructionScene(const converter::Construction& construction, const geometry::Planes& planes,
                                    double tolerance, std::size_t captionLines = 24);

/// Grows the box [lo, hi] to hold the construction's lines and dots (a picture frames both).
void extendBounds(const ConstructionScene& construction, geometry::Vec3& lo, geometry::Vec3& hi);

/// The colour a role is drawn in (ABGR, as rgba()).
std::uint32_t constructionColour(converter::ConstructionMark::Role role);

}  // namespace kerf::render

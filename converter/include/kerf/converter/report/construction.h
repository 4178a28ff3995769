// A block's construction, for teaching (docs/teaching.md): the marks that show how its geometry
// follows from its words — the chord and both candidate centres of an R arc, the I J vector, the
// angles, the chords at the step and their largest deviation, a taper move's wire, a wire-offset
// move's programmed segment — and, in sentences, what each word of the block sets and which modes
// it inherits. `kerf render --explain-line N` and the window draw it; the figures are the ones
// `kerf explain` prints (the same functions compute them).
#pragma once

#include "kerf/converter/nc/program.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/segment.h"
#include "kerf/geometry/tessellation.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace kerf::converter {

/// One mark, in the block's plane (XY, mm, the toolpath's frame).
struct ConstructionMark {
  enum class Kind : std::uint8_t {
    Segment,  ///< `segment` drawn: a line or an arc
    Arrow,    ///< a line from segment.start to segment.end with a head at the end
    Point,    ///< segment.start, a dot
    Wire,     ///< the wire: segment.start on the lower plane to segment.end on the upper
  };
  /// What the mark is, which picks its colour.
  enum class Role : std::uint8_t {
    Path,        ///< the block's own segment (lower plane)
    Upper,       ///< a taper move's upper segment
    Chord,       ///< the chord from start to end (an R arc)
    Bisector,    ///< the chord's perpendicular bisector, through both candidate centres
    Centre,      ///< the centre taken
    Rejected,    ///< the centre the sign of R rejects
    Vector,      ///< I J (or 3B's x y): from where the words start to the centre
    Radius,      ///< centre to start
    Angle,       ///< an angle's arc near the centre, or the +X ray it is measured from
    Sample,      ///< the chords at step k
    Deviation,   ///< the largest chord deviation: from the chord's middle to the arc
    Programmed,  ///< a wire-offset move: the segment as programmed
    Offset,      ///< the offset vector from the programmed segment to the wire's
  };
  Kind kind = Kind::Segment;
  Role role = Role::Path;
  geometry::Segment segment;
  bool upper = false;  ///< on the upper plane (a taper move's upper side)
  std::string label;   ///< beside the mark (ASCII: the pictures' font has no Greek); empty: none
};

/// The role's name: "path", "upper", "chord", "bisector", "centre", "rejected", "vector", "radius",
/// "angle", "sample", "deviation", "programmed", "offset" (the 3D page's data and its tests).
const char* markRoleName(ConstructionMark::Role role);

/// One word of the block and what it sets.
struct WordMeaning {
  std::string word;  ///< as written ("X40.", "R40.")
  std::string sets;  ///< "the end point's x: 40.000 mm"
};

struct Construction {
  std::size_t move = 0;
  std::uint32_t line = 0;
  std::string block;  ///< the block's text
  std::vector<ConstructionMark> marks;
  std::vector<WordMeaning> words;  ///< each word of the block in order
  std::vector<std::string> modes;  ///< the modes the block inherits, in sentences
  std::string pass;                ///< "pass 2 of contour 1: a skim", or empty
  /// An arc's largest chord deviation at the sampling, mm: geometry::sample's, as `kerf explain`
  /// prints it (the Deviation mark's label carries the same figure).
  std::optional<double> maxDeviation;
};

/// The construction of move `move` (< toolpath.moves.size()) at `sampling`. `structure` may be null
/// (no passes said). The words are read from the block's text with `parse` (the machine's parse
/// options); 3B records are explained field by field.
Construction constructionOf(const SourceFile& source, const Toolpath& toolpath, const Structure* structure,
                            const geometry::Sampling& sampling, std::size_t move, const ParseOptions& parse = {});

/// What each word of move `move`'s block sets, read with `parse` (empty for a move with no block
/// of its own); `kerf explain` prints the same.
std::vector<WordMeaning> blockWords(const SourceFile& source, const Toolpath& toolpath, std::size_t move,
                                    const ParseOptions& parse = {});
/// The modes move `move` inherits, in sentences.
std::vector<std::string> blockModes(const Toolpath& toolpath, std::size_t move);

/// The first move programmed on 1-based `line`, or nothing.
std::optional<std::size_t> moveOnLine(const Toolpath& toolpath, std::uint32_t line);

}  // namespace kerf::converter

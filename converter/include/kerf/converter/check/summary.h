// Numbers about a program: what `kerf check` prints after the diagnostics.
#pragma once

#include "kerf/converter/check/drawing_check.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/tessellation.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace kerf::converter {

/// The cut segments in order (rapids left out), and for each the index of its Move.
struct CutPath {
  std::vector<geometry::Segment> segments;
  std::vector<std::size_t> moveIndex;
};
CutPath cutPath(const Toolpath& toolpath);

/// The Move of each of a run of segments, as a view: first + k when the moves are contiguous
/// (nothing stored: 4 bytes a segment saved on the usual program), else a table held elsewhere.
class MoveIndex {
 public:
  MoveIndex() = default;
  MoveIndex(std::uint32_t first, std::size_t count) : first_(first), count_(count) {}
  MoveIndex(const std::vector<std::uint32_t>& table) : table_(table.data()), count_(table.size()) {}  // NOLINT

  [[nodiscard]] std::uint32_t operator[](std::size_t k) const {
    return table_ ? table_[k] : first_ + static_cast<std::uint32_t>(k);
  }
  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  [[nodiscard]] std::uint32_t front() const { return (*this)[0]; }
  [[nodiscard]] std::uint32_t back() const { return (*this)[count_ - 1]; }

  class Iterator {
   public:
    Iterator(const MoveIndex* index, std::size_t k) : index_(index), k_(k) {}
    std::uint32_t operator*() const { return (*index_)[k_]; }
    Iterator& operator++() {
      ++k_;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return k_ != o.k_; }

   private:
    const MoveIndex* index_;
    std::size_t k_;
  };
  [[nodiscard]] Iterator begin() const { return {this, 0}; }
  [[nodiscard]] Iterator end() const { return {this, count_}; }

 private:
  const std::uint32_t* table_ = nullptr;
  std::uint32_t first_ = 0;
  std::size_t count_ = 0;
};

/// The cut segments as the checks read them: in place, a view of the moves' lower segments, when
/// no rapid lies between the first cut and the last (the usual program); a copy only otherwise.
/// Move-only, since the views may point into its own copies.
struct CutView {
  geometry::SegmentView segments;
  MoveIndex moveIndex;                  ///< the Move of each segment
  std::vector<geometry::Segment> copy;  ///< what segments shows, when it could not be a view
  std::vector<std::uint32_t> table;     ///< what moveIndex shows, when it could not be first + k

  CutView() = default;
  CutView(CutView&&) = default;
  CutView& operator=(CutView&&) = default;
  CutView(const CutView&) = delete;
  CutView& operator=(const CutView&) = delete;
};
CutView cutView(const Toolpath& toolpath);

/// The measures of the ruled surface of a taper program, one entry per move (rapids too, so the
/// index is the move's).
struct SurfaceMeasures {
  std::vector<geometry::PatchMeasures> patches;
  std::vector<double> areas;  ///< mm^2
};
SurfaceMeasures measureSurface(const Toolpath& toolpath);

/// Where the axes move a taper part's wire: the wire extended to its guides (PlaneHeights::guides).
struct GuideTravel {
  geometry::Box lower, upper;  ///< the guides' paths over the cut moves, mm (each move at 17 points)
  /// The largest |upper guide - lower guide| along X and along Y over the cut moves (what U V travel
  /// between the guides), mm, with the move and line where it is reached: the offset between the
  /// part's faces times the guides' spacing over the part's height.
  double uvX = 0.0, uvY = 0.0;
  std::size_t uvXMove = 0, uvYMove = 0;
  std::uint32_t uvXLine = 0, uvYLine = 0;
};

/// What `kerf check` says about a taper part.
struct TaperSummary {
  Dialect dialect = Dialect::Plain;
  PlaneHeights heights;
  std::size_t patches = 0;  ///< cut moves
  double maxSlopeDegrees = 0.0, minSlopeDegrees = 0.0;
  std::size_t maxSlopeMove = 0, minSlopeMove = 0;
  std::uint32_t maxSlopeLine = 0, minSlopeLine = 0;
  double lowerLength = 0.0, upperLength = 0.0;  ///< mm, cut moves
  double area = 0.0;                            ///< mm^2, cut moves
  std::optional<GuideTravel> guides;            ///< when the guides' heights are known
};

struct Summary {
  InputFormat format = InputFormat::Iso;
  Reading reading;                   ///< machine profile and conventions the program was read with
  Dialect dialect = Dialect::Plain;  ///< how the upper contour was given
  std::size_t blocks = 0;
  std::size_t moves = 0;
  std::size_t cutMoves = 0;
  std::size_t rapidMoves = 0;
  std::size_t lines = 0;  ///< cut moves: lines and arcs of the lower contour (the only one of a 2-axis program)
  std::size_t arcs = 0;
  std::size_t upperLines = 0;  ///< a taper program: lines and arcs of the upper contour's cut moves
  std::size_t upperArcs = 0;
  bool taperProgram = false;  ///< the program has an upper contour (Toolpath::isTaper)
  double cutLength = 0.0;     ///< mm
  double rapidLength = 0.0;   ///< mm
  geometry::Box bounds;       ///< of the cut path
  geometry::Sampling sampling;
  geometry::PathSampleStats points;                  ///< the cut path sampled at `sampling`
  std::optional<TaperSummary> taper;                 ///< taper programs whose heights are known
  Structure structure;                               ///< its contours and their passes (the pipeline fills it)
  std::optional<DrawingComparison> comparison;       ///< against --drawing (the pipeline fills it)
  std::optional<DrawingComparison> comparisonUpper;  ///< the upper plane against --drawing-upper
};

Summary summarize(const Toolpath& toolpath, const geometry::Sampling& sampling,
                  const SurfaceMeasures* measures = nullptr);

/// summarize in parts: the moves' figures in stretches of a fixed length (pieces(), each made by
/// makePiece, in any order and on any thread, different ones at once), then added in order
/// (finish). The figures do not depend on which thread made which stretch.
class SummaryMaker {
 public:
  SummaryMaker(const Toolpath& toolpath, const geometry::Sampling& sampling);
  ~SummaryMaker();
  SummaryMaker(const SummaryMaker&) = delete;
  SummaryMaker& operator=(const SummaryMaker&) = delete;

  [[nodiscard]] std::size_t pieces() const;
  void makePiece(std::size_t k);
  /// The summary, once every piece is made; measures as for summarize.
  [[nodiscard]] Summary finish(const SurfaceMeasures* measures = nullptr) const;

 private:
  struct Stretch;
  const Toolpath& toolpath_;
  geometry::Sampling sampling_;
  std::vector<Stretch> stretches_;
};

}  // namespace kerf::converter

// What every writer shares (writer.h).
#include "kerf/converter/formats/writer.h"

#include <algorithm>

namespace kerf::converter {

bool startCutPathAt(const Toolpath& toolpath, CutPath& path, std::uint32_t startLine, const SourceFile* source,
                    Diagnostics& diags) {
  std::size_t k = 0;
  while (k < path.segments.size() && toolpath.moves[path.moveIndex[k]].line != startLine) ++k;
  if (k == path.segments.size()) {
    diags.error(Code::StartBlockNotFound, source, SourceSpan::wholeFile(),
                "no cutting move comes from line " + std::to_string(startLine));
    return false;
  }
  const auto at = static_cast<std::ptrdiff_t>(k);
  const bool closed = (path.segments.back().end - path.segments.front().start).norm() <= 1e-6;
  if (closed) {
    std::rotate(path.segments.begin(), path.segments.begin() + at, path.segments.end());
    std::rotate(path.moveIndex.begin(), path.moveIndex.begin() + at, path.moveIndex.end());
  } else if (k > 0) {
    diags.warning(Code::StartBlockNotFound, source, toolpath.moves[path.moveIndex[k]].span,
                  "the cut path is open: the " + std::to_string(k) + " cutting moves before this one are left out");
    path.segments.erase(path.segments.begin(), path.segments.begin() + at);
    path.moveIndex.erase(path.moveIndex.begin(), path.moveIndex.begin() + at);
  }
  return true;
}

}  // namespace kerf::converter

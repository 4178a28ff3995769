// A finding of the checks at one move (internal to check/): its block's text, the move's index and
// a point on it, for the picture's markers and the JSON.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"

#include <string>
#include <utility>

namespace kerf::converter {

inline Diagnostic finding(Severity sev, Code code, const SourceFile* src, const Move& move, std::size_t moveIndex,
                          const geometry::Vec3& p, std::string message, std::string help = {}) {
  Diagnostic d;
  d.severity = sev;
  d.code = code;
  d.source = src;
  d.span = move.span;
  d.message = std::move(message);
  d.help = std::move(help);
  d.move = moveIndex;
  d.point = p;
  return d;
}

inline geometry::Vec3 at3(const geometry::Vec2& p, double z) { return {p.x(), p.y(), z}; }

}  // namespace kerf::converter

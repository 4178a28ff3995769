// Which 4-axis dialect a program is written in (docs/taper.md), from the words present, the
// machine profile and, where neither decides, the numbers.
#pragma once

#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/toolpath.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

struct DialectDetection {
  Dialect dialect = Dialect::Plain;
  std::string reason;               ///< the evidence, e.g. "M101 P on line 3"
  SourceSpan span;                  ///< where that evidence is
  std::vector<Dialect> candidates;  ///< more than one: the words fit several dialects
  [[nodiscard]] bool ambiguous() const { return candidates.size() > 1; }
};

/// Evidence, strongest first: ':' -> sodick-colon; G51/G52 -> taper-angle; G140-G142 ->
/// sodick-colon. U/V outside G92: xyuv-abs when a block carries a second motion word or a second
/// I J / R for the upper side, or M100/M101; xyuv-linuxcnc with an (AXIS,…_Z_POS) comment;
/// xyuv-rel when K/L appear with U/V or G92 carries I J (NCVC heights). With no such word, or
/// words of both kinds: what the machine profile says U V mean; then the numbers — U V that follow
/// X Y (|U - X| small against |U|) are absolute, U V small against their distance from X Y are
/// relative. Otherwise ambiguous.
DialectDetection detectDialect(const Program& program, const MachineProfile& machine);

/// "auto" gives nothing; an unknown name gives nothing too (the caller checks the list).
std::optional<Dialect> parseDialect(std::string_view name);

/// Where a piece of evidence is, as the detection notes say it: "G51 on line 12".
std::string onLine(const std::string& what, std::uint32_t line);

}  // namespace kerf::converter

// Wire offsets by register (docs/passes.md, "Offset registers"): the values G41/G42 D.. or H..
// take when the program's own table (Sodick `H001 = ...;`) does not give them, from an
// `--offsets FILE` or a machine profile's `offset H001 = 0.180` lines.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

/// Register name ("H001", "D012") to the offset in mm (>= 0).
using OffsetTable = std::map<std::string, double>;

/// The largest offset a table may give, mm: no wire plus spark gap is a centimetre.
inline constexpr double kLargestTableOffset = 10.0;

/// "H001" for `H1`, `h001` or `H 1`; empty when the text is not D or H and a whole number of at most
/// three digits.
std::string offsetRegisterName(std::string_view text);

/// Reads an offset table file: one `REGISTER = VALUE` a line (`H001 = 0.180`, `D1 = 0.15`), mm,
/// blank lines and `#` comments allowed. Each wrong line, a value that is not a number in
/// [0, 10] mm and a register given twice is an error (K0811) at its line; nullopt when any.
std::optional<OffsetTable> readOffsetTable(const SourceFile& file, Diagnostics& diags);

}  // namespace kerf::converter

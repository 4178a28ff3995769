// Offset tables (offset_table.h): the register names and the `--offsets FILE` format.
#include "kerf/converter/interpret/offset_table.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>

namespace kerf::converter {

std::string offsetRegisterName(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  if (i >= text.size()) return {};
  const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
  if (letter != 'D' && letter != 'H') return {};
  ++i;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  std::size_t end = text.size();
  while (end > i && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  if (i == end || end - i > 3) return {};
  int number = 0;
  for (std::size_t k = i; k < end; ++k) {
    if (text[k] < '0' || text[k] > '9') return {};
    number = number * 10 + (text[k] - '0');
  }
  char name[16];  // the letter and at most three digits; room for any int, which the format must allow
  std::snprintf(name, sizeof name, "%c%03d", letter, number);
  return name;
}

std::optional<OffsetTable> readOffsetTable(const SourceFile& file, Diagnostics& diags) {
  OffsetTable table;
  bool ok = true;
  for (std::uint32_t line = 1; line <= file.lineCount(); ++line) {
    // Not a structured binding: clang 14 (the fuzz build) does not let a lambda capture one.
    const std::pair<std::uint32_t, std::uint32_t> range = file.lineRange(line);
    const std::uint32_t begin = range.first;
    std::string_view text = file.text().substr(begin, range.second - begin);
    if (const std::size_t hash = text.find('#'); hash != std::string_view::npos) text = text.substr(0, hash);
    if (text.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    auto fail = [&](std::size_t at, std::size_t length, std::string message) {
      diags.error(
          Code::OffsetTableError, &file,
          {static_cast<std::uint32_t>(begin + at), static_cast<std::uint32_t>(std::max<std::size_t>(1, length))},
          std::move(message), "write one register a line: H001 = 0.180 (mm)");
      ok = false;
    };
    const std::size_t lead = text.find_first_not_of(" \t");
    const std::size_t eq = text.find('=');
    if (eq == std::string_view::npos) {
      fail(lead, text.size() - lead, "expected 'REGISTER = VALUE'");
      continue;
    }
    const std::string name = offsetRegisterName(text.substr(0, eq));
    if (name.empty()) {
      fail(lead, eq - lead, "'" + std::string(text.substr(lead, eq - lead)) + "' is not a D or H register");
      continue;
    }
    double value = 0.0;
    const std::string_view field = text.substr(eq + 1);
    if (!parseNumberField(field, value) || value < 0.0 || value > kLargestTableOffset) {
      fail(eq + 1, field.size(), name + ": '" + std::string(field) + "' is not an offset from 0 to 10 mm");
      continue;
    }
    if (!table.emplace(name, value).second) fail(lead, eq - lead, name + " is given twice");
  }
  if (!ok) return std::nullopt;
  return table;
}

}  // namespace kerf::converter

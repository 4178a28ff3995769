// SARIF 2.1.0 and JUnit XML reports (ci_report.h).
//
// SARIF: OASIS Static Analysis Results Interchange Format 2.1.0 — sarifLog, run, tool.driver with
// reportingDescriptor rules, result with ruleId/ruleIndex, level, message and physicalLocation
// (artifactLocation.uri, region startLine/startColumn/endLine/endColumn, 1-based). The tests check
// the output with Microsoft's SARIF Multitool (`validate`), not with our reading of the spec.
#include "kerf/converter/ci_report.h"

#include "kerf/converter/source.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>

namespace kerf::converter {
namespace docs {
extern const char* const kDiagnosticsMd;  // docs/diagnostics.md, compiled in (converter/CMakeLists.txt)
}

namespace {

using json = nlohmann::ordered_json;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// Markdown of a table cell as plain text: no code ticks, `\|` as `|`.
std::string plain(std::string_view cell) {
  std::string out;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    if (cell[i] == '`') continue;
    if (cell[i] == '\\' && i + 1 < cell.size() && cell[i + 1] == '|') continue;
    out += cell[i];
  }
  return out;
}

/// The cells of a table row `| a | b \| c | d |`: a `\|` stays inside its cell.
std::vector<std::string_view> cells(std::string_view row) {
  std::vector<std::string_view> out;
  std::size_t start = 1;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      out.push_back(trim(row.substr(start, i - start)));
      start = i + 1;
    }
  }
  return out;
}

std::vector<CodeInfo> readCodeTable() {
  std::vector<CodeInfo> codes;
  const std::string_view text = docs::kDiagnosticsMd;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    if (!line.starts_with("| K")) continue;
    const std::vector<std::string_view> c = cells(line);
    if (c.size() < 3) continue;
    CodeInfo info;
    info.id = std::string(c[0]);
    info.name = std::string(c[1]);
    const std::string_view meaning = c[2];
    const std::size_t colon = meaning.find(':');
    info.severityText = std::string(trim(meaning.substr(0, colon)));
    info.meaning = plain(colon == std::string_view::npos ? meaning : trim(meaning.substr(colon + 1)));
    info.severity = info.severityText.starts_with("error")     ? Severity::Error
                    : info.severityText.starts_with("warning") ? Severity::Warning
                                                               : Severity::Note;
    codes.push_back(std::move(info));
  }
  return codes;
}

/// A file name as a URI reference (RFC 3986; RFC 8089 for an absolute path, file:///...):
/// unreserved characters and '/' stay, others are percent-encoded, so names with spaces or
/// non-ASCII bytes stay valid.
std::string uriOf(const std::string& name) {
  // An absolute path is a file URI (SARIF1004: a URI reference with no scheme must be relative).
  // Without dot segments (SARIF1002): /a/b/../c is /a/c.
  const std::string path = std::filesystem::path(name).lexically_normal().generic_string();
  std::string out = path.starts_with('/') ? "file://" : "";
  for (const char ch : path) {
    const auto c = static_cast<unsigned char>(ch);
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                      c == '.' || c == '_' || c == '~' || c == '/';
    if (keep) {
      out += ch;
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

json sarifResult(const Diagnostic& d, const std::map<std::string, std::size_t>& ruleIndex) {
  json r;
  const std::string id = codeName(d.code);
  r["ruleId"] = id;
  if (const auto it = ruleIndex.find(id); it != ruleIndex.end()) r["ruleIndex"] = it->second;
  r["level"] = severityName(d.severity);  // SARIF's levels error, warning, note are the severities' names
  r["message"] = {{"text", d.help.empty() ? d.message : d.message + " (help: " + d.help + ")"}};
  if (d.source) {
    json physical;
    physical["artifactLocation"] = {{"uri", uriOf(d.source->name())}};
    if (d.span.isWholeFile()) {  // a finding about the whole program: all of its lines
      physical["region"] = {{"startLine", 1}, {"endLine", std::max<std::uint32_t>(1, d.source->lineCount())}};
    } else {
      const SourceLocation from = d.source->locate(d.span.offset);
      const SourceLocation to = d.source->locate(d.span.offset + d.span.length);
      json region;
      region["startLine"] = from.line;
      region["startColumn"] = from.column;
      // The end column is the first column after the span (exclusive), on the span's last line.
      region["endLine"] = std::max(from.line, to.line);
      region["endColumn"] = to.line > from.line ? to.column : std::max(to.column, from.column + 1);
      physical["region"] = std::move(region);
    }
    r["locations"] = json::array({{{"physicalLocation", std::move(physical)}}});
  }
  json properties = json::object();
  if (d.point) properties["point"] = json::array({d.point->x(), d.point->y(), d.point->z()});
  if (d.move) properties["move"] = *d.move;
  if (!properties.empty()) r["properties"] = std::move(properties);
  return r;
}

std::string xmlEscaped(std::string_view s) {
  std::string out;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 has no control characters but tab, line feed and carriage return.
        if (c < 0x20 && ch != '\t' && ch != '\n' && ch != '\r')
          out += '?';
        else
          out += ch;
    }
  }
  return out;
}

}  // namespace

const std::vector<CodeInfo>& diagnosticCodes() {
  static const std::vector<CodeInfo> codes = readCodeTable();
  return codes;
}

std::string sarifLog(std::span<const CheckedFile> files, const std::string& version) {
  json rules = json::array();
  std::map<std::string, std::size_t> ruleIndex;
  for (const CodeInfo& c : diagnosticCodes()) {
    ruleIndex.emplace(c.id, rules.size());
    rules.push_back({{"id", c.id},
                     {"name", c.name},
                     {"shortDescription", {{"text", c.meaning}}},
                     {"fullDescription", {{"text", c.severityText + ": " + c.meaning}}},
                     {"help",
                      {{"text", c.id + " (" + c.name + "), " + c.severityText + ": " + c.meaning +
                                    ". docs/diagnostics.md lists every code."}}},
                     {"defaultConfiguration", {{"level", severityName(c.severity)}}}});
  }
  json results = json::array();
  json artifacts = json::array();
  json notifications = json::array();
  for (const CheckedFile& f : files) {
    artifacts.push_back({{"location", {{"uri", uriOf(f.name)}}}});
    if (!f.failure.empty())
      notifications.push_back(
          {{"level", "error"},
           {"message", {{"text", f.name + ": " + f.failure}}},
           {"locations", json::array({{{"physicalLocation", {{"artifactLocation", {{"uri", uriOf(f.name)}}}}}}})}});
    if (f.diags)
      for (const Diagnostic& d : f.diags->all()) results.push_back(sarifResult(d, ruleIndex));
  }
  json invocation;
  invocation["executionSuccessful"] = notifications.empty();
  if (!notifications.empty()) invocation["toolExecutionNotifications"] = std::move(notifications);
  json run;
  run["tool"] = {
      {"driver", {{"name", "kerf"}, {"version", version}, {"semanticVersion", version}, {"rules", std::move(rules)}}}};
  run["invocations"] = json::array({std::move(invocation)});
  run["artifacts"] = std::move(artifacts);
  run["results"] = std::move(results);
  // Kerf counts columns in bytes; for the ASCII text of NC programs that is the code point.
  run["columnKind"] = "unicodeCodePoints";
  json log;
  log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = json::array({std::move(run)});
  return log.dump(2) + "\n";
}

std::string junitReport(std::span<const CheckedFile> files) {
  std::size_t failures = 0, errors = 0;
  std::string cases;
  for (const CheckedFile& f : files) {
    cases += "    <testcase classname=\"kerf.check\" name=\"" + xmlEscaped(f.name) + "\">\n";
    std::string failed, other;
    std::size_t errorCount = 0;
    if (f.diags) {
      for (const Diagnostic& d : f.diags->all()) {
        std::string line =
            formatLocation(d) + ": " + severityName(d.severity) + ": " + d.message + " [" + codeName(d.code) + "]\n";
        if (d.severity == Severity::Error) {
          failed += line;
          ++errorCount;
        } else {
          other += line;
        }
      }
    }
    if (!f.failure.empty()) {
      ++errors;
      cases += "      <error message=\"" + xmlEscaped(f.failure) + "\" type=\"unreadable\">" + xmlEscaped(failed) +
               "</error>\n";
    } else if (f.diags && f.diags->hasErrors()) {
      ++failures;
      const std::size_t total = f.diags->errorCount();
      cases += "      <failure message=\"" + std::to_string(total) + (total == 1 ? " error" : " errors") +
               "\" type=\"kerf.check\">" + xmlEscaped(failed) +
               (total > errorCount ? xmlEscaped("(" + std::to_string(total - errorCount) + " more errors not shown)\n")
                                   : std::string()) +
               "</failure>\n";
    }
    if (!other.empty()) cases += "      <system-out>" + xmlEscaped(other) + "</system-out>\n";
    cases += "    </testcase>\n";
  }
  const std::string counts = "tests=\"" + std::to_string(files.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"kerf check\" " + counts +
         ">\n  <testsuite name=\"kerf check\" " + counts + ">\n" + cases + "  </testsuite>\n</testsuites>\n";
}

}  // namespace kerf::converter

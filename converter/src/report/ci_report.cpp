// SARIF 2.1.0 and JUnit XML reports (ci_report.h).
//
// SARIF: OASIS Static Analysis Results Interchange Format 2.1.0 — sarifLog, run, tool.driver with
// reportingDescriptor rules, result with ruleId/ruleIndex, level, message and physicalLocation
// (artifactLocation.uri, region startLine/startColumn/endLine/endColumn, 1-based). The tests check
// the output with Microsoft's SARIF Multitool (`validate`), not with our reading of the spec.
#include "kerf/converter/report/ci_report.h"
#include "kerf/converter/report/html.h"

#include "kerf/converter/nc/source.h"
#include "kerf/converter/report/report.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>

namespace kerf::converter {
namespace {

using OrderedJson = nlohmann::ordered_json;

/// A meaning's Markdown as plain text: no code ticks, `\|` as `|`.
std::string plain(std::string_view markdown) {
  std::string out;
  for (std::size_t i = 0; i < markdown.size(); ++i) {
    if (markdown[i] == '`') continue;
    if (markdown[i] == '\\' && i + 1 < markdown.size() && markdown[i + 1] == '|') continue;
    out += markdown[i];
  }
  return out;
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

OrderedJson sarifResult(const Diagnostic& d, const std::map<std::string, std::size_t>& ruleIndex) {
  OrderedJson r;
  const std::string id = codeName(d.code);
  r["ruleId"] = id;
  if (const auto it = ruleIndex.find(id); it != ruleIndex.end()) r["ruleIndex"] = it->second;
  r["level"] = severityName(d.severity);  // SARIF's levels error, warning, note are the severities' names
  r["message"] = {{"text", d.help.empty() ? d.message : d.message + " (help: " + d.help + ")"}};
  if (d.source) {
    OrderedJson physical;
    physical["artifactLocation"] = {{"uri", uriOf(d.source->name())}};
    if (d.span.isWholeFile()) {  // a finding about the whole program: all of its lines
      physical["region"] = {{"startLine", 1}, {"endLine", std::max<std::uint32_t>(1, d.source->lineCount())}};
    } else {
      const SourceLocation from = d.source->locate(d.span.offset);
      const SourceLocation to = d.source->locate(d.span.offset + d.span.length);
      OrderedJson region;
      region["startLine"] = from.line;
      region["startColumn"] = from.column;
      // The end column is the first column after the span (exclusive), on the span's last line.
      region["endLine"] = std::max(from.line, to.line);
      region["endColumn"] = to.line > from.line ? to.column : std::max(to.column, from.column + 1);
      physical["region"] = std::move(region);
    }
    r["locations"] = OrderedJson::array({{{"physicalLocation", std::move(physical)}}});
  }
  OrderedJson properties = OrderedJson::object();
  if (d.point) properties["point"] = OrderedJson::array({d.point->x(), d.point->y(), d.point->z()});
  if (d.move) properties["move"] = *d.move;
  if (!properties.empty()) r["properties"] = std::move(properties);
  return r;
}

}  // namespace

std::string sarifLog(std::span<const CheckedFile> files, const std::string& version) {
  OrderedJson rules = OrderedJson::array();
  std::map<std::string, std::size_t> ruleIndex;
  for (const CodeInfo& c : diagnosticCodes()) {
    const std::string id = codeName(c.code), name(c.name), words(c.severityText), meaning = plain(c.meaning);
    ruleIndex.emplace(id, rules.size());
    rules.push_back(
        {{"id", id},
         {"name", name},
         {"shortDescription", {{"text", meaning}}},
         {"fullDescription", {{"text", words + ": " + meaning}}},
         {"help",
          {{"text", id + " (" + name + "), " + words + ": " + meaning + ". docs/diagnostics.md lists every code."}}},
         {"defaultConfiguration", {{"level", severityName(c.severity)}}}});
  }
  OrderedJson results = OrderedJson::array();
  OrderedJson artifacts = OrderedJson::array();
  OrderedJson notifications = OrderedJson::array();
  for (const CheckedFile& f : files) {
    OrderedJson artifact = {{"location", {{"uri", uriOf(f.name)}}}};
    if (f.structure) artifact["properties"] = {{"structure", OrderedJson::parse(structureJson(*f.structure))}};
    artifacts.push_back(std::move(artifact));
    if (!f.failure.empty())
      notifications.push_back(
          {{"level", "error"},
           {"message", {{"text", f.name + ": " + f.failure}}},
           {"locations",
            OrderedJson::array({{{"physicalLocation", {{"artifactLocation", {{"uri", uriOf(f.name)}}}}}}})}});
    if (f.diags)
      for (const Diagnostic& d : f.diags->all()) results.push_back(sarifResult(d, ruleIndex));
  }
  OrderedJson invocation;
  invocation["executionSuccessful"] = notifications.empty();
  if (!notifications.empty()) invocation["toolExecutionNotifications"] = std::move(notifications);
  OrderedJson run;
  run["tool"] = {
      {"driver", {{"name", "kerf"}, {"version", version}, {"semanticVersion", version}, {"rules", std::move(rules)}}}};
  run["invocations"] = OrderedJson::array({std::move(invocation)});
  run["artifacts"] = std::move(artifacts);
  run["results"] = std::move(results);
  // Kerf counts columns in bytes; for the ASCII text of NC programs that is the code point.
  run["columnKind"] = "unicodeCodePoints";
  OrderedJson log;
  log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = OrderedJson::array({std::move(run)});
  return log.dump(2) + "\n";
}

std::string junitReport(std::span<const CheckedFile> files) {
  std::size_t failures = 0, errors = 0;
  std::string cases;
  for (const CheckedFile& f : files) {
    cases += "    <testcase classname=\"kerf.check\" name=\"" + markupText(f.name) + "\">\n";
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
      cases += "      <error message=\"" + markupText(f.failure) + "\" type=\"unreadable\">" + markupText(failed) +
               "</error>\n";
    } else if (f.diags && f.diags->hasErrors()) {
      ++failures;
      const std::size_t total = f.diags->errorCount();
      cases += "      <failure message=\"" + std::to_string(total) + (total == 1 ? " error" : " errors") +
               "\" type=\"kerf.check\">" + markupText(failed) +
               (total > errorCount ? markupText("(" + std::to_string(total - errorCount) + " more errors not shown)\n")
                                   : std::string()) +
               "</failure>\n";
    }
    if (!other.empty()) cases += "      <system-out>" + markupText(other) + "</system-out>\n";
    cases += "    </testcase>\n";
  }
  const std::string counts = "tests=\"" + std::to_string(files.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"kerf check\" " + counts +
         ">\n  <testsuite name=\"kerf check\" " + counts + ">\n" + cases + "  </testsuite>\n</testsuites>\n";
}

}  // namespace kerf::converter

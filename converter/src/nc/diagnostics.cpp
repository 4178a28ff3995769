#include "kerf/converter/nc/diagnostics.h"

#include <algorithm>
#include <cstdio>

namespace kerf::converter {

std::string codeName(Code code) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "K%04u", static_cast<unsigned>(code));
  return buf;
}

namespace {

constexpr CodeInfo kCodes[] = {
#define KERF_CODE_INFO(number, name, severity, words, meaning) {Code::name, #name, Severity::severity, words, meaning},
    KERF_DIAGNOSTIC_TABLE(KERF_CODE_INFO)
#undef KERF_CODE_INFO
};

}  // namespace

std::span<const CodeInfo> diagnosticCodes() { return kCodes; }

const CodeInfo& codeInfo(Code code) {
  // The table is in ascending order (tests/unit/diagnostics_test.cpp keeps it so).
  const auto* it = std::lower_bound(std::begin(kCodes), std::end(kCodes), code,
                                    [](const CodeInfo& c, Code k) { return c.code < k; });
  return it != std::end(kCodes) && it->code == code ? *it : kCodes[0];
}

std::string diagnosticsMarkdown() {
  std::string md = R"(# Diagnostic codes

Stable codes; the text may improve, the code stays. `kerf check` prints them compiler style:

```
part.nc:12:7: error: arc radius 4.000 is shorter than half the chord 5.000 mm [K0302]
    G02 X10. Y0 R4.
                ^~~
```

This page is made from the table in `converter/include/kerf/converter/nc/diagnostic_table.h`, the one
source of the codes, their severities and meanings (a test keeps the two equal:
`KERF_UPDATE_GOLDEN=1` rewrites this page). The hundreds are the family: 1 reading the text, 2
words and modal state, 3 arcs, 4 motion, 5 program flow, 6 the geometry of the cut, 7 numbers, 8
outputs and options, 9 the wire offset.

| code | name | severity and meaning |
|---|---|---|
)";
  for (const CodeInfo& c : kCodes) {
    md += "| " + codeName(c.code) + " | ";
    md += c.name;
    md += " | ";
    md += c.severityText;
    md += ": ";
    md += c.meaning;
    md += " |\n";
  }
  md += R"(
Exit codes of `kerf`: 0 no errors (warnings and notes allowed), 1 errors in the program, 2 usage or
file problems (a file that cannot be read, a wrong machine profile, an output that cannot be
written, standard output lost). With several files, the worst of them.

A code has one meaning. Where one meaning was split from another, the old code kept the first:
K0205 (letters) gave K0222, K0223, K0224 and K0225; K0220 (two files) gave K0226 and K0227; K0304
(lower arc) gave K0306; K0604 (retrace) gave K0609; K0201 (unknown G) gave K0236; K0606 (nothing
to cut) gave K0813 (a writer with nothing to write), K0814 (an option the input cannot take) and
K0635 (an empty `--drawing`); K0210 (offset not applied) gave K0901 (offset applied).

Renumbered once, when the wire offset became a family of its own: K0126 → K0902 (WireCannotReach),
K0127 → K0903 (InsideCornerRadius), K0128 → K0904 (WirePathSplits), K0129 → K0905
(WireOffsetRefused). A 3B program's single `D` (a pause) is K0231, as a machine's codes are, no
longer K0205.
)";
  return md;
}

const char* severityName(Severity s) {
  switch (s) {
    case Severity::Note: return "note";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
  }
  return "error";
}

void Diagnostics::report(Diagnostic d) {
  if (d.severity == Severity::Error) ++errors_;
  if (d.severity == Severity::Warning) ++warnings_;
  if (items_.size() >= cap_) {
    ++dropped_;
    return;
  }
  items_.push_back(std::move(d));
}

std::optional<Severity> DiagnosticPolicy::levelOf(const Diagnostic& d) const {
  auto named = [&](const std::vector<Code>& codes) {
    return std::find(codes.begin(), codes.end(), d.code) != codes.end();
  };
  if (d.severity == Severity::Error) return Severity::Error;
  if (named(silenced)) return std::nullopt;
  if (named(promoted) || (warningsAreErrors && d.severity == Severity::Warning)) return Severity::Error;
  return d.severity;
}

Diagnostics Diagnostics::under(const DiagnosticPolicy& policy) const {
  Diagnostics out(cap_);
  std::size_t seenErrors = 0, seenWarnings = 0;
  for (const Diagnostic& d : items_) {
    seenErrors += d.severity == Severity::Error;
    seenWarnings += d.severity == Severity::Warning;
    const std::optional<Severity> level = policy.levelOf(d);
    if (!level) continue;
    Diagnostic copy = d;
    copy.severity = *level;
    out.report(std::move(copy));
  }
  out.errors_ += errors_ - seenErrors;
  out.warnings_ += warnings_ - seenWarnings;
  out.dropped_ += dropped_;
  return out;
}

void Diagnostics::append(Diagnostics&& later) {
  errors_ += later.errors_;
  warnings_ += later.warnings_;
  dropped_ += later.dropped_;
  for (Diagnostic& d : later.items_) {
    if (items_.size() >= cap_)
      ++dropped_;
    else
      items_.push_back(std::move(d));
  }
  later = Diagnostics(later.cap_);
}

void Diagnostics::error(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help) {
  report({Severity::Error, code, src, span, std::move(message), std::move(help), std::nullopt, std::nullopt});
}
void Diagnostics::warning(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help) {
  report({Severity::Warning, code, src, span, std::move(message), std::move(help), std::nullopt, std::nullopt});
}

void Diagnostics::note(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help) {
  report({Severity::Note, code, src, span, std::move(message), std::move(help), std::nullopt, std::nullopt});
}

void Diagnostics::sortByPosition() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    // Not tied to a place first (options, whole-file findings), then by position.
    const bool aNowhere = a.source == nullptr || a.span.isWholeFile();
    const bool bNowhere = b.source == nullptr || b.span.isWholeFile();
    if (aNowhere != bNowhere) return aNowhere;
    return a.span.offset < b.span.offset;
  });
}

std::string formatLocation(const Diagnostic& d) {
  if (!d.source) return "kerf";
  if (d.span.isWholeFile()) return d.source->name();
  const SourceLocation loc = d.source->locate(d.span.offset);
  return d.source->name() + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

namespace {

/// The diagnostic's line with a caret under its span, or why the line is not shown.
void appendQuote(std::string& out, const Diagnostic& d) {
  const SourceLocation loc = d.source->locate(d.span.offset);
  std::string_view text = d.source->lineText(loc.line);
  std::size_t col = loc.column - 1;
  // Long lines are shown as a window around the column, so a binary file or a megabyte-long
  // line cannot flood the terminal.
  constexpr std::size_t kBefore = 40, kWidth = 100;
  std::string prefix, suffix;
  if (text.size() > kWidth) {
    const std::size_t from = col > kBefore ? col - kBefore : 0;
    if (from > 0) prefix = "...";
    if (from + kWidth < text.size()) suffix = "...";
    text = text.substr(from, kWidth);
    col = col - from + prefix.size();
  }
  out += "    " + prefix;
  // Control and non-ASCII bytes would garble the terminal; show them as '?'.
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    out += ((u < 0x20 && c != '\t') || u >= 0x7f) ? '?' : c;
  }
  out += suffix + "\n    ";
  const std::string shown = prefix + std::string(text);
  for (std::size_t i = 0; i < col && i < shown.size(); ++i) out += shown[i] == '\t' ? '\t' : ' ';
  out += '^';
  const std::size_t room = shown.size() > col ? shown.size() - col : 0;
  const std::size_t tail = std::min<std::size_t>(d.span.length > 0 ? d.span.length - 1 : 0, room > 0 ? room - 1 : 0);
  out.append(tail, '~');
  out += '\n';
}

}  // namespace

std::string formatDiagnostic(const Diagnostic& d) {
  std::string out =
      formatLocation(d) + ": " + severityName(d.severity) + ": " + d.message + " [" + codeName(d.code) + "]\n";
  if (d.source && !d.span.isWholeFile()) appendQuote(out, d);
  if (!d.help.empty()) out += "    help: " + d.help + "\n";
  return out;
}

}  // namespace kerf::converter

#include "kerf/converter/diagnostics.h"

#include <algorithm>
#include <cstdio>

namespace kerf::converter {

std::string codeName(Code code) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "K%04u", static_cast<unsigned>(code));
  return buf;
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
  if (d.source->changedOnDisk()) {  // read again for the quote, and no longer what was checked
    out += "    (the file changed after it was read: its line is not quoted)\n";
    return;
  }
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

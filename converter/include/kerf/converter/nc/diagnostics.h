// Diagnostics: what Kerf says about a program, compiler style.
//
//   part.nc:12:7: error: arc radius 4.000 is shorter than half the chord 5.000 [K0302]
//       G02 X10. Y0 R4.
//                   ^~~
// Every diagnostic has a stable code (diagnostic_table.h; docs/diagnostics.md lists them), a
// severity and a span.
#pragma once

#include "kerf/converter/nc/diagnostic_table.h"
#include "kerf/converter/nc/source.h"
#include "kerf/geometry/vec.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

enum class Severity : std::uint8_t { Note, Warning, Error };

/// Stable diagnostic codes, from the one table (diagnostic_table.h). The number is the code users
/// see: K0302 is Code::RadiusTooSmall.
enum class Code : std::uint16_t {
#define KERF_CODE_ENUMERATOR(number, name, ...) name = number,
  KERF_DIAGNOSTIC_TABLE(KERF_CODE_ENUMERATOR)
#undef KERF_CODE_ENUMERATOR
};

/// One row of the table (diagnostic_table.h).
struct CodeInfo {
  Code code{};
  std::string_view name;          ///< "RadiusTooSmall"
  Severity severity{};            ///< the usual severity (a SARIF rule's default level)
  std::string_view severityText;  ///< as documented: "error", "note/warning", ...
  std::string_view meaning;       ///< one line of Markdown
};

/// Every code, in ascending order.
std::span<const CodeInfo> diagnosticCodes();
/// The row of a code (every Code has one).
const CodeInfo& codeInfo(Code code);
/// docs/diagnostics.md as the table makes it: the prose around it and one row per code.
std::string diagnosticsMarkdown();

/// "K0302" for Code::RadiusTooSmall.
std::string codeName(Code code);
const char* severityName(Severity s);

struct Diagnostic {
  Severity severity = Severity::Error;
  Code code = Code::UnexpectedCharacter;
  const SourceFile* source = nullptr;  ///< null: not tied to a file (options, emitters)
  SourceSpan span;
  std::string message;
  std::string help;  ///< optional "did you mean ..." or how to fix it
  // Geometric findings also name the move (index into Toolpath::moves) and a 3D point (z = 0 on
  // the program plane), so the report, the picture and the window show the same place.
  std::optional<std::size_t> move;
  std::optional<geometry::Vec3> point;
};

/// What the user asked of the codes, as compilers take it (-Wno-K0604, -Werror=K0650, -Werror).
/// Every command applies it to the pipeline's findings, so they all say the same.
struct DiagnosticPolicy {
  std::vector<Code> silenced;      ///< -Wno-CODE: a warning or note not reported
  std::vector<Code> promoted;      ///< -Werror=CODE: reported as an error
  bool warningsAreErrors = false;  ///< -Werror: every warning is an error
  [[nodiscard]] bool empty() const { return silenced.empty() && promoted.empty() && !warningsAreErrors; }
  /// The severity d is reported with, or nothing when it is silenced. Errors are never silenced.
  [[nodiscard]] std::optional<Severity> levelOf(const Diagnostic& d) const;
};

/// The cap of a collection meant to keep every diagnostic of a run (the pipeline's, a command's):
/// the checks stop reporting a kind long before it (K0899).
constexpr std::size_t kAllDiagnostics = 100000;

/// Collects diagnostics up to a cap; counts every one.
class Diagnostics {
 public:
  explicit Diagnostics(std::size_t cap = 50) : cap_(cap) {}

  void report(Diagnostic d);
  void error(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  void warning(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  void note(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  /// Appends what later reported (its counts and its dropped ones too), as if reported here.
  void append(Diagnostics&& later);

  [[nodiscard]] const std::vector<Diagnostic>& all() const { return items_; }
  [[nodiscard]] std::size_t errorCount() const { return errors_; }
  [[nodiscard]] std::size_t warningCount() const { return warnings_; }
  [[nodiscard]] std::size_t dropped() const { return dropped_; }
  [[nodiscard]] std::size_t cap() const { return cap_; }
  [[nodiscard]] bool hasErrors() const { return errors_ > 0; }
  /// Stable order for output: by file position, then as reported.
  void sortByPosition();
  /// The same diagnostics under a policy: silenced ones gone, promoted ones errors. Those dropped
  /// past the cap were never seen, so they keep their severities in the counts.
  [[nodiscard]] Diagnostics under(const DiagnosticPolicy& policy) const;

 private:
  std::size_t cap_;
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t dropped_ = 0;
};

/// One diagnostic as text: the location line, the source line and a caret under the span.
std::string formatDiagnostic(const Diagnostic& d);

/// "file:line:col" (or the file name alone for a span-less diagnostic).
std::string formatLocation(const Diagnostic& d);

}  // namespace kerf::converter

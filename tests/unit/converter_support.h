// Helpers for converter tests: run the reading pipeline on a string.
#pragma once

#include "kerf/converter/check/checks.h"
#include "kerf/converter/interpret/analysis.h"

#include <memory>
#include <string>

namespace kerf::test {

struct Run {
  std::unique_ptr<converter::SourceFile> source;
  converter::Diagnostics diags{200};
  converter::Analysis analysis;

  [[nodiscard]] const converter::Toolpath& path() const { return analysis.toolpath; }
  [[nodiscard]] bool hasCode(converter::Code c) const {
    for (const auto& d : diags.all())
      if (d.code == c) return true;
    return false;
  }
};

inline std::unique_ptr<Run> run(const std::string& text, const converter::InterpreterOptions& options = {},
                                bool check = false) {
  auto r = std::make_unique<Run>();
  r->source = std::make_unique<converter::SourceFile>("test.nc", text);
  r->analysis = converter::analyse(*r->source, options, r->diags);
  if (check) converter::checkToolpath(r->analysis.toolpath, r->source.get(), {}, r->diags);
  return r;
}

/// The diagnostics as text, for failure messages.
inline std::string dump(const converter::Diagnostics& d) {
  std::string out = "\n";
  for (const auto& x : d.all()) out += converter::formatDiagnostic(x);
  return out;
}

}  // namespace kerf::test

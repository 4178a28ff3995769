#include "load.h"

#include "file_io.h"
#include "kerf/converter/report/report.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string_view>
#include <thread>

namespace kerf::cli {

void reportError(const std::string& message) { std::cerr << "kerf: error: " << message << "\n"; }

converter::Diagnostics shownDiagnostics(const converter::Diagnostics& all, const CheckOptions& options) {
  converter::Diagnostics shown(options.maxDiagnostics);
  for (const converter::Diagnostic& d : all.all())
    if (!options.quiet || d.severity == converter::Severity::Error) shown.report(d);
  return shown;
}

unsigned threadsFromEnvironment() {
  if (const char* env = std::getenv("KERF_THREADS"); env && *env) {
    char* end = nullptr;
    const unsigned long n = std::strtoul(env, &end, 10);
    if (*end == '\0' && n >= 1) return static_cast<unsigned>(std::min(n, 64ul));
  }
  return std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
}

bool colourOn(const CheckOptions& options) {
  if (options.color != "auto") return options.color == "always";
  // https://no-color.org: a NO_COLOR that is set and not empty turns colour off.
  const char* noColor = std::getenv("NO_COLOR");
  const char* term = std::getenv("TERM");
  return (!noColor || !*noColor) && !(term && std::string_view(term) == "dumb") && isatty(fileno(stderr)) == 1;
}

std::string diagnosticsText(const converter::Diagnostics& shown, const CheckOptions& options) {
  std::string text = converter::formatDiagnosticsText(shown);
  if (!colourOn(options)) return text;
  // The severity on each location line (the quoted source lines are indented), as compilers
  // colour it: errors red, warnings magenta, notes cyan, all bold.
  static constexpr std::pair<std::string_view, std::string_view> kColours[] = {
      {": error: ", "\x1b[1;31m"}, {": warning: ", "\x1b[1;35m"}, {": note: ", "\x1b[1;36m"}};
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    end = end == std::string::npos ? text.size() : end + 1;
    std::string line = text.substr(at, end - at);
    at = end;
    if (!line.empty() && line[0] != ' ') {
      for (const auto& [word, colour] : kColours) {
        if (const std::size_t k = line.find(word); k != std::string::npos) {
          line = line.substr(0, k + 2) + std::string(colour) + std::string(word.substr(2, word.size() - 3)) +
                 "\x1b[0m" + line.substr(k + word.size() - 1);
          break;
        }
      }
    }
    out += line;
  }
  return out;
}

void printDiagnostics(const converter::Diagnostics& diags, const CommonOptions& options) {
  std::cerr << diagnosticsText(shownDiagnostics(diags, options.checks), options.checks);
}

int verdictExit(const converter::Pipeline& pipeline) { return pipeline.diags.hasErrors() ? kExitErrors : kExitOk; }

std::optional<Loaded> loadQuietly(const CommonOptions& options, const std::string& file, LoadNeeds needs,
                                  std::string& failure) {
  converter::PipelineOptions po;
  converter::DiagnosticPolicy policy;
  if (!pipelineOptions(options, po, failure) || !diagnosticPolicy(options.checks, policy, failure)) return std::nullopt;
  const bool curve = options.input.curve && file == kCurveInput;
  if (needs.summary) po.summarize = options.sampling.sampling();
  po.centreWords = needs.centreWords;
  std::optional<std::string> text = curve ? std::optional<std::string>(curveText(options.input))
                                          : readTextFile(file, options.input.maxInputMiB << 20, failure);
  if (!text) return std::nullopt;
  std::optional<converter::SourceText> upper;
  if (options.input.upper) {
    std::optional<std::string> upperText = readTextFile(*options.input.upper, options.input.maxInputMiB << 20, failure);
    if (!upperText) return std::nullopt;
    upper = converter::SourceText{*options.input.upper, std::move(*upperText)};
  }
  Loaded out{converter::runPipeline({curve ? file : displayName(file), std::move(*text)}, po, std::move(upper)), {}};
  // Every command says what check says under the same -W options.
  if (!policy.empty()) out.pipeline.diags = out.pipeline.diags.under(policy);
  if (!out.pipeline.read) return out;
  if (!curve) out.inputs.push_back(file);
  if (options.input.upper) out.inputs.push_back(*options.input.upper);
  if (po.read.machineFile) out.inputs.push_back(po.read.machineFile->name);
  if (po.read.offsetsFile) out.inputs.push_back(po.read.offsetsFile->name);
  if (po.drawing) out.inputs.push_back(po.drawing->name);
  return out;
}

std::optional<Loaded> load(const CommonOptions& options, const std::string& file, LoadNeeds needs) {
  std::string failure;
  std::optional<Loaded> out = loadQuietly(options, file, needs, failure);
  if (!out) {
    reportError(failure);
    return std::nullopt;
  }
  if (!out->pipeline.read) {
    printDiagnostics(out->pipeline.diags, options);
    return std::nullopt;
  }
  return out;
}

std::optional<Loaded> loadOne(const CommonOptions& options, LoadNeeds needs) {
  std::optional<Loaded> in = load(options, options.input.files.front(), needs);
  if (in) printDiagnostics(in->pipeline.diags, options);
  return in;
}

}  // namespace kerf::cli

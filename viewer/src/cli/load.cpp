#include "load.h"

#include "file_io.h"
#include "kerf/converter/report.h"

#include <iostream>

namespace kerf::cli {

void reportError(const std::string& message) { std::cerr << "kerf: error: " << message << "\n"; }

converter::Diagnostics capped(const converter::Diagnostics& all, std::size_t cap) {
  converter::Diagnostics shown(cap);
  for (const converter::Diagnostic& d : all.all()) shown.report(d);
  return shown;
}

void printDiagnostics(const converter::Diagnostics& diags, const CommonOptions& options) {
  std::cerr << converter::formatDiagnosticsText(capped(diags, options.checks.maxDiagnostics));
}

int verdictExit(const converter::Pipeline& pipeline) { return pipeline.diags.hasErrors() ? kExitErrors : kExitOk; }

std::optional<Loaded> load(const CommonOptions& options, const std::string& file, LoadNeeds needs) {
  std::string error;
  converter::PipelineOptions po;
  if (!pipelineOptions(options, po, error)) {
    reportError(error);
    return std::nullopt;
  }
  const bool curve = options.input.curve && file == kCurveInput;
  if (needs.summary) po.summarize = options.sampling.sampling();
  po.centreWords = needs.centreWords;
  if (needs.quoteOnly && !curve && file != "-") {
    po.rereadSource = [file]() -> std::optional<std::string> {
      std::string why;
      return readTextFile(file, converter::SourceFile::kMaxSize, why);
    };
  }
  std::optional<std::string> text = curve ? std::optional<std::string>(curveText(options.input))
                                          : readTextFile(file, converter::SourceFile::kMaxSize, error);
  if (!text) {
    reportError(error);
    return std::nullopt;
  }
  std::optional<converter::SourceText> upper;
  if (options.input.upper) {
    std::optional<std::string> upperText = readTextFile(*options.input.upper, converter::SourceFile::kMaxSize, error);
    if (!upperText) {
      reportError(error);
      return std::nullopt;
    }
    upper = converter::SourceText{*options.input.upper, std::move(*upperText)};
  }
  Loaded out{converter::runPipeline({curve ? file : displayName(file), std::move(*text)}, po, std::move(upper)), {}};
  if (!out.pipeline.read) {
    printDiagnostics(out.pipeline.diags, options);
    return std::nullopt;
  }
  if (!curve) out.inputs.push_back(file);
  if (options.input.upper) out.inputs.push_back(*options.input.upper);
  if (po.read.machineFile) out.inputs.push_back(po.read.machineFile->name);
  return out;
}

std::optional<Loaded> loadOne(const CommonOptions& options, LoadNeeds needs) {
  std::optional<Loaded> in = load(options, options.input.files.front(), needs);
  if (in) printDiagnostics(in->pipeline.diags, options);
  return in;
}

}  // namespace kerf::cli

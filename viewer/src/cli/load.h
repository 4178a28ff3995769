// Reading a program for a command: the files (the program, --upper, --machine FILE) into the
// pipeline, and the diagnostics onto the terminal.
#pragma once

#include "options.h"

#include "kerf/converter/pipeline.h"

#include <optional>
#include <string>
#include <vector>

namespace kerf::cli {

constexpr int kExitOk = 0;      ///< no errors (warnings and notes allowed)
constexpr int kExitErrors = 1;  ///< the program has errors
constexpr int kExitUsage = 2;   ///< a usage or file problem

struct Loaded {
  converter::Pipeline pipeline;
  std::vector<std::string> inputs;  ///< every file read: an output may replace none of them
};

/// The threads a check may use (geometry::setWorkerCount): KERF_THREADS when it is a whole number
/// from 1 up (at most 64), else the hardware's count, at most 16.
unsigned threadsFromEnvironment();

/// What a command needs of the pipeline besides the toolpath and the diagnostics.
struct LoadNeeds {
  /// The summary at the options' sampling (Pipeline::summary).
  bool summary = false;
  /// How each arc's centre was written (PipelineOptions::centreWords): kerf explain shows it.
  bool centreWords = false;
};

/// Reads `file` (with --upper and --machine) and runs the pipeline. Nothing, with the reason
/// printed, when a file cannot be read or the machine profile is wrong (exit 2).
std::optional<Loaded> load(const CommonOptions& options, const std::string& file, LoadNeeds needs = {});

/// load() without a word on the terminal: nothing with `failure` saying why when a file cannot be
/// read or an option is wrong; a pipeline with read == false when the machine profile is wrong
/// (its diagnostics say why).
std::optional<Loaded> loadQuietly(const CommonOptions& options, const std::string& file, LoadNeeds needs,
                                  std::string& failure);

/// For the commands that take one program: load() it and print its diagnostics, as check does.
std::optional<Loaded> loadOne(const CommonOptions& options, LoadNeeds needs = {});

/// What the terminal shows of `all`: errors only under --quiet, at most --max-diagnostics, every
/// one still counted.
converter::Diagnostics shownDiagnostics(const converter::Diagnostics& all, const CheckOptions& options);

/// The shown diagnostics as text, coloured by severity when --color asks for it (auto: standard
/// error is a terminal and NO_COLOR is not set).
std::string diagnosticsText(const converter::Diagnostics& shown, const CheckOptions& options);

/// The diagnostics on standard error, compiler style, at most options.checks.maxDiagnostics.
void printDiagnostics(const converter::Diagnostics& diags, const CommonOptions& options);

/// 1 when the program has errors, else 0.
int verdictExit(const converter::Pipeline& pipeline);

/// Prints "kerf: error: message" on standard error.
void reportError(const std::string& message);

}  // namespace kerf::cli

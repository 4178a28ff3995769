// kerf check FILE|DIR... : diagnostics, geometric findings and the part's numbers, for each file;
// folders are walked, files are checked on every core, and the exit code is the worst one.
#include "commands.h"
#include "draw_module.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/check/summary.h"
#include "kerf/converter/report/ci_report.h"
#include "kerf/converter/report/html_report.h"
#include "kerf/converter/report/report.h"
#include "kerf/geometry/parallel.h"

#include <CLI/CLI.hpp>

#include <glob.h>
#include <sys/stat.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <thread>

namespace kerf::cli {

namespace {

/// The extensions a folder is searched for (case does not matter); a file named on the command
/// line is read whatever its name. docs/ci.md lists them.
constexpr std::string_view kProgramExtensions[] = {".nc",  ".ngc", ".iso", ".gcode", ".tap", ".cnc",
                                                   ".mpf", ".ptp", ".eia", ".3b",    ".dxf"};

bool isProgramName(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(std::begin(kProgramExtensions), std::end(kProgramExtensions), ext) != std::end(kProgramExtensions);
}

/// The files to check: each argument, or for a folder the programs under it, in name order.
/// False after saying what is wrong.
bool expandInputs(const std::vector<std::string>& args, std::vector<std::string>& files) {
  for (const std::string& a : args) {
    std::error_code ec;
    if (a == "-" || !std::filesystem::is_directory(a, ec)) {
      files.push_back(a);
      continue;
    }
    std::vector<std::string> found;
    std::filesystem::recursive_directory_iterator it(a, std::filesystem::directory_options::skip_permission_denied, ec);
    for (; !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
      if (it->is_regular_file(ec) && isProgramName(it->path())) found.push_back(it->path().string());
    if (ec) {
      reportError(a + ": the folder cannot be read: " + ec.message());
      return false;
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  // Each file once, however often a folder, a pattern or a name reaches it (by device and inode:
  // `a.nc`, `./a.nc` and a link to it are one file); the first place it came in keeps it.
  std::set<std::pair<dev_t, ino_t>> seen;
  std::erase_if(files, [&seen](const std::string& f) {
    struct stat st {};
    return f != "-" && ::stat(f.c_str(), &st) == 0 && !seen.insert({st.st_dev, st.st_ino}).second;
  });
  return true;
}

/// The most bytes a --files-from list may hold (a list of names, not programs).
constexpr std::size_t kMaxFileList = std::size_t{16} << 20;

/// The lines of --files-from (a file, or standard input for "-"): each a file, a folder or a glob
/// pattern, expanded in name order; blank lines and lines starting with '#' skipped. False after
/// saying what is wrong (a list that cannot be read, a pattern that matches nothing).
bool readFileList(const std::string& list, std::vector<std::string>& out) {
  std::string error;
  const std::optional<std::string> read = readTextFile(list, kMaxFileList, error);  // "-": stdin
  if (!read) {
    reportError(error);
    return false;
  }
  const std::string& text = *read;
  std::size_t lineNumber = 0;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(at, end - at);
    at = end + 1;
    ++lineNumber;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    if (line.find_first_of("*?[") == std::string::npos) {
      out.push_back(line);
      continue;
    }
    glob_t g{};
    const int rc = ::glob(line.c_str(), 0, nullptr, &g);
    // Sorted by glob(). Only files and folders: a FIFO or a device is read only when named
    // directly (a pattern that matched a FIFO would block on it).
    if (rc == 0)
      for (std::size_t k = 0; k < g.gl_pathc; ++k) {
        struct stat st {};
        if (::stat(g.gl_pathv[k], &st) == 0 && (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)))
          out.emplace_back(g.gl_pathv[k]);
      }
    ::globfree(&g);
    if (rc != 0) {
      reportError((list == "-" ? std::string("<stdin>") : list) + ":" + std::to_string(lineNumber) + ": '" + line +
                  "' matches no file");
      return false;
    }
  }
  return true;
}

/// What checking one file gave: the text for the terminal and what a report needs.
struct Outcome {
  std::string out, err;  ///< standard output and standard error, printed in the files' order
  int exit = kExitOk;
  converter::Diagnostics shown;  ///< what the terminal shows (and the reports carry)
  std::string failure;           ///< why the file was not read
  // The diagnostics point into the sources: they live as long as the outcome.
  std::unique_ptr<converter::SourceFile> source, upperSource, machineSource, offsetsSource;
  std::size_t errors = 0, warnings = 0;
  std::optional<converter::Structure> structure;  ///< its contours and passes, when it was read
  // --format html: what its page shows.
  std::optional<converter::Summary> summary;
  std::string summaryText, diagnosticsPlain;
  std::optional<double> worstDeviation, tolerance;  ///< --drawing's
};

Outcome checkOne(const CheckArgs& a, const std::string& file, bool many) {
  Outcome o;
  std::optional<Loaded> in = loadQuietly(a.common, file, {.summary = true}, o.failure);
  if (!in) {
    o.exit = kExitUsage;
    o.err = "kerf: error: " + o.failure + "\n";
    return o;
  }
  converter::Pipeline& p = in->pipeline;
  o.shown = shownDiagnostics(p.diags, a.common.checks);
  o.errors = p.diags.errorCount();
  o.warnings = p.diags.warningCount();
  const std::string format = a.json ? "json" : a.format;
  if (format == "html") {  // the page shows them as the terminal does, without its colours
    CheckOptions plain = a.common.checks;
    plain.color = "never";
    o.diagnosticsPlain = diagnosticsText(o.shown, plain);
  }
  if (!p.read) {  // the machine profile or the offset table is wrong: its diagnostics say why
    o.exit = kExitUsage;
    // The offset table is read only after the profile was: a source for it means it failed.
    o.failure = p.offsetsSource ? "the offset table cannot be used" : "the machine profile cannot be used";
    o.err = diagnosticsText(o.shown, a.common.checks);
  } else {
    o.exit = verdictExit(p);
    if (p.summary) o.structure = p.summary->structure;
    if (a.trace) {
      o.out = converter::formatTrace(p.toolpath, p.diags);
    } else if (format == "json") {
      o.out = converter::checkReportJson(displayName(file), *p.summary, o.shown, p.drawing ? &*p.drawing : nullptr,
                                         p.wires.empty() ? nullptr : &p.wires);
      while (!o.out.empty() && o.out.back() == '\n') o.out.pop_back();
      if (!many) o.out += "\n";
    } else if (format == "text" || format == "html") {
      o.err = diagnosticsText(o.shown, a.common.checks);
      std::string summary = converter::formatSummaryText(displayName(file), *p.summary, o.shown);
      if (!a.common.checks.quiet) o.out = summary;
      if (format == "html") {
        o.summaryText = std::move(summary);
        o.summary = *p.summary;
        if (p.comparison) {
          o.worstDeviation = p.comparison->worst;
          o.tolerance = p.comparison->tolerance;
        }
      }
    }
  }
  // The quotes of a report read the text again (a source may have given it back): keep the sources.
  o.source = std::move(p.source);
  o.upperSource = std::move(p.upperSource);
  o.machineSource = std::move(p.machineSource);
  o.offsetsSource = std::move(p.offsetsSource);
  return o;
}

/// --format html: the report's folder (converter/report/html_report.h) with each program's pictures
/// and 3D page (drawn by the drawing module; without it, the pages say so), written whole or not
/// at all; false, said, when it cannot be.
bool writeHtmlReport(const CheckArgs& a, const std::vector<std::string>& files, const std::vector<Outcome>& outcomes,
                     const std::string& summaryLine) {
  std::vector<std::string> names;
  for (const std::string& f : files) names.push_back(displayName(f));
  const std::vector<std::string> pages = converter::htmlPageNames(names);
  std::string moduleError, note;
  const DrawCommands* draw = loadDrawCommands(moduleError);
  if (!draw) note = "No pictures: " + moduleError + ".";
  auto fill = [&](const std::string& folder, std::string& error) {
    ReportArgs pictures{&a.common, files, names, {}, folder};
    for (const std::string& page : pages) pictures.stems.push_back(page.substr(0, page.size() - 5));  // ".html"
    if (draw) draw->reportPictures(pictures);
    std::vector<converter::HtmlReportEntry> entries;
    for (std::size_t i = 0; i < files.size(); ++i) {
      const Outcome& o = outcomes[i];
      converter::HtmlReportEntry e;
      e.name = names[i];
      e.page = pages[i];
      e.exit = o.exit;
      e.failure = o.failure;
      e.errors = o.errors;
      e.warnings = o.warnings;
      for (const converter::Diagnostic& d : o.shown.all()) e.notes += d.severity == converter::Severity::Note;
      e.diagnosticsText = o.diagnosticsPlain;
      e.summaryText = o.summaryText;
      e.summary = o.summary ? &*o.summary : nullptr;
      e.worstDeviation = o.worstDeviation;
      e.tolerance = o.tolerance;
      // What the drawing module made of it.
      const ReportAssets made(pictures.stems[i]);
      const auto kept = [&folder](const std::string& name) {
        return std::filesystem::exists(std::filesystem::path(folder) / name) ? name : std::string();
      };
      e.thumbnail = kept(made.thumbnail);
      e.top = kept(made.top);
      e.iso = kept(made.iso);
      e.page3d = kept(made.page3d);
      entries.push_back(std::move(e));
    }
    if (!writeFileIn(folder, "index.html", converter::htmlReportIndex(entries, summaryLine, note), error)) return false;
    for (const converter::HtmlReportEntry& e : entries)
      if (!writeFileIn(folder, e.page, converter::htmlReportPage(e), error)) return false;
    return true;
  };
  std::string error;
  if (!writeFolder(a.output, fill, error)) {
    reportError(error);
    return false;
  }
  std::cerr << "kerf: wrote the report of " << files.size() << (files.size() == 1 ? " program" : " programs") << " to "
            << (std::filesystem::path(a.output) / "index.html").string() << "\n";
  return true;
}

}  // namespace

CLI::App* addCheckCommand(CLI::App& app, CheckArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "check", "verify programs (files, or folders of them): diagnostics, geometric findings, summary");
  addCommonOptions(*cmd, a.common, true);
  auto* format = cmd->add_option("--format", a.format,
                                 "text (default), json, sarif (SARIF 2.1.0 for code scanning) or junit (JUnit XML), on "
                                 "stdout; sarif and junit make one report of every file; html: the text, and a "
                                 "report folder (-o DIR) with a page per program")
                     ->check(CLI::IsMember({"text", "json", "sarif", "junit", "html"}));
  cmd->add_option("-o,--output", a.output, "--format html: the report's folder (made, or a report Kerf wrote replaced)")
      ->needs(format);
  auto* json = cmd->add_flag("--json", a.json,
                             "the same as --format json: machine-readable output on stdout (an array when several "
                             "files are checked)")
                   ->excludes(format);
  cmd->add_flag(
         "--trace", a.trace,
         "the toolpath and every diagnostic in a stable fixed-decimal text on stdout (golden files, bug reports)")
      ->excludes(json)
      ->excludes(format);
  return cmd;
}

int runCheck(const CheckArgs& a) {
  const std::string format = a.json ? "json" : a.format;
  if ((format == "html") != !a.output.empty()) {
    reportError(format == "html" ? "--format html writes a report folder: give it with -o DIR"
                                 : "-o DIR is the folder of --format html");
    return kExitUsage;
  }
  std::vector<std::string> named = a.common.input.files;
  if (a.common.input.filesFrom) {
    if (*a.common.input.filesFrom == "-" && std::count(named.begin(), named.end(), "-") > 0) {
      reportError("standard input can hold the list of files (--files-from -) or a program ('-'), not both");
      return kExitUsage;
    }
    if (!readFileList(*a.common.input.filesFrom, named)) return kExitUsage;
  }
  std::vector<std::string> files;
  if (!expandInputs(named, files)) return kExitUsage;
  if (files.empty()) {
    reportError("no programs to check: the folders hold no file named " + std::string(".nc, .ngc, .iso, ...") +
                " (docs/ci.md lists the extensions)");
    return kExitUsage;
  }
  const bool many = files.size() > 1;
  if (a.common.input.upper && many) {
    reportError("--upper pairs one lower program with one upper program: give a single file with it");
    return kExitUsage;
  }
  if (std::count(files.begin(), files.end(), "-") > 1) {
    reportError("standard input ('-') can be read only once");
    return kExitUsage;
  }
  // The files on every core (each file's own checks then run in its thread); each one's output
  // is kept and printed in the files' order.
  std::vector<Outcome> outcomes(files.size());
  geometry::parallelFor(files.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) outcomes[i] = checkOne(a, files[i], many);
  });

  int worst = kExitOk;
  std::size_t withErrors = 0, withWarnings = 0, errors = 0, warnings = 0, unread = 0;
  std::string jsonArray;
  std::vector<converter::CheckedFile> report;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const Outcome& o = outcomes[i];
    worst = std::max(worst, o.exit);
    errors += o.errors;
    warnings += o.warnings;
    withErrors += o.errors > 0;
    withWarnings += o.warnings > 0;
    unread += !o.failure.empty();
    report.push_back({displayName(files[i]), &o.shown, o.failure, o.structure ? &*o.structure : nullptr});
    std::cerr << o.err;
    if (format == "json" && many && !a.trace) {
      if (!o.out.empty()) jsonArray += (jsonArray.empty() ? "[\n" : ",\n") + o.out;
    } else {
      std::cout << o.out;
    }
  }
  if (format == "json" && many && !a.trace) std::cout << (jsonArray.empty() ? "[" : jsonArray) << "\n]\n";
  if (format == "sarif") std::cout << converter::sarifLog(report, KERF_VERSION);
  if (format == "junit") std::cout << converter::junitReport(report);
  const char* verdict = worst == kExitUsage ? "unreadable files" : worst == kExitErrors ? "errors" : "ok";
  const std::string summaryLine =
      std::to_string(files.size()) + (many ? " files" : " file") + " checked: " + std::to_string(withErrors) +
      " with errors, " + std::to_string(withWarnings) + " with warnings" +
      (unread ? ", " + std::to_string(unread) + " not read" : std::string()) + "; " + std::to_string(errors) +
      (errors == 1 ? " error, " : " errors, ") + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings") +
      "; worst: " + verdict;
  if (many && !a.common.checks.quiet) std::cerr << "kerf: " << summaryLine << "\n";
  if (format == "html" && !writeHtmlReport(a, files, outcomes, summaryLine)) return kExitUsage;
  return worst;
}

}  // namespace kerf::cli

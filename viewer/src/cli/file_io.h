// Reading inputs and writing outputs for the kerf program: the one writer every command uses.
//
// Outputs never replace an input (any of them: the program, the --upper program, a profile),
// never replace what is not a regular file, and are written atomically:
//   - "-" is standard output; a failed write there is an error;
//   - a symbolic link is followed: the file it names is written, the link stays;
//   - a character device or a FIFO (/dev/null, a pipe) is written through, never renamed over;
//   - a folder, a block device or a socket is refused;
//   - a regular file, or a new one, is written to a temporary file in the same folder (keeping
//     the output's extension, which some writers insist on) and renamed over it, keeping the
//     permissions of the file it replaces.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kerf::cli {

/// The whole file ("-": standard input) with plain read(2), or nothing with a message in error
/// (missing, unreadable, a folder, larger than maxBytes).
std::optional<std::string> readTextFile(const std::string& path, std::size_t maxBytes, std::string& error);

/// The name a file is shown under: "<stdin>" for "-".
std::string displayName(const std::string& path);

/// Writes text to path ("-" is standard output). Refuses to write over any of `inputs`.
bool writeOutput(const std::string& path, const std::vector<std::string>& inputs, const std::string& text,
                 std::string& error);

/// Writes path through `writer`, which must create the file at the temporary path it is given.
/// Refuses to write over any of `inputs`; no "-".
bool writeOutputVia(const std::string& path, const std::vector<std::string>& inputs,
                    const std::function<bool(const std::string& temporary, std::string& error)>& writer,
                    std::string& error);

/// Flushes standard output; false with a message when something written there was lost (a full
/// disk, a closed pipe).
bool finishStandardOutput(std::string& error);

/// A folder written whole or not at all: `fill` writes the files into a new folder beside `path`
/// (whose path it is given; false, with the reason in its error, abandons it), which is then
/// renamed to `path`. An existing `path` is replaced only when it is a folder Kerf wrote so (it
/// holds the `.kerf-report` mark); anything else there is left alone and refused.
bool writeFolder(const std::string& path,
                 const std::function<bool(const std::string& folder, std::string& error)>& fill, std::string& error);

/// Writes a new file `name` (a plain file name) in `folder`; false, with the reason, when it exists
/// or cannot be written.
bool writeFileIn(const std::string& folder, const std::string& name, std::string_view bytes, std::string& error);

}  // namespace kerf::cli

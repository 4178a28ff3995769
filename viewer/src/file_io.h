// Reading inputs and writing outputs for the kerf program. Outputs are written atomically
// (a temporary file in the same folder, then rename) and never over an input file.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace kerf::cli {

/// The whole file, or nothing with a message in error (missing, unreadable, a folder, too big).
std::optional<std::string> readTextFile(const std::string& path, std::size_t maxBytes, std::string& error);

/// Writes text to path ("-" is standard output). Refuses to write over `input`.
bool writeOutput(const std::string& path, const std::string& input, const std::string& text, std::string& error);

/// Writes path through `writer`, which must create the file at the temporary path it is given
/// (same folder, so the final rename is atomic). Refuses to write over `input`; no "-".
bool writeOutputVia(const std::string& path, const std::string& input,
                    const std::function<bool(const std::string& temporary, std::string& error)>& writer,
                    std::string& error);

}  // namespace kerf::cli

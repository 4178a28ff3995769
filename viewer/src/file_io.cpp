#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kerf::cli {

namespace fs = std::filesystem;

std::optional<std::string> readTextFile(const std::string& path, std::size_t maxBytes, std::string& error) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) {
    error = "cannot open '" + path + "': no such file";
    return std::nullopt;
  }
  if (fs::is_directory(st)) {
    error = "'" + path + "' is a folder, not a file";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open '" + path + "': " + std::strerror(errno);
    return std::nullopt;
  }
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > maxBytes) {
      error = "'" + path + "' is larger than " + std::to_string(maxBytes) + " bytes";
      return std::nullopt;
    }
  }
  if (in.bad()) {
    error = "error reading '" + path + "'";
    return std::nullopt;
  }
  return text;
}

bool writeOutput(const std::string& path, const std::string& input, const std::string& text, std::string& error) {
  if (path == "-") {
    std::cout << text;
    std::cout.flush();
    return static_cast<bool>(std::cout);
  }
  return writeOutputVia(
      path, input,
      [&text, &path](const std::string& temporary, std::string& err) {
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) {
          err = "cannot write '" + path + "': " + std::strerror(errno);
          return false;
        }
        std::size_t done = 0;
        while (done < text.size()) {
          const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
          if (n < 0) {
            if (errno == EINTR) continue;
            err = "cannot write '" + path + "': " + std::strerror(errno);
            ::close(fd);
            return false;
          }
          done += static_cast<std::size_t>(n);
        }
        if (::fsync(fd) != 0 || ::close(fd) != 0) {
          err = "cannot write '" + path + "': " + std::strerror(errno);
          return false;
        }
        return true;
      },
      error);
}

bool writeOutputVia(const std::string& path, const std::string& input,
                    const std::function<bool(const std::string& temporary, std::string& error)>& writer,
                    std::string& error) {
  std::error_code ec;
  if (fs::exists(path, ec) && fs::equivalent(path, input, ec)) {
    error = "refusing to write the output over the input file '" + input + "'";
    return false;
  }
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string tmpl = (dir / ("." + target.filename().string() + ".kerf-XXXXXX")).string();
  const int fd = mkstemp(tmpl.data());
  if (fd < 0) {
    error = "cannot create a file in '" + dir.string() + "': " + std::strerror(errno);
    return false;
  }
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  if (!writer(tmpl, error)) {
    std::remove(tmpl.c_str());
    return false;
  }
  if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
    error = "cannot write '" + path + "': " + std::strerror(errno);
    std::remove(tmpl.c_str());
    return false;
  }
  return true;
}

}  // namespace kerf::cli

#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <system_error>

#include <algorithm>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

std::string errnoText() { return std::strerror(errno); }

bool writeAll(int fd, const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/// Copies a finished file's bytes into what is already open for writing (a device, a FIFO).
bool copyInto(const std::string& from, int to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return false;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(in);
      return n == 0;
    }
    if (!writeAll(to, buf, static_cast<std::size_t>(n))) {
      ::close(in);
      return false;
    }
  }
}

/// "part.ply" -> ".ply"; "" when the name has no extension.
std::string extensionOf(const fs::path& p) { return p.has_extension() ? p.extension().string() : std::string{}; }

/// A new temporary file in dir, named after the output and ending in its extension.
std::optional<std::string> makeTemporary(const fs::path& dir, const fs::path& target, std::string& error) {
  const std::string ext = extensionOf(target);
  std::string name = (dir / ("." + target.stem().string() + ".kerf-XXXXXX" + ext)).string();
  const int fd = ::mkstemps(name.data(), static_cast<int>(ext.size()));
  if (fd < 0) {
    error = "cannot create a file in '" + dir.string() + "': " + errnoText();
    return std::nullopt;
  }
  ::close(fd);
  return name;
}

}  // namespace

std::string displayName(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::optional<std::string> readTextFile(const std::string& path, std::size_t maxBytes, std::string& error) {
  std::string text;
  char buf[1 << 16];
  if (path == "-") {
    while (std::cin.read(buf, sizeof buf) || std::cin.gcount() > 0) {
      text.append(buf, static_cast<std::size_t>(std::cin.gcount()));
      if (text.size() > maxBytes) {
        error = "standard input holds more than " + std::to_string(maxBytes) + " bytes";
        return std::nullopt;
      }
    }
    if (std::cin.bad()) {
      error = "error reading standard input";
      return std::nullopt;
    }
    return text;
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    error = "cannot open '" + path + "': " + (errno == ENOENT ? std::string("no such file") : errnoText());
    return std::nullopt;
  }
  if (S_ISDIR(st.st_mode)) {
    error = "'" + path + "' is a folder, not a file";
    return std::nullopt;
  }
  // A FIFO is opened waiting for its writer (opened without, a read before the writer comes says
  // end of file); anything stat called a regular file without waiting, in case it became a FIFO
  // since.
  const bool regular = S_ISREG(st.st_mode);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (regular ? O_NONBLOCK : 0));
  if (fd < 0) {
    error = "cannot open '" + path + "': " + errnoText();
    return std::nullopt;
  }
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
    // A regular file's size is known: the text is read into its place, held once. A file that
    // grows meanwhile is still read whole, up to the limit.
    if (static_cast<std::uintmax_t>(st.st_size) > maxBytes) {
      ::close(fd);
      error = "'" + path + "' is larger than " + std::to_string(maxBytes) + " bytes";
      return std::nullopt;
    }
    text.reserve(static_cast<std::size_t>(st.st_size) + 1);
  } else if (regular) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  }
  for (;;) {
    // The room already reserved, down to the one byte that lets a regular file's last read say end
    // of file without growing the text; a buffer's worth more only when that is used up.
    const std::size_t spare = text.capacity() - text.size();
    const std::size_t room = spare > 0 ? spare : sizeof buf;
    const std::size_t at = text.size();
    text.resize(at + room);
    const ssize_t n = ::read(fd, text.data() + at, room);
    if (n < 0 && errno == EINTR) {
      text.resize(at);
      continue;
    }
    text.resize(at + static_cast<std::size_t>(std::max<ssize_t>(n, 0)));
    if (n < 0) {
      ::close(fd);
      error = "error reading '" + path + "': " + errnoText();
      return std::nullopt;
    }
    if (n == 0) break;
    if (text.size() > maxBytes) {
      ::close(fd);
      error = "'" + path + "' is larger than " + std::to_string(maxBytes) + " bytes";
      return std::nullopt;
    }
  }
  ::close(fd);
  return text;
}

bool writeOutput(const std::string& path, const std::vector<std::string>& inputs, const std::string& text,
                 std::string& error) {
  if (path == "-") {
    std::cout << text;
    std::cout.flush();
    if (!std::cout) {
      error = "cannot write to standard output: " + errnoText();
      return false;
    }
    return true;
  }
  return writeOutputVia(
      path, inputs,
      [&text, &path](const std::string& temporary, std::string& err) {
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) {
          err = "cannot write '" + path + "': " + errnoText();
          return false;
        }
        if (!writeAll(fd, text.data(), text.size()) || ::fsync(fd) != 0) {
          err = "cannot write '" + path + "': " + errnoText();
          ::close(fd);
          return false;
        }
        if (::close(fd) != 0) {
          err = "cannot write '" + path + "': " + errnoText();
          return false;
        }
        return true;
      },
      error);
}

bool writeOutputVia(const std::string& path, const std::vector<std::string>& inputs,
                    const std::function<bool(const std::string& temporary, std::string& error)>& writer,
                    std::string& error) {
  std::error_code ec;
  // A symbolic link is followed, even one whose file does not exist yet: its target is the
  // output, and the link itself stays.
  fs::path target(path);
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(target, ec)); ++hops) {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) break;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  for (const std::string& in : inputs) {
    if (in.empty()) continue;
    if (in == "-") {  // standard input: refused when it is the very file the output would replace
      struct stat stdinStat {};
      if (exists && ::fstat(STDIN_FILENO, &stdinStat) == 0 && S_ISREG(stdinStat.st_mode) &&
          stdinStat.st_dev == st.st_dev && stdinStat.st_ino == st.st_ino) {
        error = "refusing to write the output over the file standard input reads ('" + path + "')";
        return false;
      }
      continue;
    }
    if (exists && fs::equivalent(target, in, ec)) {
      error = "refusing to write the output over the input file '" + in + "'";
      return false;
    }
  }
  if (exists && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) {
      error = "'" + path + "' is a folder: give a file name for the output";
      return false;
    }
    if (!S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode)) {
      error = "'" + path + "' is not a regular file, a character device or a pipe: refusing to write to it";
      return false;
    }
    // A device or a pipe is written through, never replaced (renaming over /dev/null as root
    // would destroy the device node).
    const std::optional<std::string> temporary = makeTemporary(fs::temp_directory_path(ec), target, error);
    if (!temporary) return false;
    bool ok = writer(*temporary, error);
    if (ok) {
      const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
      ok = fd >= 0 && copyInto(*temporary, fd);
      if (!ok) error = "cannot write '" + path + "': " + errnoText();
      if (fd >= 0 && ::close(fd) != 0 && ok) {
        error = "cannot write '" + path + "': " + errnoText();
        ok = false;
      }
    }
    std::remove(temporary->c_str());
    return ok;
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::optional<std::string> temporary = makeTemporary(dir, target, error);
  if (!temporary) return false;
  // The new file keeps the permissions of the one it replaces; a new one gets the umask's.
  mode_t mode = 0;
  if (exists) {
    mode = st.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  ::chmod(temporary->c_str(), mode);
  if (!writer(*temporary, error)) {
    std::remove(temporary->c_str());
    return false;
  }
  if (std::rename(temporary->c_str(), target.c_str()) != 0) {
    error = "cannot write '" + path + "': " + errnoText();
    std::remove(temporary->c_str());
    return false;
  }
  return true;
}

bool finishStandardOutput(std::string& error) {
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0) {
    error = "cannot write to standard output: " + errnoText();
    return false;
  }
  return true;
}

bool writeFileIn(const std::string& folder, const std::string& name, std::string_view bytes, std::string& error) {
  const std::string file = (fs::path(folder) / name).string();
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  const bool written = fd >= 0 && writeAll(fd, bytes.data(), bytes.size());
  std::string closing;
  if (fd >= 0 && ::close(fd) != 0) closing = errnoText();
  if (written && closing.empty()) return true;
  error = "cannot write '" + file + "': " + (closing.empty() ? errnoText() : closing);
  return false;
}

bool writeFolder(const std::string& path, const std::function<bool(const std::string&, std::string&)>& fill,
                 std::string& error) {
  constexpr const char* kMark = ".kerf-report";
  std::error_code ec;
  std::string named = path;  // "report/" is the folder report
  while (named.size() > 1 && named.back() == '/') named.pop_back();
  const fs::path target(named);
  const fs::file_status status = fs::symlink_status(target, ec);
  const bool exists = fs::exists(status);
  if (exists && (!fs::is_directory(status) || !fs::exists(target / kMark, ec))) {
    error = "'" + path + "' exists and is not a report Kerf wrote (no " + kMark + " in it): it is not replaced";
    return false;
  }
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string base = target.filename().string() + ".kerf-" + std::to_string(::getpid());
  const fs::path partial = parent / (base + "-partial"), old = parent / (base + "-old");
  fs::remove_all(partial, ec);
  if (!fs::create_directory(partial, ec)) {
    error = "cannot make the folder '" + partial.string() + "': " + ec.message();
    return false;
  }
  if (!fill(partial.string(), error) ||
      !writeFileIn(partial.string(), kMark, "a report written by Kerf: kerf check --format html replaces this folder\n",
                   error)) {
    fs::remove_all(partial, ec);
    return false;
  }
  if (exists) fs::rename(target, old, ec);
  if (!ec) fs::rename(partial, target, ec);
  if (ec) {
    error = "cannot put the report at '" + path + "': " + ec.message();
    if (exists && !fs::exists(target)) fs::rename(old, target, ec);  // the old report back
    fs::remove_all(partial, ec);
    return false;
  }
  if (exists) fs::remove_all(old, ec);
  return true;
}

}  // namespace kerf::cli

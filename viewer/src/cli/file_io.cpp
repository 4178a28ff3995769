#include "file_io.h"

#include "kerf/geometry/phase_times.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <mutex>

#include <fcntl.h>
#include <sys/mman.h>
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

// ---- a long program mapped, not read ----------------------------------------------------------
//
// Reading a 6 MB program into memory of our own cost a check more than its parse's serial part:
// every 4 KiB page written faults once and is cleared before the copy (1,500 faults, 3.6-4.7 ms on
// the 2-core machine), where mapping the page cache's own pages read-only took 0.4-0.5 ms to map
// and touch (the kernel maps 16 pages a fault). The text is then read where the system keeps it.
//
// Two things a copy gave for free are made here:
//   - A NUL after the last byte. The file's whole pages are mapped; its last part page is read into
//     a page of our own behind them (pread), whose rest is zero. So nothing written to the file
//     later (it may grow) moves the NUL or what lies past the mapping.
//   - No crash when the file is cut short meanwhile. The pages past its new end then raise SIGBUS
//     when read. The handler maps zero pages from there to the end of the file's part and marks the
//     read cut short; the read goes on over zeros and the load fails with a message (load.cpp).
//     A file written in place meanwhile is read as it is then, as read() would have.
namespace {

struct MappedRegion {  // the file part of one mapping: [begin, end), and its cut-short mark
  std::atomic<std::uintptr_t> begin{0};
  std::atomic<std::uintptr_t> end{0};
  std::atomic<std::atomic<bool>*> cut{nullptr};
};
constexpr std::size_t kMappedRegions = 64;  // programs mapped at once; past it they are read
MappedRegion mappedRegions[kMappedRegions];
std::atomic<std::uintptr_t> pageMask{0};
struct sigaction busBefore {};

extern "C" void onMappedBus(int /*signal*/, siginfo_t* info, void* /*context*/) {
  const auto at = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (MappedRegion& r : mappedRegions) {
    const std::uintptr_t begin = r.begin.load(std::memory_order_acquire);
    const std::uintptr_t end = r.end.load(std::memory_order_acquire);
    if (begin == 0 || at < begin || at >= end) continue;
    const std::uintptr_t page = at & ~pageMask.load(std::memory_order_relaxed);
    // mmap is a system call that takes no lock of the program's: safe here in practice.
    if (::mmap(reinterpret_cast<void*>(page), end - page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) ==
        MAP_FAILED)
      break;
    if (std::atomic<bool>* cut = r.cut.load(std::memory_order_acquire)) cut->store(true);
    return;  // the read that faulted runs again, over zeros
  }
  // Not a program's mapping: what was there before (the default ends the program), on the same
  // access again.
  ::sigaction(SIGBUS, &busBefore, nullptr);
}

bool installBusHandler() {
  static std::once_flag once;
  static bool installed = false;
  std::call_once(once, [] {
    pageMask.store(static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE)) - 1);
    struct sigaction action {};
    action.sa_sigaction = onMappedBus;
    action.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    installed = ::sigaction(SIGBUS, &action, &busBefore) == 0;
  });
  return installed;
}

// From this size on a program is mapped (below, a read costs a few page faults at most).
constexpr std::uintmax_t kMapFrom = 256 * 1024;

class MappedText final : public converter::TextKeeper {
 public:
  MappedText(void* base, std::size_t length, std::size_t region, std::shared_ptr<std::atomic<bool>> cut)
      : base_(base), length_(length), region_(region), cut_(std::move(cut)) {}
  MappedText(const MappedText&) = delete;
  MappedText& operator=(const MappedText&) = delete;
  ~MappedText() override {
    MappedRegion& r = mappedRegions[region_];
    r.end.store(0, std::memory_order_release);
    r.cut.store(nullptr, std::memory_order_release);
    ::munmap(base_, length_);
    r.begin.store(0, std::memory_order_release);  // free again
  }

 private:
  void* base_;
  std::size_t length_;
  std::size_t region_;
  std::shared_ptr<std::atomic<bool>> cut_;  // the handler marks it; load.cpp holds it too
};

/// The program's `size` bytes mapped (see above), or nothing when it cannot be (the caller reads it).
std::optional<converter::TextBytes> mapProgram(int fd, std::size_t size,
                                               std::shared_ptr<const std::atomic<bool>>* cut) {
  if (!installBusHandler()) return std::nullopt;
  const std::size_t page = pageMask.load() + 1;
  const std::size_t whole = size / page * page, tail = size - whole, length = whole + page;
  void* base = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (base == MAP_FAILED) return std::nullopt;
  auto* bytes = static_cast<char*>(base);
  auto fail = [&]() -> std::optional<converter::TextBytes> {
    ::munmap(base, length);
    return std::nullopt;
  };
  std::size_t got = 0;
  while (got < tail) {  // the last part page, into the page of our own
    const ssize_t n = ::pread(fd, bytes + whole + got, tail - got, static_cast<off_t>(whole + got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return fail();
    got += static_cast<std::size_t>(n);
  }
  if (::mprotect(bytes + whole, page, PROT_READ) != 0) return fail();
  std::size_t region = kMappedRegions;
  for (std::size_t k = 0; k < kMappedRegions && region == kMappedRegions; ++k) {
    std::uintptr_t free = 0;
    if (mappedRegions[k].begin.compare_exchange_strong(free, reinterpret_cast<std::uintptr_t>(base))) region = k;
  }
  if (region == kMappedRegions) return fail();
  auto cutShort = std::make_shared<std::atomic<bool>>(false);
  mappedRegions[region].cut.store(cutShort.get(), std::memory_order_release);
  mappedRegions[region].end.store(reinterpret_cast<std::uintptr_t>(bytes + whole), std::memory_order_release);
  auto keeper = std::make_unique<MappedText>(base, length, region, cutShort);  // unmaps from here on
  if (whole > 0 && ::mmap(base, whole, PROT_READ, MAP_PRIVATE | MAP_FIXED, fd, 0) == MAP_FAILED) return std::nullopt;
  // Grown or shrunk since it was measured: the caller reads it whole instead.
  struct stat st {};
  if (::fstat(fd, &st) != 0 || static_cast<std::uintmax_t>(st.st_size) != size) return std::nullopt;
  if (cut) *cut = cutShort;
  return converter::TextBytes::kept(bytes, size, std::move(keeper));
}

}  // namespace

std::optional<converter::TextBytes> readProgramFile(const std::string& path, std::size_t maxBytes, std::string& error,
                                                    std::shared_ptr<const std::atomic<bool>>* cutShort) {
  if (cutShort) cutShort->reset();
  auto throughText = [&]() -> std::optional<converter::TextBytes> {
    std::optional<std::string> text = readTextFile(path, maxBytes, error);
    if (!text) return std::nullopt;
    return converter::TextBytes(*text);
  };
  // Only a regular file is opened here (a FIFO opened twice would lose its writer), and without
  // waiting, in case the path became something else since.
  struct stat st {};
  if (path == "-" || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return throughText();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return throughText();  // its messages: missing, not readable
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return throughText();
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > maxBytes) {
    ::close(fd);
    error = "'" + path + "' is larger than " + std::to_string(maxBytes) + " bytes";
    return std::nullopt;
  }
  kerf::geometry::markPhase("file opened");
  if (size >= kMapFrom) {
    if (std::optional<converter::TextBytes> mapped = mapProgram(fd, static_cast<std::size_t>(size), cutShort)) {
      ::close(fd);
      kerf::geometry::markPhase("file read");
      return mapped;
    }
  }
  converter::TextBytes text = converter::TextBytes::ofSize(static_cast<std::size_t>(size));
  std::size_t got = 0;
  bool failed = false;
  while (got < text.size()) {
    const ssize_t n = ::read(fd, text.writable() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      failed = n < 0;
      break;
    }
    got += static_cast<std::size_t>(n);
  }
  char more = 0;
  ssize_t extra = 0;
  if (!failed && got == text.size()) {
    do extra = ::read(fd, &more, 1);
    while (extra < 0 && errno == EINTR);
    failed = extra < 0;
  }
  ::close(fd);
  kerf::geometry::markPhase("file read");
  if (failed) {
    error = "error reading '" + path + "'";
    return std::nullopt;
  }
  if (extra > 0) return throughText();  // it grew while read: read whole, up to the limit
  text.shrink(got);                     // it shrank: what it held
  return text;
}

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
    error = "cannot open '" + path + "': " + errnoText();
    return std::nullopt;
  }
  // A regular file's size is known: the text is held once, not in a string that doubled past it
  // (a file that grows while read is still read whole, up to the limit).
  if (fs::is_regular_file(st)) {
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec) text.reserve(static_cast<std::size_t>(std::min<std::uintmax_t>(size, maxBytes)) + 1);
  }
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
    if (in.empty() || in == "-") continue;
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

}  // namespace kerf::cli

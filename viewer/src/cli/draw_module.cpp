#include "draw_module.h"

#include "load.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace kerf::cli {

namespace {

std::filesystem::path programFolder() {
  std::string buf(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size());
  if (n <= 0 || static_cast<std::size_t>(n) >= buf.size()) return {};
  buf.resize(static_cast<std::size_t>(n));
  return std::filesystem::path(buf).parent_path();
}

std::vector<std::string> candidates() {
  if (const char* named = std::getenv("KERF_DRAW_LIBRARY"); named && *named) return {named};
  const std::filesystem::path folder = programFolder();
  if (folder.empty()) return {};
  return {(folder / "libkerf-draw.so").string(), (folder / KERF_DRAW_RELATIVE / "libkerf-draw.so").string()};
}

const DrawCommands* load(std::string& error) {
  const std::vector<std::string> paths = candidates();
  if (paths.empty()) {
    error = "cannot find the folder this program is in, so not its drawing module either";
    return nullptr;
  }
  std::string tried;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path;
      continue;
    }
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      error = "cannot load the drawing module " + path + ": " + (why ? why : "unknown reason");
      return nullptr;
    }
    using Entry = const DrawCommands* (*)();
    const void* symbol = ::dlsym(handle, "kerf_draw_commands");
    Entry entry = nullptr;
    static_assert(sizeof entry == sizeof symbol);
    std::memcpy(&entry, &symbol, sizeof entry);  // POSIX: dlsym's object pointer is the function's address
    const DrawCommands* commands = entry ? entry() : nullptr;
    if (!commands || commands->abi != kDrawAbi || std::string(commands->version) != kDrawVersion) {
      error = "the drawing module " + path + " comes from another build of kerf";
      return nullptr;
    }
    return commands;  // kept loaded until the program ends
  }
  error = "the drawing module is not installed (looked for " + tried + ")";
  return nullptr;
}

}  // namespace

const DrawCommands* loadDrawCommands(std::string& error) {
  static std::string why;
  static const DrawCommands* const commands = load(why);
  if (!commands) error = why;
  return commands;
}

int drawModuleMissing(const std::string& error) {
  reportError(error + "; render, view, mesh and page export need it (check, explain, convert and cam do not)");
  return kExitUsage;
}

}  // namespace kerf::cli

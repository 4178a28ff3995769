// The commands that draw (render, view, and export to a mesh) live in a module of their own,
// libkerf-draw.so, which the program loads only when one of them runs. kerf check, explain,
// convert, cam, machines and export to DXF load no OpenGL, OSMesa, EGL, VTK, GLFW or ImGui
// library: they start in a few milliseconds, and they run where those libraries are missing.
//
// The module is found beside the program (the build tree), then in KERF_DRAW_RELATIVE from the
// program's folder (an installed kerf: ../lib/kerf). KERF_DRAW_LIBRARY in the environment names
// it outright (a test, a relocated package).
#pragma once

#include "commands.h"

#include <cstdint>
#include <string>

namespace kerf::cli {

/// Changes with the layout of the arguments the program hands the module, so a module from another
/// build is refused instead of misread.
inline constexpr std::uint64_t kDrawAbi =
    1u + (sizeof(RenderArgs) << 8) + (sizeof(ViewArgs) << 24) + (static_cast<std::uint64_t>(sizeof(ExportArgs)) << 40) +
    (static_cast<std::uint64_t>(sizeof(CommonOptions)) << 52) + (static_cast<std::uint64_t>(sizeof(ReportArgs)) << 32);
inline constexpr const char* kDrawVersion = KERF_VERSION;

struct DrawCommands {
  std::uint64_t abi;
  const char* version;
  int (*render)(const RenderArgs&);
  int (*view)(const ViewArgs&);
  int (*exportMesh)(const ExportArgs&);  ///< -o .vtp, .stl, .ply
  int (*exportPage)(const ExportArgs&);  ///< -o .html: the 3D page
  /// Writes what it can of each program's pictures and 3D page; the number of programs drawn.
  std::size_t (*reportPictures)(const ReportArgs&);
};

/// The module's commands, loaded once; nothing, with the reason in error, when the module is
/// missing, cannot be loaded (a library it needs is missing) or comes from another build.
const DrawCommands* loadDrawCommands(std::string& error);

/// Reports why the drawing commands cannot run; the exit code for it (2).
int drawModuleMissing(const std::string& error);

}  // namespace kerf::cli

// Headless OpenGL 3.3 core contexts: no display, no GPU. Two back ends, found at run time with
// dlopen so one binary works whichever Mesa the machine has:
//   - OSMesa (libOSMesa.so.8, OSMesaCreateContextAttribs with the core profile): Mesa up to 25.0;
//   - EGL with the surfaceless platform (EGL_MESA_platform_surfaceless; libEGL.so.1): newer Mesa.
// Either renders into an OffscreenTarget; the context's own buffer is a token 1x1.
#pragma once

#include "kerf/render/gl.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::headless {

enum class Backend { Auto, OSMesa, Egl };
std::optional<Backend> parseBackend(std::string_view name);
const char* backendName(Backend b);

class Context {
 public:
  virtual ~Context() = default;
  /// Loads GL functions of this context (for render::loadGl).
  [[nodiscard]] virtual render::GlProcLoader loader() const = 0;
  [[nodiscard]] virtual Backend backend() const = 0;
  /// "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6".
  [[nodiscard]] std::string description() const;
};

/// A current OpenGL 3.3 core context with the GL table loaded. Auto tries OSMesa, then EGL. On
/// failure returns null and says, for each back end tried, why it did not work.
std::unique_ptr<Context> createContext(Backend backend, std::string& error);

}  // namespace kerf::headless

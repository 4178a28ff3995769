#include "kerf/render/gl.h"

#include <cstdio>
#include <cstring>

namespace kerf::render {
namespace {
GlApi table;
}

bool loadGl(GlProcLoader loader, std::string& error) {
  GlApi loaded;
  const char* missing = nullptr;
#define KERF_GL_LOAD(type, name)                            \
  loaded.name = reinterpret_cast<type>(loader("gl" #name)); \
  if (loaded.name == nullptr && missing == nullptr) missing = "gl" #name;
  KERF_GL_FUNCTIONS(KERF_GL_LOAD)
#undef KERF_GL_LOAD
  if (missing != nullptr) {
    error = std::string("the OpenGL context has no ") + missing;
    return false;
  }
  GLint major = 0, minor = 0;
  loaded.GetIntegerv(GL_MAJOR_VERSION, &major);
  loaded.GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major < 3 || (major == 3 && minor < 3)) {
    const auto* version = reinterpret_cast<const char*>(loaded.GetString(GL_VERSION));
    error = std::string("OpenGL 3.3 core is needed; the context gives ") + (version ? version : "no version");
    return false;
  }
  table = loaded;
  return true;
}

const GlApi& gl() { return table; }

}  // namespace kerf::render

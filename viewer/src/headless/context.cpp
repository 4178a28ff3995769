// Index: dynamic loading; OSMesa; EGL surfaceless; createContext.
#include "kerf/headless/context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>

namespace kerf::headless {

std::optional<Backend> parseBackend(std::string_view name) {
  if (name == "auto") return Backend::Auto;
  if (name == "osmesa") return Backend::OSMesa;
  if (name == "egl") return Backend::Egl;
  return std::nullopt;
}

const char* backendName(Backend b) {
  switch (b) {
    case Backend::Auto: return "auto";
    case Backend::OSMesa: return "osmesa";
    case Backend::Egl: return "egl";
  }
  return "auto";
}

std::string Context::description() const {
  const render::GlApi& g = render::gl();
  const auto* renderer = reinterpret_cast<const char*>(g.GetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(g.GetString(GL_VERSION));
  return std::string(backend() == Backend::OSMesa ? "OSMesa" : "EGL surfaceless") + ": " + (renderer ? renderer : "?") +
         ", OpenGL " + (version ? version : "?");
}

namespace {

// ---- dynamic loading ------------------------------------------------------------------------

void* openFirst(std::initializer_list<const char*> names, std::string& error) {
  for (const char* n : names)
    if (void* h = dlopen(n, RTLD_NOW | RTLD_LOCAL)) return h;
  error = std::string("cannot load ") + *names.begin() + " (" + dlerror() + ")";
  return nullptr;
}

template <typename F>
bool symbol(void* lib, const char* name, F& out, std::string& error) {
  out = reinterpret_cast<F>(dlsym(lib, name));
  if (out == nullptr) error = std::string("the library has no ") + name;
  return out != nullptr;
}

// ---- OSMesa ---------------------------------------------------------------------------------

using OSMesaCreateContextAttribsFn = OSMesaContext (*)(const int*, OSMesaContext);
using OSMesaMakeCurrentFn = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using OSMesaGetProcAddressFn = OSMESAproc (*)(const char*);
using OSMesaDestroyContextFn = void (*)(OSMesaContext);

OSMesaGetProcAddressFn osmesaGetProc = nullptr;
void* osmesaLoader(const char* name) { return reinterpret_cast<void*>(osmesaGetProc(name)); }

class OSMesaContextImpl final : public Context {
 public:
  bool create(std::string& error) {
    lib_ = openFirst({"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}, error);
    if (!lib_) return false;
    OSMesaCreateContextAttribsFn createFn = nullptr;
    OSMesaMakeCurrentFn makeCurrent = nullptr;
    if (!symbol(lib_, "OSMesaCreateContextAttribs", createFn, error) ||
        !symbol(lib_, "OSMesaMakeCurrent", makeCurrent, error) ||
        !symbol(lib_, "OSMesaGetProcAddress", osmesaGetProc, error) ||
        !symbol(lib_, "OSMesaDestroyContext", destroy_, error))
      return false;
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = createFn(attribs, nullptr);
    if (!context_) {
      error = "OSMesaCreateContextAttribs gave no OpenGL 3.3 core context";
      return false;
    }
    if (!makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      error = "OSMesaMakeCurrent failed";
      return false;
    }
    return render::loadGl(&osmesaLoader, error);
  }
  ~OSMesaContextImpl() override {
    if (context_) destroy_(context_);
    // The library stays loaded: Mesa keeps threads and atexit handlers that outlive a dlclose.
  }
  [[nodiscard]] render::GlProcLoader loader() const override { return &osmesaLoader; }
  [[nodiscard]] Backend backend() const override { return Backend::OSMesa; }

 private:
  void* lib_ = nullptr;
  OSMesaContext context_ = nullptr;
  OSMesaDestroyContextFn destroy_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

// ---- EGL surfaceless ------------------------------------------------------------------------

using EglGetProcAddressFn = void* (*)(const char*);
EglGetProcAddressFn eglGetProc = nullptr;
void* eglLoader(const char* name) { return eglGetProc(name); }

class EglContextImpl final : public Context {
 public:
  bool create(std::string& error) {
    lib_ = openFirst({"libEGL.so.1", "libEGL.so"}, error);
    if (!lib_) return false;
    if (!symbol(lib_, "eglGetProcAddress", eglGetProc, error) || !symbol(lib_, "eglInitialize", initialize_, error) ||
        !symbol(lib_, "eglBindAPI", bindApi_, error) || !symbol(lib_, "eglChooseConfig", chooseConfig_, error) ||
        !symbol(lib_, "eglCreateContext", createContext_, error) ||
        !symbol(lib_, "eglMakeCurrent", makeCurrent_, error) ||
        !symbol(lib_, "eglDestroyContext", destroyContext_, error) || !symbol(lib_, "eglTerminate", terminate_, error))
      return false;
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProc("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
      error = "EGL has no eglGetPlatformDisplayEXT";
      return false;
    }
    display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !initialize_(display_, &major, &minor)) {
      error = "EGL has no surfaceless display (EGL_MESA_platform_surfaceless)";
      display_ = EGL_NO_DISPLAY;
      return false;
    }
    if (!bindApi_(EGL_OPENGL_API)) {
      error = "EGL cannot bind the desktop OpenGL API";
      return false;
    }
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!chooseConfig_(display_, configAttribs, &config, 1, &count) || count < 1) {
      error = "EGL has no desktop OpenGL configuration";
      return false;
    }
    const EGLint contextAttribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = createContext_(display_, config, EGL_NO_CONTEXT, contextAttribs);
    if (context_ == EGL_NO_CONTEXT) {
      error = "eglCreateContext gave no OpenGL 3.3 core context";
      return false;
    }
    if (!makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      error = "eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context)";
      return false;
    }
    return render::loadGl(&eglLoader, error);
  }
  ~EglContextImpl() override {
    if (display_ != EGL_NO_DISPLAY) {
      makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (context_ != EGL_NO_CONTEXT) destroyContext_(display_, context_);
      terminate_(display_);
    }
  }
  [[nodiscard]] render::GlProcLoader loader() const override { return &eglLoader; }
  [[nodiscard]] Backend backend() const override { return Backend::Egl; }

 private:
  void* lib_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  PFNEGLINITIALIZEPROC initialize_ = nullptr;
  PFNEGLBINDAPIPROC bindApi_ = nullptr;
  PFNEGLCHOOSECONFIGPROC chooseConfig_ = nullptr;
  PFNEGLCREATECONTEXTPROC createContext_ = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent_ = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroyContext_ = nullptr;
  PFNEGLTERMINATEPROC terminate_ = nullptr;
};

template <typename Impl>
std::unique_ptr<Context> tryCreate(std::string& error) {
  auto c = std::make_unique<Impl>();
  if (!c->create(error)) return nullptr;
  return c;
}

}  // namespace

std::unique_ptr<Context> createContext(Backend backend, std::string& error) {
  std::string osmesaError, eglError;
  if (backend == Backend::OSMesa || backend == Backend::Auto)
    if (auto c = tryCreate<OSMesaContextImpl>(osmesaError)) return c;
  if (backend == Backend::Egl || backend == Backend::Auto)
    if (auto c = tryCreate<EglContextImpl>(eglError)) return c;
  error = "no headless OpenGL 3.3 context:";
  if (!osmesaError.empty()) error += " OSMesa: " + osmesaError + ";";
  if (!eglError.empty()) error += " EGL surfaceless: " + eglError + ";";
  error += " install Mesa's libosmesa6 or libegl-mesa0, or choose one with --backend osmesa|egl";
  return nullptr;
}

}  // namespace kerf::headless

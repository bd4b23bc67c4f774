// Surfaceless EGL context. llvmpipe exposes only pbuffer configs, so the context is made with
// EGL_KHR_no_config_context and rendering goes into an FBO owned by gfx.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>
#include <vector>

#include "platform/platform.h"

namespace arc {
namespace {

const char* egl_error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
  }
}

[[noreturn]] void fail(const std::string& step) {
  throw PlatformError("EGL: " + step + " failed (" + egl_error_name(eglGetError()) + ")");
}

bool has_ext(const char* list, const char* name) {
  if (!list) return false;
  size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

EGLDisplay open_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_ext(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) {
      EGLint major = 0, minor = 0;
      if (eglInitialize(d, &major, &minor)) return d;
    }
  }
  if (!has_ext(client, "EGL_EXT_platform_device")) fail("eglGetPlatformDisplayEXT(surfaceless or device)");
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) fail("eglQueryDevicesEXT");
  std::vector<EGLDeviceEXT> devices(count);
  if (!eglQueryDevicesEXT(count, devices.data(), &count)) fail("eglQueryDevicesEXT");
  for (EGLint i = 0; i < count; ++i) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (d == EGL_NO_DISPLAY) continue;
    EGLint major = 0, minor = 0;
    if (eglInitialize(d, &major, &minor)) return d;
  }
  fail("eglInitialize (platform device)");
}

class EglHeadless final : public HeadlessContext {
 public:
  EglHeadless() {
    display_ = open_display();
    if (!has_ext(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
      throw PlatformError("EGL: EGL_KHR_no_config_context missing (EGL_BAD_CONFIG)");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext(3.3 core, no config)");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent(EGL_NO_SURFACE)");
    const char* v = eglQueryString(display_, EGL_VERSION);
    description_ = std::string("EGL ") + (v ? v : "?") + " surfaceless, OpenGL " +
                   reinterpret_cast<const char*>(glGetString(GL_VERSION)) + " (" +
                   reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ")";
  }
  ~EglHeadless() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    // No eglTerminate: the display handle is shared by every context of the process.
    eglDestroyContext(display_, context_);
  }
  std::string description() const override { return description_; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string description_;
};

}  // namespace

std::unique_ptr<HeadlessContext> create_headless_context() { return std::make_unique<EglHeadless>(); }

}  // namespace arc

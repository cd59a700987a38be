#if PLUMBAGO_GL_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "gpu/gl/platform.hpp"

namespace plumbago::gpu {
namespace {

template <class F>
F egl_proc(const char* name) {
  auto f = reinterpret_cast<F>(eglGetProcAddress(name));
  if (!f) throw std::runtime_error(std::string("EGL lacks ") + name);
  return f;
}

bool has_extension(EGLDisplay display, const char* ext) {
  const char* list = eglQueryString(display, EGL_EXTENSIONS);
  return list && std::strstr(list, ext);
}

// An NVIDIA (or any non-software) device through EGL_EXT_platform_device, if present.
EGLDisplay device_display() {
  if (!has_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) return EGL_NO_DISPLAY;
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLint count = 0;
  query_devices(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(size_t(count > 0 ? count : 0));
  query_devices(count, devices.data(), &count);
  for (EGLDeviceEXT d : devices) {
    const char* exts = query_string(d, EGL_EXTENSIONS);
    bool software = exts && std::strstr(exts, "EGL_MESA_device_software");
    if (!software) return platform_display(EGL_PLATFORM_DEVICE_EXT, d, nullptr);
  }
  return EGL_NO_DISPLAY;
}

EGLDisplay surfaceless_display() {
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  return platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

struct EglContext : Context::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  ~EglContext() override {
    if (context != EGL_NO_CONTEXT) {
      make_current(false);
      eglDestroyContext(display, context);
    }
    if (display != EGL_NO_DISPLAY) eglTerminate(display);
  }
  bool make_current(bool current) override {
    return eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, current ? context : EGL_NO_CONTEXT);
  }
};

EGLContext create_core_context(EGLDisplay display) {
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &n) || n == 0) config = nullptr;
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    4,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_CONTEXT_OPENGL_DEBUG,
                                    EGL_TRUE,
                                    EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
}

}  // namespace

std::unique_ptr<Context::Impl> create_platform_context(std::string& platform) {
  auto egl = std::make_unique<EglContext>();
  egl->display = device_display();
  platform = "egl-device";
  if (egl->display == EGL_NO_DISPLAY) {
    egl->display = surfaceless_display();
    platform = "egl-surfaceless";
  }
  if (egl->display == EGL_NO_DISPLAY || !eglInitialize(egl->display, nullptr, nullptr))
    throw std::runtime_error(
        "no EGL display: install the Debian package 'libegl-mesa0' (Mesa's EGL) "
        "or an NVIDIA driver");
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL cannot bind the desktop OpenGL API");
  egl->context = create_core_context(egl->display);
  if (egl->context == EGL_NO_CONTEXT)
    throw std::runtime_error("EGL cannot create a GL 4.5 core context (EGL error 0x" + std::to_string(eglGetError()) +
                             "); Mesa's llvmpipe needs 'libgl1-mesa-dri'");
  if (!egl->make_current(true)) throw std::runtime_error("EGL cannot make the context current without a surface");
  return egl;
}

}  // namespace plumbago::gpu
#endif

#if PLUMBAGO_GL_OSMESA
#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "gpu/gl/platform.hpp"

namespace plumbago::gpu {
namespace {

struct OsMesaContext : Context::Impl {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer = std::vector<unsigned char>(4);  // 1x1: we draw into FBOs
  ~OsMesaContext() override {
    if (context) OSMesaDestroyContext(context);
  }
  bool make_current(bool current) override {
    return current ? OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, 1, 1)
                   : OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
};

}  // namespace

std::unique_ptr<Context::Impl> create_platform_context(std::string& platform) {
  platform = "osmesa";
  auto os = std::make_unique<OsMesaContext>();
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         4,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         5,
                         0};
  os->context = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!os->context) throw std::runtime_error("OSMesa cannot create a GL 4.5 core context");
  if (!os->make_current(true)) throw std::runtime_error("OSMesa cannot make the context current");
  return os;
}

}  // namespace plumbago::gpu
#endif

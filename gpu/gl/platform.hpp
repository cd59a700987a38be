// The platform half of the GL context: EGL (egl_context.cpp) or OSMesa
// (osmesa_context.cpp), chosen at build time by PLUMBAGO_GL.
#pragma once

#include <memory>
#include <string>

#include "gpu/gl/context.hpp"

namespace plumbago::gpu {

struct Context::Impl {
  virtual ~Impl() = default;
  // Makes the context current (true) or none current (false); false when refused.
  virtual bool make_current(bool current) = 0;
};

// Creates a GL 4.5 core context and makes it current; sets `platform` to its name.
std::unique_ptr<Context::Impl> create_platform_context(std::string& platform);

}  // namespace plumbago::gpu

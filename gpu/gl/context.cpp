#include "gpu/gl/context.hpp"

#include <malloc.h>

#include <stdexcept>

#include "gpu/gl/gl.hpp"
#include "gpu/gl/platform.hpp"

namespace plumbago::gpu {

void debug_callback_sink(Context& ctx, bool is_error, std::string message) {
  (is_error ? ctx.errors_ : ctx.messages_).push_back(std::move(message));
}

namespace {

void GLAPIENTRY on_debug_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei length, const GLchar* text,
                                 const void* user) {
  bool is_error = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
  debug_callback_sink(*static_cast<Context*>(const_cast<void*>(user)), is_error, std::string(text, size_t(length)));
}

// llvmpipe allocates and frees tens of MB of vertex and bin memory on every draw of a
// large mesh. With glibc's default policy the freed top of the heap is given back to the
// kernel and the next frame page-faults it in again: the sketchy Ogre frame took 228 ms
// where the same frame after an earlier renderer had warmed the heap took 64 ms. Keeping
// freed memory (blocks up to 32 MiB on the heap, no trimming below 512 MiB) gives every
// renderer the warm speed; with a hardware driver it changes nothing measurable.
void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

Context& Context::get() {
  static Context context;
  return context;
}

Context::Context() : impl_((keep_freed_memory(), create_platform_context(platform_))) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 45)
    throw std::runtime_error("GL 4.5 core is needed, the context offers " + gl_string(GL_VERSION) + " (" +
                             gl_string(GL_RENDERER) + ")");
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(on_debug_message, this);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

Context::~Context() = default;

std::string Context::renderer() const { return gl_string(GL_RENDERER); }
std::string Context::version() const { return gl_string(GL_VERSION); }

void Context::check_errors(const std::string& what) {
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    errors_.push_back("glGetError 0x" + [](GLenum v) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%04X", v);
      return std::string(buf);
    }(e));
  if (errors_.empty()) return;
  std::string text = "GL error during " + what + ":";
  for (const auto& e : errors_) text += "\n  " + e;
  errors_.clear();
  throw std::runtime_error(text);
}

void Context::make_current() {
  if (!impl_->make_current(true))
    throw std::runtime_error("cannot make the " + platform_ + " GL context current again");
}

void Context::release() {
  if (!impl_->make_current(false)) throw std::runtime_error("cannot release the " + platform_ + " GL context");
}

std::vector<std::string> Context::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

}  // namespace plumbago::gpu

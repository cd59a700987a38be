// RAII owners of GL objects (direct state access, GL 4.5) and image transfer.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "common/util/image.hpp"
#include "gpu/gl/gl.hpp"

namespace plumbago::gpu {

// Owns one GL name; `Deleter` frees it.
template <void (*Delete)(GLuint)>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  ~GlName() { reset(); }
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
}  // namespace detail

using Buffer = GlName<detail::delete_buffer>;
using Framebuffer = GlName<detail::delete_framebuffer>;
using Renderbuffer = GlName<detail::delete_renderbuffer>;
using VertexArray = GlName<detail::delete_vertex_array>;

// A 2D or 3D texture with its size and format.
struct Texture {
  GlName<detail::delete_texture> name;
  int width = 0, height = 0;
  GLenum internal_format = 0;
  GLenum target = GL_TEXTURE_2D;
  int depth = 1;  // layers of a GL_TEXTURE_3D
  GLuint id() const { return name.id(); }
};

// Immutable storage of `internal_format`, NEAREST filtering, CLAMP_TO_EDGE.
Texture make_texture(int width, int height, GLenum internal_format);
// A GL_TEXTURE_2D_ARRAY of `layers` layers, uninitialized; NEAREST, CLAMP_TO_EDGE.
Texture make_texture_array(int width, int height, int layers, GLenum internal_format);
// A GL_TEXTURE_3D (filtered across layers, as the pencil stack is sampled) or a
// GL_TEXTURE_2D_ARRAY (layers kept apart) made of `layers` (equal sizes); LINEAR,
// REPEAT in s and t, CLAMP_TO_EDGE in r.
Texture upload_texture_3d(const std::vector<Image>& layers, GLenum internal_format, GLenum target = GL_TEXTURE_3D);
// Uploads a float image (1-4 channels) into a texture of `internal_format`; an unsigned
// integer format gets the floats as whole numbers.
Texture upload_texture(const Image& img, GLenum internal_format);
// Replaces a texture's contents: `channels` floats (or uint32 when `integer`) per texel.
void write_texture(const Texture& tex, int channels, bool integer, const void* data);
// Filter (GL_NEAREST/GL_LINEAR) and wrap modes (GL_REPEAT/GL_CLAMP_TO_EDGE) of a texture
// (wrap_r matters for 3D textures only).
void set_sampling(const Texture& tex, GLenum filter, GLenum wrap_s, GLenum wrap_t, GLenum wrap_r = GL_CLAMP_TO_EDGE);
// Reads back `channels` float channels (row 0 = bottom, as GL stores it); an unsigned
// integer texture's values as floats.
Image download_texture(const Texture& tex, int channels);
ImageU32 download_texture_u32(const Texture& tex, int channels);
// The first `records` records of a float table (common/util/image.hpp table_image), `channels`
// floats each, read back in record order: the rows they take, a partial one whole.
std::vector<float> read_table(const Texture& table, int channels, size_t records);

// A buffer of `bytes` from `data` (or uninitialized where null), of at least 16 bytes: GL
// refuses a buffer of none, and a binding of one.
Buffer make_buffer(const void* data, size_t bytes);
// A buffer kept across frames and made anew only to hold more (a renderer's bounds repeat
// from frame to frame); one made from data holds it for one use.
struct ScratchBuffer {
  Buffer buffer;
  size_t bytes = 0;
  void reserve(size_t n) {
    if (!buffer.id() || n > bytes) buffer = make_buffer(nullptr, n), bytes = n;
  }
  GLuint id() const { return buffer.id(); }
  operator const Buffer&() const { return buffer; }
};
// A scratch buffer holding `records`, for one use.
template <class T>
ScratchBuffer scratch_of(const std::vector<T>& records) {
  return {make_buffer(records.data(), records.size() * sizeof(T)), records.size() * sizeof(T)};
}
// Sets every uint32 of `buffer` to `value`, on the GPU.
void clear_buffer(const Buffer& buffer, uint32_t value = 0);
// Copies `bytes` from the start of `from` into `to` from byte `offset`, on the GPU.
void copy_buffer(const Buffer& from, const Buffer& to, size_t bytes, size_t offset = 0);
// Reads `bytes` of a buffer from `offset` back into `out`.
void read_buffer(const Buffer& buffer, void* out, size_t bytes, size_t offset = 0);
// Every byte read back from GPU memory so far (download_texture*, read_buffer): what a frame
// read back is the difference across it.
size_t bytes_read_back();
VertexArray make_vertex_array();
Framebuffer make_framebuffer();
Renderbuffer make_renderbuffer(int width, int height, GLenum internal_format);

}  // namespace plumbago::gpu

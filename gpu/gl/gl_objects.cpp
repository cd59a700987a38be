#include "gpu/gl/gl_objects.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

// Written against GL 4.3 bind-to-edit entry points, not 4.5 direct state access: Mesa's
// libOSMesa exports no DSA functions, and the OSMesa build links them statically.
namespace plumbago::gpu {

namespace {

GLenum format_of(int channels) {
  switch (channels) {
    case 1:
      return GL_RED;
    case 2:
      return GL_RG;
    case 3:
      return GL_RGB;
    case 4:
      return GL_RGBA;
  }
  throw std::invalid_argument("images have 1 to 4 channels, not " + std::to_string(channels));
}

GLenum integer_format_of(int channels) {
  switch (channels) {
    case 1:
      return GL_RED_INTEGER;
    case 2:
      return GL_RG_INTEGER;
    case 3:
      return GL_RGB_INTEGER;
    case 4:
      return GL_RGBA_INTEGER;
  }
  throw std::invalid_argument("images have 1 to 4 channels, not " + std::to_string(channels));
}

std::atomic<size_t> read_back{0};

template <class T>
void read_texture(const Texture& tex, GLenum format, GLenum type, std::vector<T>& out) {
  read_back += out.size() * sizeof(T);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glGetTexImage(GL_TEXTURE_2D, 0, format, type, out.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace

Texture make_texture(int width, int height, GLenum internal_format) {
  GLuint id = 0;
  glGenTextures(1, &id);
  Texture t{GlName<detail::delete_texture>(id), width, height, internal_format};
  glBindTexture(GL_TEXTURE_2D, id);
  glTexStorage2D(GL_TEXTURE_2D, 1, internal_format, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

Texture make_texture_array(int width, int height, int layers, GLenum internal_format) {
  GLuint id = 0;
  glGenTextures(1, &id);
  Texture t{GlName<detail::delete_texture>(id), width, height, internal_format, GL_TEXTURE_2D_ARRAY, layers};
  glBindTexture(GL_TEXTURE_2D_ARRAY, id);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, internal_format, width, height, layers);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  set_sampling(t, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
  return t;
}

void write_texture(const Texture& tex, int channels, bool integer, const void* data) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, tex.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, tex.width, tex.height,
                  integer ? integer_format_of(channels) : format_of(channels), integer ? GL_UNSIGNED_INT : GL_FLOAT,
                  data);
  glBindTexture(GL_TEXTURE_2D, 0);
}

bool integer_texture(GLenum internal_format) {
  return internal_format == GL_R32UI || internal_format == GL_RG32UI || internal_format == GL_RGBA32UI;
}

Texture upload_texture(const Image& img, GLenum internal_format) {
  Texture t = make_texture(img.width, img.height, internal_format);
  if (!integer_texture(internal_format)) {
    write_texture(t, img.channels, false, img.data.data());
    return t;
  }
  std::vector<uint32_t> values(img.data.begin(), img.data.end());  // whole numbers held as floats
  write_texture(t, img.channels, true, values.data());
  return t;
}

Image download_texture(const Texture& tex, int channels) {
  Image img(tex.width, tex.height, channels);
  if (!integer_texture(tex.internal_format)) {
    read_texture(tex, format_of(channels), GL_FLOAT, img.data);
    return img;
  }
  ImageU32 values = download_texture_u32(tex, channels);
  img.data.assign(values.data.begin(), values.data.end());
  return img;
}

ImageU32 download_texture_u32(const Texture& tex, int channels) {
  ImageU32 img(tex.width, tex.height, channels);
  read_texture(tex, integer_format_of(channels), GL_UNSIGNED_INT, img.data);
  return img;
}

std::vector<float> read_table(const Texture& table, int channels, size_t records) {
  const auto width = size_t(table.width), columns = std::min(width, records);
  const size_t rows = std::min(size_t(table.height), (records + width - 1) / width);
  std::vector<float> out(columns * rows * size_t(channels));
  if (out.empty()) return out;
  read_back += out.size() * sizeof(float);
  Framebuffer fbo = make_framebuffer();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, table.id(), 0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, GLsizei(columns), GLsizei(rows), format_of(channels), GL_FLOAT, out.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return out;
}

void set_sampling(const Texture& tex, GLenum filter, GLenum wrap_s, GLenum wrap_t, GLenum wrap_r) {
  glBindTexture(tex.target, tex.id());
  glTexParameteri(tex.target, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTexParameteri(tex.target, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTexParameteri(tex.target, GL_TEXTURE_WRAP_S, GLint(wrap_s));
  glTexParameteri(tex.target, GL_TEXTURE_WRAP_T, GLint(wrap_t));
  glTexParameteri(tex.target, GL_TEXTURE_WRAP_R, GLint(wrap_r));
  glBindTexture(tex.target, 0);
}

Texture upload_texture_3d(const std::vector<Image>& layers, GLenum internal_format, GLenum target) {
  const Image& first = layers.at(0);
  GLuint id = 0;
  glGenTextures(1, &id);
  Texture t{GlName<detail::delete_texture>(id), first.width, first.height, internal_format, target, int(layers.size())};
  glBindTexture(target, id);
  glTexStorage3D(target, 1, internal_format, first.width, first.height, GLsizei(layers.size()));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (size_t l = 0; l < layers.size(); ++l)
    glTexSubImage3D(target, 0, 0, 0, GLint(l), first.width, first.height, 1, format_of(first.channels), GL_FLOAT,
                    layers[l].data.data());
  glBindTexture(target, 0);
  set_sampling(t, GL_LINEAR, GL_REPEAT, GL_REPEAT, GL_CLAMP_TO_EDGE);
  return t;
}

Buffer make_buffer(const void* data, size_t bytes) {
  constexpr size_t kLeast = 16;
  std::vector<unsigned char> padded;
  if (bytes < kLeast) {
    padded.assign(kLeast, 0);
    if (data) std::copy_n(static_cast<const unsigned char*>(data), bytes, padded.begin());
    data = padded.data(), bytes = kLeast;
  }
  GLuint id = 0;
  glGenBuffers(1, &id);
  glBindBuffer(GL_ARRAY_BUFFER, id);
  glBufferStorage(GL_ARRAY_BUFFER, GLsizeiptr(bytes), data, 0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return Buffer(id);
}

void clear_buffer(const Buffer& buffer, uint32_t value) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());  // not glClearNamedBufferData: OSMesa has no such entry
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void copy_buffer(const Buffer& from, const Buffer& to, size_t bytes, size_t offset) {
  glBindBuffer(GL_COPY_READ_BUFFER, from.id());
  glBindBuffer(GL_COPY_WRITE_BUFFER, to.id());  // not glCopyNamedBufferSubData: OSMesa has no such entry
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, GLintptr(offset), GLsizeiptr(bytes));
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

VertexArray make_vertex_array() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return VertexArray(id);
}

Framebuffer make_framebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return Framebuffer(id);
}

Renderbuffer make_renderbuffer(int width, int height, GLenum internal_format) {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  glBindRenderbuffer(GL_RENDERBUFFER, id);
  glRenderbufferStorage(GL_RENDERBUFFER, internal_format, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  return Renderbuffer(id);
}

void read_buffer(const Buffer& buffer, void* out, size_t bytes, size_t offset) {
  read_back += bytes;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());  // not glGetNamedBufferSubData: OSMesa has no such entry
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), out);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

size_t bytes_read_back() { return read_back; }

}  // namespace plumbago::gpu

#include "gpu/gl_objects.hpp"

#include <stdexcept>
#include <string>

namespace plumbago::gpu {

namespace {

GLenum format_of(int channels) {
  switch (channels) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    case 4: return GL_RGBA;
  }
  throw std::invalid_argument("images have 1 to 4 channels, not " + std::to_string(channels));
}

GLenum integer_format_of(int channels) {
  switch (channels) {
    case 1: return GL_RED_INTEGER;
    case 2: return GL_RG_INTEGER;
    case 3: return GL_RGB_INTEGER;
    case 4: return GL_RGBA_INTEGER;
  }
  throw std::invalid_argument("images have 1 to 4 channels, not " + std::to_string(channels));
}

}  // namespace

Texture make_texture(int width, int height, GLenum internal_format) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  Texture t{GlName<detail::delete_texture>(id), width, height, internal_format};
  glTextureStorage2D(id, 1, internal_format, width, height);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

Texture upload_texture(const Image& img, GLenum internal_format) {
  Texture t = make_texture(img.width, img.height, internal_format);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, format_of(img.channels), GL_FLOAT, img.data.data());
  return t;
}

Image download_texture(const Texture& tex, int channels) {
  Image img(tex.width, tex.height, channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex.id(), 0, format_of(channels), GL_FLOAT, GLsizei(img.data.size() * sizeof(float)),
                    img.data.data());
  return img;
}

ImageU32 download_texture_u32(const Texture& tex, int channels) {
  ImageU32 img(tex.width, tex.height, channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex.id(), 0, integer_format_of(channels), GL_UNSIGNED_INT,
                    GLsizei(img.data.size() * sizeof(uint32_t)), img.data.data());
  return img;
}

Buffer make_buffer(const void* data, size_t bytes) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  glNamedBufferStorage(id, GLsizeiptr(bytes), data, 0);
  return Buffer(id);
}

VertexArray make_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

Framebuffer make_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}

Renderbuffer make_renderbuffer(int width, int height, GLenum internal_format) {
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  glNamedRenderbufferStorage(id, internal_format, width, height);
  return Renderbuffer(id);
}

}  // namespace plumbago::gpu

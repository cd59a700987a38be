// Full-window passes: draw one triangle into a texture, every fragment at a pixel center.
#pragma once

#include <glm/glm.hpp>

#include "common/util/image.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

class FullscreenPass {
 public:
  FullscreenPass();
  // Binds each texture to the sampler uniform it names (gpu/gl/program.hpp bind_textures),
  // then draws `program` into `target`.
  void draw(const Program& program, std::initializer_list<TextureBinding> textures, Texture& target);
  // The same into several targets of one size: fragment output k goes to targets[k].
  void draw(const Program& program, std::initializer_list<TextureBinding> textures,
            std::initializer_list<Texture*> targets);
  // The same, but only the pixels inside `rect` run the program: target k is first
  // cleared to outside[k], the value the program would write there.
  void draw_inside(const Program& program, std::initializer_list<TextureBinding> textures,
                   std::initializer_list<Texture*> targets, const PixelRect& rect,
                   std::initializer_list<glm::vec4> outside);
  // The same into one layer of a GL_TEXTURE_2D_ARRAY.
  void draw_layer(const Program& program, std::initializer_list<TextureBinding> textures, Texture& array, int layer);

 private:
  void bind_targets(std::initializer_list<Texture*> targets);
  void use_attachments(GLsizei n, const Texture& first);
  void draw_triangle(const Program& program, std::initializer_list<TextureBinding> textures);
  Framebuffer fbo_;
  VertexArray empty_;
};

}  // namespace plumbago::gpu

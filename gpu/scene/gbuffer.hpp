// Rasterized G-buffer (docs/stages.md, gbuffer), the twin of reference/scene/gbuffer.cpp.
#pragma once

#include <climits>
#include <memory>
#include <string>
#include <vector>

#include "common/pencil/interior_intensity.hpp"
#include "common/scene/gbuffer.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"

namespace plumbago::gpu {

// The G-buffer's render targets, kept on the GPU for the stages that read them.
struct GBufferTargets {
  Texture normal, face_normal, depth, ids, bary, gouraud, theta_min, theta_max;
  float near = 0, far = 1;
  int width() const { return depth.width; }
  int height() const { return depth.height; }
};

// Each triangle's corner angles (Lee et al. 2006, §5.3), what the G-buffer's angle channels hold at its
// pixels, as one record per triangle: the pencil interior reads them through the ids
// channel, so a frame writes no angle targets (two float targets less for llvmpipe).
struct TriangleAngles {
  Buffer angles;          // std430 vec4 pairs: theta_min of corners 0-2, then theta_max (w unused)
  Buffer first_triangle;  // uint per object (object id - 1): the index of its first record
};
// Parity only: the records of a G-buffer's ids and angle channels (zero where it has no
// angles), for a stage fed the reference's G-buffer.
TriangleAngles triangle_angles_from(const GBuffer& g);

GBufferTargets make_gbuffer_targets(int width, int height, GBufferFormat normal_format);
GBuffer download_gbuffer(const GBufferTargets& targets);
// Parity only: the reference's G-buffer on the GPU, so that a later stage gets identical inputs.
GBufferTargets upload_gbuffer(const GBuffer& g);

// Which G-buffer channels a frame's passes sample (each says so: gpu/core/stage.hpp); the
// others are not written (their draw buffers are GL_NONE), which saves the bandwidth of up
// to six float targets. Physical targets, not the stages' declared inputs: the linear
// depth that edge detection reads rides in the normals' w, the Gouraud intensity in the
// barycentrics' w, the corner angles in TriangleAngles.
struct GBufferChannels {
  bool normal = true, face_normal = true, bary = true, gouraud = true, theta_min = true, theta_max = true;
  bool depth = true;            // the depth target; the edge filter reads the depth next to the normals
  bool triangle_angles = true;  // TriangleAngles for this frame's camera (the pencil interior)
  // Whether the barycentrics, Gouraud intensity and angles hold their background values off
  // the objects. No stage reads them there (the interior reads only where ids != 0), so a
  // frame leaves them as they were (llvmpipe: 52 bytes a pixel less to write); a dump writes them.
  bool object_only_background = true;
  // Where stages read the other channels: a frame writes their background values only
  // there (filter_rect of the edge filter's reach, common/scene/scene.hpp); a dump, in the whole
  // window (GBufferPass::draw_background).
  PixelRect read_region{0, 0, INT_MAX, INT_MAX};

  // Nothing read: what a frame's readers add to (gpu/core/stage.hpp GpuFrame::read_gbuffer).
  static GBufferChannels none() { return {false, false, false, false, false, false, false, false, false, {}}; }
};

// Uploads a scene's geometry once; render() draws it into targets of any size.
// What the ordinary G-buffer's pass shares with later passes.
inline constexpr Shared<Renderbuffer> kDepthBuffer{"gbuffer.depth_buffer"};  // a sketchy sprite's depth test
inline constexpr Shared<TriangleAngles> kTriangleAngles{"gbuffer.triangle_angles"};

class GBufferPass {
 public:
  // `curvature`: one per object for the corner angles of Lee et al. 2006, §5.3, or none.
  explicit GBufferPass(const Scene& scene, const std::vector<Curvature>& curvature = {});
  void render(const Scene& scene, GBufferTargets& targets, const GBufferChannels& channels = {});
  // The Gouraud intensities again, under `scene`'s lights (the objects the pass was made with).
  void relight(const Scene& scene);
  // The depth buffer of the last render: what later geometry (a depth sprite) is tested against.
  const Renderbuffer& depth_buffer() const { return depth_test_; }
  // The corner angles of the last render that wrote angles or TriangleAngles.
  const TriangleAngles& triangle_angles() const { return triangle_angles_; }
  // Faces that cannot be seen are culled: of a closed, oriented object whose bounding box is
  // wholly beyond the near plane (gpu/scene/gbuffer.cpp hidden_faces). Tests turn it off to
  // compare; culled_objects() counts the objects the last render() culled.
  void set_culling(bool on) { culling_ = on; }
  int culled_objects() const { return culled_objects_; }

 private:
  struct Batch {
    Buffer vertices, triangle_vertices, vertex_curvature, vertex_angles;  // the last three with curvature
    VertexArray layout;
    GLsizei corners = 0;
    GLuint mesh_vertices = 0, first_triangle = 0;  // its first record in triangle_angles_
    GLenum hidden_faces = GL_NONE;                 // GL_BACK, GL_FRONT, or GL_NONE: never culled
    glm::vec3 box_min{0}, box_max{0};              // world space
  };
  void draw_background(const GBufferChannels& channels, const bool wanted[8], float far);
  void compute_corner_angles(const glm::mat4& view_projection, int w, int h, float fov_deg, const InteriorParams& p);
  // The program variant that writes exactly `channels` (compiled on first use).
  const Program& program_for(const GBufferChannels& channels);
  std::vector<Batch> batches_;  // one per object
  bool has_curvature_;
  std::unique_ptr<Program> angles_program_,
      triangle_angles_program_;  // corner_ and triangle_angles.comp, with curvature
  TriangleAngles triangle_angles_;
  Program background_program_;
  ProgramVariants programs_;  // gbuffer.frag per set of channels written
  Framebuffer fbo_;
  VertexArray empty_;  // for the background's full-window triangle
  Renderbuffer depth_test_;
  int depth_test_width_ = 0, depth_test_height_ = 0;
  bool culling_ = true;
  int culled_objects_ = 0;
};

}  // namespace plumbago::gpu

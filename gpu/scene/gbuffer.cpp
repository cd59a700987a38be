#include "gpu/scene/gbuffer.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "common/core/frame.hpp"
#include "common/mesh/mesh_topology.hpp"
#include "common/pencil/edge_detect.hpp"
#include "common/pencil/interior_intensity.hpp"
#include "common/pencil/pencil_interior.hpp"
#include "common/sketchy/sketchy_gbuffer.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

// One vertex of the triangle soup; the layout matches shaders/scene/gbuffer.vert.
struct Corner {
  glm::vec3 position, normal, face_normal, corner;
  float gouraud;
};

// Per mesh vertex, what shaders/scene/corner_angles.comp reads (Lee et al. 2006, §5.3); made only when the
// scene has curvature.
struct VertexCurvature {
  glm::vec4 position, d_min, d_max;  // world space; w unused
};

std::vector<Corner> triangle_soup(const WorldObject& obj) {
  static const glm::vec3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<Corner> soup;
  soup.reserve(obj.triangles.size() * 3);
  for (size_t t = 0; t < obj.triangles.size(); ++t) {
    glm::vec3 fn = face_normal(obj, t);
    for (int k = 0; k < 3; ++k) {
      uint32_t v = obj.triangles[t][k];
      soup.push_back({obj.positions[v], obj.flat ? fn : obj.normals[v], fn, unit[k], obj.gouraud[v]});
    }
  }
  return soup;
}

std::vector<VertexCurvature> vertex_curvature(const WorldObject& obj) {
  std::vector<VertexCurvature> out(obj.positions.size());
  for (size_t v = 0; v < out.size(); ++v)
    out[v] = {glm::vec4(obj.positions[v], 0), glm::vec4(obj.d_min[v], 0), glm::vec4(obj.d_max[v], 0)};
  return out;
}

// The faces that can never be the nearest surface when the object is seen from outside:
// where every edge joins two faces that run along it in opposite directions (no face
// split off, no boundary edge), the surface is closed and oriented, and a ray from outside
// enters it before it leaves, so its first hit faces the camera. Its signed volume says
// whether the triangles turn counter-clockwise seen from outside (GL_BACK faces hidden) or
// clockwise (GL_FRONT); GL_NONE for an open, non-manifold or flat mesh.
GLenum hidden_faces(const Mesh& mesh, const WorldObject& obj) {
  MeshTopology topology = build_topology(mesh);
  bool closed = topology.split_faces == 0 && std::none_of(topology.edges.begin(), topology.edges.end(),
                                                          [](const MeshTopology::Edge& e) { return e.face[1] < 0; });
  if (!closed) return GL_NONE;
  double volume = 0;  // 6x the signed volume, in world space (a mirroring transform flips it)
  for (const glm::uvec3& t : obj.triangles)
    volume += glm::dot(glm::dvec3(obj.positions[t[0]]),
                       glm::cross(glm::dvec3(obj.positions[t[1]]), glm::dvec3(obj.positions[t[2]])));
  return volume > 0 ? GL_BACK : volume < 0 ? GL_FRONT : GL_NONE;
}

// Whether the camera sees the box [lo, hi] whole, from outside: every corner beyond the
// near plane (a camera inside a closed surface has some of it behind itself).
bool beyond_near_plane(const glm::mat4& view, float near, const glm::vec3& lo, const glm::vec3& hi) {
  for (int c = 0; c < 8; ++c) {
    glm::vec3 corner(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    if (-(view * glm::vec4(corner, 1.0f)).z <= near) return false;
  }
  return true;
}

// With the vertex array bound: attribute `index` reads `size` floats at `offset` of the
// vertex buffer bound to `binding`.
void describe_attribute(GLuint index, int size, size_t offset, GLuint binding = 0) {
  glEnableVertexAttribArray(index);
  glVertexAttribFormat(index, size, GL_FLOAT, GL_FALSE, GLuint(offset));
  glVertexAttribBinding(index, binding);
}

GLenum normal_storage(GBufferFormat f) {
  switch (f) {
    case GBufferFormat::RGBA16F:
      return GL_RGBA16F;
    case GBufferFormat::RGBA8:
      return GL_RGBA8_SNORM;
    default:
      return GL_RGBA32F;
  }
}

}  // namespace

GBufferTargets make_gbuffer_targets(int width, int height, GBufferFormat normal_format) {
  GBufferTargets t;
  t.normal = make_texture(width, height, normal_storage(normal_format));
  t.face_normal = make_texture(width, height, normal_storage(normal_format));
  t.depth = make_texture(width, height, GL_R32F);
  t.ids = make_texture(width, height, GL_RG32UI);
  t.bary = make_texture(width, height, GL_RGBA32F);
  t.gouraud = make_texture(width, height, GL_R32F);
  t.theta_min = make_texture(width, height, GL_RGBA32F);
  t.theta_max = make_texture(width, height, GL_RGBA32F);
  return t;
}

GBuffer download_gbuffer(const GBufferTargets& t) {
  GBuffer g;
  g.normal = download_texture(t.normal, 3);
  g.face_normal = download_texture(t.face_normal, 3);
  g.depth = download_texture(t.depth, 1);
  g.ids = download_texture_u32(t.ids, 2);
  g.bary = download_texture(t.bary, 3);
  g.gouraud = download_texture(t.gouraud, 1);
  g.theta_min = download_texture(t.theta_min, 3);
  g.theta_max = download_texture(t.theta_max, 3);
  g.near = t.near;
  g.far = t.far;
  return g;
}

namespace {

// A 3-channel image with a 1-channel one as fourth channel, as gbuffer.frag packs them
// (normals and depth, barycentrics and Gouraud intensity).
Image with_fourth_channel(const Image& xyz, const Image& w) {
  Image out(xyz.width, xyz.height, 4);
  for (size_t i = 0; i < xyz.pixels(); ++i) {
    std::copy_n(&xyz.data[3 * i], 3, &out.data[4 * i]);
    out.data[4 * i + 3] = w.data[i];
  }
  return out;
}

}  // namespace

GBufferTargets upload_gbuffer(const GBuffer& g) {
  GBufferTargets t;
  t.normal = upload_texture(with_fourth_channel(g.normal, g.depth), GL_RGBA32F);
  t.face_normal = upload_texture(with_fourth_channel(g.face_normal, g.depth), GL_RGBA32F);
  t.depth = upload_texture(g.depth, GL_R32F);
  t.ids = make_texture(g.ids.width, g.ids.height, GL_RG32UI);
  write_texture(t.ids, 2, true, g.ids.data.data());
  t.bary = upload_texture(with_fourth_channel(g.bary, g.gouraud), GL_RGBA32F);
  t.gouraud = upload_texture(g.gouraud, GL_R32F);
  t.theta_min =
      upload_texture(g.theta_min.empty() ? Image(g.gouraud.width, g.gouraud.height, 3) : g.theta_min, GL_RGBA32F);
  t.theta_max =
      upload_texture(g.theta_max.empty() ? Image(g.gouraud.width, g.gouraud.height, 3) : g.theta_max, GL_RGBA32F);
  t.near = g.near;
  t.far = g.far;
  return t;
}

GBufferPass::GBufferPass(const Scene& scene, const std::vector<Curvature>& curvature)
    : has_curvature_(!curvature.empty()),
      angles_program_(has_curvature_ ? std::make_unique<Program>(
                                           Program::compute("scene/corner_angles.comp", glsl_params<InteriorParams>()))
                                     : nullptr),
      triangle_angles_program_(
          has_curvature_ ? std::make_unique<Program>(Program::compute("scene/triangle_angles.comp")) : nullptr),
      background_program_("util/fullscreen.vert", "scene/gbuffer_background.frag", "#define FULLSCREEN_Z 1.0\n"),
      programs_("scene/gbuffer.vert", "scene/gbuffer.frag", glsl_params<InteriorParams>(),
                {"WRITE_NORMAL", "WRITE_FACE_NORMAL", "WRITE_BARY", "WRITE_GOURAUD", "WRITE_THETA_MIN",
                 "WRITE_THETA_MAX", "WRITE_DEPTH"}),
      fbo_(make_framebuffer()),
      empty_(make_vertex_array()) {
  std::vector<WorldObject> objects = world_geometry(scene, curvature);
  std::vector<GLuint> first_triangle;
  GLuint triangles = 0;
  for (size_t i = 0; i < objects.size(); ++i) {
    const WorldObject& obj = objects[i];
    std::vector<Corner> soup = triangle_soup(obj);
    Batch b{
        make_buffer(soup.data(), soup.size() * sizeof(Corner)), {}, {}, {}, make_vertex_array(), GLsizei(soup.size())};
    b.hidden_faces = hidden_faces(*scene.objects[i].mesh, obj);
    first_triangle.push_back(b.first_triangle = triangles);
    triangles += GLuint(obj.triangles.size());
    b.box_min = b.box_max = obj.positions.front();
    for (const glm::vec3& p : obj.positions) {
      b.box_min = glm::min(b.box_min, p);
      b.box_max = glm::max(b.box_max, p);
    }
    glBindVertexArray(b.layout.id());
    glBindVertexBuffer(0, b.vertices.id(), 0, sizeof(Corner));
    describe_attribute(0, 3, offsetof(Corner, position));
    describe_attribute(1, 3, offsetof(Corner, normal));
    describe_attribute(2, 3, offsetof(Corner, face_normal));
    describe_attribute(3, 3, offsetof(Corner, corner));
    describe_attribute(4, 1, offsetof(Corner, gouraud));
    if (!obj.d_min.empty()) {
      std::vector<VertexCurvature> curvature = vertex_curvature(obj);
      b.triangle_vertices = make_buffer(obj.triangles.data(), obj.triangles.size() * sizeof(glm::uvec3));
      b.vertex_curvature = make_buffer(curvature.data(), curvature.size() * sizeof(VertexCurvature));
      b.vertex_angles = make_buffer(nullptr, curvature.size() * sizeof(glm::vec2));
      b.mesh_vertices = GLuint(curvature.size());
    }
    glBindVertexArray(0);
    batches_.push_back(std::move(b));
  }
  // Zero until computed: the angles of objects without curvature.
  std::vector<glm::vec4> zero_angles(2 * std::max<size_t>(triangles, 1), glm::vec4(0.0f));
  triangle_angles_.angles = make_buffer(zero_angles.data(), zero_angles.size() * sizeof(glm::vec4));
  if (first_triangle.empty()) first_triangle.push_back(0);
  triangle_angles_.first_triangle = make_buffer(first_triangle.data(), first_triangle.size() * sizeof(GLuint));
}

void GBufferPass::relight(const Scene& scene) {
  std::vector<WorldObject> objects = world_geometry(scene, {});
  for (size_t i = 0; i < objects.size(); ++i) {
    std::vector<Corner> soup = triangle_soup(objects[i]);
    Batch& b = batches_[i];
    b.vertices = make_buffer(soup.data(), soup.size() * sizeof(Corner));  // immutable storage: made anew
    glBindVertexArray(b.layout.id());
    glBindVertexBuffer(0, b.vertices.id(), 0, sizeof(Corner));
  }
  glBindVertexArray(0);
}

const Program& GBufferPass::program_for(const GBufferChannels& c) {
  return programs_.get({c.normal, c.face_normal, c.bary, c.gouraud, c.theta_min, c.theta_max, c.depth});
}

// Every mesh vertex's stroke angles for this camera (corner_angles.comp), then each
// triangle's record of its corners' (triangle_angles.comp), for the draws and the interior.
void GBufferPass::compute_corner_angles(const glm::mat4& view_projection, int w, int h, float fov_deg,
                                        const InteriorParams& p) {
  const Program& program = *angles_program_;
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("view_projection"), 1, GL_FALSE, glm::value_ptr(view_projection));
  glUniform2f(program.uniform("window_size"), float(w), float(h));
  glUniform1f(program.uniform("tan_half_fov"), std::tan(glm::radians(fov_deg) * 0.5f));
  program.set_params(p);
  for (const Batch& b : batches_) {
    if (b.mesh_vertices == 0) continue;
    glUniform1ui(program.uniform("vertex_count"), b.mesh_vertices);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, b.vertex_curvature.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, b.vertex_angles.id());
    dispatch_in_chunks(program, b.mesh_vertices, "first");
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const Program& gather = *triangle_angles_program_;
  glUseProgram(gather.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, triangle_angles_.angles.id());
  for (const Batch& b : batches_) {
    if (b.mesh_vertices == 0) continue;
    GLuint triangles = GLuint(b.corners / 3);
    glUniform1ui(gather.uniform("triangle_count"), triangles);
    glUniform1ui(gather.uniform("first_triangle"), b.first_triangle);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, b.vertex_angles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, b.triangle_vertices.id());
    dispatch_in_chunks(gather, triangles, "first");
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

TriangleAngles triangle_angles_from(const GBuffer& g) {
  std::vector<GLuint> triangles;  // per object: 1 + its largest triangle index seen
  for (size_t i = 0; i < g.ids.pixels(); ++i) {
    uint32_t object = g.ids.data[2 * i], triangle = g.ids.data[2 * i + 1];
    if (object == 0) continue;
    if (triangles.size() < object) triangles.resize(object, 0);
    triangles[object - 1] = std::max(triangles[object - 1], triangle + 1);
  }
  std::vector<GLuint> first(std::max<size_t>(triangles.size(), 1), 0);
  for (size_t o = 1; o < triangles.size(); ++o) first[o] = first[o - 1] + triangles[o - 1];
  size_t records = triangles.empty() ? 1 : first.back() + triangles.back();
  std::vector<glm::vec4> angles(2 * std::max<size_t>(records, 1), glm::vec4(0.0f));
  for (int y = 0; y < g.ids.height && !g.theta_min.empty(); ++y)
    for (int x = 0; x < g.ids.width; ++x) {
      uint32_t object = g.ids.at(x, y, 0);
      if (object == 0) continue;
      size_t t = first[object - 1] + g.ids.at(x, y, 1);
      for (int k = 0; k < 3; ++k) {
        angles[2 * t][k] = g.theta_min.at(x, y, k);
        angles[2 * t + 1][k] = g.theta_max.empty() ? 0.0f : g.theta_max.at(x, y, k);
      }
    }
  return {make_buffer(angles.data(), angles.size() * sizeof(glm::vec4)),
          make_buffer(first.data(), first.size() * sizeof(GLuint))};
}

void GBufferPass::render(const Scene& scene, GBufferTargets& t, const GBufferChannels& channels) {
  int w = t.width(), h = t.height();
  if (w != depth_test_width_ || h != depth_test_height_) {
    depth_test_ = make_renderbuffer(w, h, GL_DEPTH_COMPONENT32F);
    depth_test_width_ = w;
    depth_test_height_ = h;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  const Texture* color[] = {&t.normal, &t.face_normal, &t.depth,     &t.ids,
                            &t.bary,   &t.gouraud,     &t.theta_min, &t.theta_max};
  const bool wanted[] = {channels.normal, channels.face_normal, channels.depth,     true,
                         channels.bary,   channels.gouraud,     channels.theta_min, channels.theta_max};  // ids: always
  GLenum draw[8];
  for (int i = 0; i < 8; ++i) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, color[i]->id(), 0);
    draw[i] = wanted[i] ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_test_.id());
  glDrawBuffers(8, draw);

  const Camera& cam = scene.camera;
  glm::mat4 view = cam.view(), projection = cam.projection(float(w) / float(h));
  t.near = cam.near;
  t.far = cam.far;
  const float one = 1;
  glClearBufferfv(GL_DEPTH, 0, &one);  // whole: a sketchy depth sprite is tested against it

  if (has_curvature_ && (channels.theta_min || channels.theta_max || channels.triangle_angles))
    compute_corner_angles(projection * view, w, h, cam.fov_deg, scene.params.get<InteriorParams>());
  glViewport(0, 0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const Program& program = program_for(channels);
  glUseProgram(program.id());
  glUniformMatrix4fv(program.uniform("view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(program.uniform("projection"), 1, GL_FALSE, glm::value_ptr(projection));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, triangle_angles_.angles.id());
  culled_objects_ = 0;
  for (size_t i = 0; i < batches_.size(); ++i) {
    const Batch& b = batches_[i];
    // Culling the faces that cannot be seen leaves the image as it was, and halves the
    // triangles llvmpipe rasterizes (fandisk, every effect: -4.5 ms of 14 a frame).
    bool cull = culling_ && b.hidden_faces != GL_NONE && beyond_near_plane(view, cam.near, b.box_min, b.box_max);
    if (cull) {
      glEnable(GL_CULL_FACE);
      glCullFace(b.hidden_faces);
      ++culled_objects_;
    } else {
      glDisable(GL_CULL_FACE);
    }
    glUniform1ui(program.uniform("object_id"), GLuint(i + 1));
    glUniform1ui(program.uniform("first_triangle"), b.first_triangle);
    glBindVertexArray(b.layout.id());
    glDrawArrays(GL_TRIANGLES, 0, b.corners);
  }
  glDisable(GL_CULL_FACE);
  draw_background(channels, wanted, cam.far);
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The background values inside the read region, where no object is: a full-window triangle
// at the far plane (gbuffer_background.frag) passes GL_LEQUAL exactly where the depth buffer
// still holds its clear value 1, since the objects, drawn with GL_LESS, never write 1. One
// draw for every channel, skipping the pixels objects cover, where a clear inside a scissor
// costs llvmpipe a quad draw per channel over the whole region (fandisk: -2 ms a frame).
void GBufferPass::draw_background(const GBufferChannels& channels, const bool wanted[8], float far) {
  const bool object_only[] = {false, false, false, false, true, true, true, true};  // see GBufferChannels
  GLenum draw[8];
  for (int i = 0; i < 8; ++i)
    draw[i] =
        wanted[i] && (channels.object_only_background || !object_only[i]) ? GL_COLOR_ATTACHMENT0 + GLenum(i) : GL_NONE;
  glDrawBuffers(8, draw);
  const PixelRect& r = channels.read_region;
  int w = depth_test_width_, h = depth_test_height_, x0 = std::clamp(r.x0, 0, w), y0 = std::clamp(r.y0, 0, h);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, y0, std::clamp(r.x1, x0, w) - x0, std::clamp(r.y1, y0, h) - y0);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glUseProgram(background_program_.id());
  glUniform1f(background_program_.uniform("far_plane"), far);
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_SCISSOR_TEST);
}

namespace {

// A G-buffer stage of a frame: "gbuffer" draws the ordinary objects (with the corner angles
// where the frame made curvature), "sketchy_gbuffer" the sketchy ones. It shares its
// targets under the stage's name, and the ordinary one its depth buffer (what a sketchy
// depth sprite is tested against) and its corner angles.
class GBufferStagePass : public GpuPass {
 public:
  GBufferStagePass(GpuFrame& f, GBufferSlot stage, const Scene& objects, const std::vector<Curvature>& curvature)
      : stage_(stage),
        objects_(objects),
        pass_(objects, curvature),
        targets_(make_gbuffer_targets(f.scene.width, f.scene.height, f.params<GBufferParams>().normal_format)) {
    f.put(stage_, targets_);
    if (std::string(stage_.name) != kGBuffer.name) return;
    f.put(kDepthBuffer, pass_.depth_buffer());
    f.put(kTriangleAngles, pass_.triangle_angles());
  }
  void run(GpuFrame& f) override { pass_.render(f.scene, targets_, f.gbuffer_channels(stage_.name)); }
  void moved(GpuFrame&, bool lights_moved) override {
    if (lights_moved) pass_.relight(objects_);
  }
  void dump(GpuFrame&, const std::vector<std::string>&, std::map<std::string, Image>& out) override {
    add_gbuffer_buffers(download_gbuffer(targets_), out, stage_.name);
  }

 private:
  GBufferSlot stage_;
  const Scene& objects_;  // the frame's ordinary or sketchy objects, which move with it
  GBufferPass pass_;
  GBufferTargets targets_;
};

}  // namespace

PLUMBAGO_GPU_PASS(gbuffer, {{"gbuffer"},
                            {},
                            [](GpuFrame& f) -> std::unique_ptr<GpuPass> {
                              const std::vector<Curvature>* curvature = f.get(maybe(kCurvature));
                              return std::make_unique<GBufferStagePass>(
                                  f, kGBuffer, f.ordinary, curvature ? *curvature : std::vector<Curvature>{});
                            },
                            Probe::Raster});
PLUMBAGO_GPU_PASS(sketchy_gbuffer, {{"sketchy_gbuffer"},
                                    {},
                                    [](GpuFrame& f) -> std::unique_ptr<GpuPass> {
                                      return std::make_unique<GBufferStagePass>(f, kSketchyGBuffer, f.sketchy,
                                                                                std::vector<Curvature>{});
                                    },
                                    Probe::Raster});

}  // namespace plumbago::gpu

// The ID reference image on the GPU (Kalnins et al. 2002, §4.6), the twin of reference/strokes/id_image.cpp:
// the rules of common/strokes/id_image.hpp, depth-tested GL_GREATER on z = near / d, written as
// the fragment's depth. The faces are the G-buffer's, copied in one full-window pass
// (shaders/strokes/id_gbuffer.frag); the sketchy objects' are pulled from their meshes,
// uploaded once (shaders/strokes/id_faces.vert): no CPU loop over faces per frame. The
// creases and borders (gpu/strokes/crease_rows.hpp) and the silhouettes are made window paths
// on the GPU, in double: the silhouettes are the GPU's own (silhouette_paths), their points
// placed and projected on the GPU (gpu/strokes/silhouette_points.hpp), then cut and measured
// there (gpu/strokes/silhouette_rows.hpp); the decals and hatches too, from their surface
// points, uploaded once (gpu/strokes/decal_rows.hpp). All are written in the frame's path
// table, and the GPU writes its header (gpu/strokes/row_counts.hpp TableRows). A frame that
// sizes the buffers (the first, and any that keeps its lines whole: GpuFrame::whole_lines)
// reads back the GPU's counts and bounds (RowCounts); the others read nothing back. A frame
// that keeps its lines whole also reads the silhouettes back and makes the same window paths
// on the CPU. From the table the GPU expands the lines' quads (gpu/strokes/id_lines.hpp) and
// the visibility steps sample.
// Every draw writes both key images (under strokes.crease_under_silhouettes) but the
// silhouettes', which leave crease_ids as it stood.
#include "common/strokes/id_image.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/strokes/mobile_hatching.hpp"
#include "common/strokes/silhouette_paths.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/scene/mesh_buffers.hpp"
#include "gpu/strokes/crease_rows.hpp"
#include "gpu/strokes/decal.hpp"
#include "gpu/strokes/decal_rows.hpp"
#include "gpu/strokes/id_lines.hpp"
#include "gpu/strokes/row_counts.hpp"
#include "gpu/strokes/silhouette_points.hpp"
#include "gpu/strokes/silhouette_rows.hpp"

namespace plumbago::gpu {

namespace {

class IdImagePass : public GpuPass {
 public:
  explicit IdImagePass(GpuFrame& f)
      : gbuffer_program_("util/fullscreen.vert", "strokes/id_gbuffer.frag"),
        faces_program_("strokes/id_faces.vert", "strokes/id_image.frag", "#define FACES\n"),
        fbo_(make_framebuffer()),
        empty_(make_vertex_array()),
        depth_(make_renderbuffer(f.scene.width, f.scene.height, GL_DEPTH_COMPONENT32F)),
        silhouettes_(f.scene, f.get(kLineMeshes), stroke_meshes(f)),
        creases_(f.scene, f.get(kLineMeshes), stroke_meshes(f)),
        records_(first_faces(f.scene).back()),
        rows_(records_),
        // The decals' surface points, projected once for the renderer's frames (Kalnins et al.
        // 2002, §3).
        decals_(has_decals(f.scene) ? project_decals_through_gbuffer(f.scene) : DecalSurface{}),
        mobile_(f.scene, decals_),
        decal_rows_(f.scene, decals_, mobile_),
        styles_(3 + decals_.size()),
        counts_(make_buffer(nullptr, RowCounts::bytes(styles_))) {
    first_key_ = first_faces(f.scene);
    for (uint32_t o = 0; o < f.scene.objects.size(); ++o)
      if (f.scene.objects[o].style == Style::Sketchy) sketchy_.push_back(upload_mesh(f.scene, o));
    std::vector<uint32_t> first = gbuffer_first_keys(f.scene);
    first.push_back(0);  // never empty
    gbuffer_first_keys_ = make_buffer(first.data(), first.size() * sizeof(uint32_t));
    f.read_region(kGBuffer, {0, 0, f.scene.width, f.scene.height});
  }

  void run(GpuFrame& f) override {
    auto p = f.params<StrokesParams>();
    const LineMeshes& meshes = f.get(kLineMeshes);
    const Texture& paths = f.get(kSilhouettePaths);
    silhouettes_.place(f.scene, meshes, paths, f.get(kSilhouetteCrossings), p.silhouette_normalized);
    const bool whole = f.whole_lines || f.dump;  // a dump reads runs back on the lines
    std::vector<ChainPath> read;                 // none unless the lines stay whole
    if (whole) read = silhouettes_.read(f.scene, meshes, paths);
    std::optional<SurfaceStrokes> strokes;  // the decals and hatches drawn this frame
    if (has_decals(f.scene)) strokes = surface_strokes(f.scene, decals_, &mobile_, whole);  // copies moved: decal_rows_
    WindowLines lines =
        window_lines(f.scene, p, LineObjects::Strokes, &meshes, strokes ? &*strokes : nullptr, &read, whole);
    const size_t silhouette_points = silhouette_point_rows(records_),
                 decal_points = strokes ? DecalRows::points(*strokes) : 0;
    const size_t gpu_paths = creases_.points() + records_ + decal_points,
                 gpu_points = creases_.points() + silhouette_points + decal_points;
    table_.reserve(gpu_paths, gpu_points);
    const RowFrame frame{f.scene.width, f.scene.height, f.scene.camera.near, p.vis_step_px};
    clear_buffer(counts_);
    creases_(f.scene, frame, 0, counts_, table_);
    rows_(paths, silhouettes_, frame, uint32_t(creases_.points()), counts_, table_);
    if (strokes)
      decal_rows_(f.scene, *strokes, frame, uint32_t(creases_.points() + silhouette_points), counts_, table_);
    header_(counts_, table_);
    table_.sized = whole || !sized_;
    if (table_.sized) size_by_counts(whole ? &lines : nullptr);
    f.put(kWindowLines, std::move(lines));
    f.put(kPathTable, table_);
    Texture& target = f.put(kIds);
    const Texture& crease_target = crease_ids(f, p.crease_under_silhouettes);
    lines_.prepare(table_, p, target.width, target.height, f.scene.camera.near);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
    const bool both_images = p.crease_under_silhouettes;
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, both_images ? crease_target.id() : 0,
                           0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1}, keys_only[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
    const GLuint none[4] = {0, 0, 0, 0};
    const float far = 0;
    glDrawBuffers(2, both_images ? both : keys_only);
    glClearBufferuiv(GL_COLOR, 0, none);
    if (both_images) glClearBufferuiv(GL_COLOR, 1, none);
    glClearBufferfv(GL_DEPTH, 0, &far);
    glViewport(0, 0, target.width, target.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glBindVertexArray(empty_.id());
    draw_gbuffer_faces(f);
    draw_sketchy_faces(f);
    lines_.draw(table_, IdLineRule::CreasesAndBorders);
    glDrawBuffers(2, keys_only);  // crease_ids keeps what stands before the silhouettes
    lines_.draw(table_, IdLineRule::Silhouettes);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // A new camera makes other paths: the next frame sizes the buffers by its counts again.
  // The decals stay where their strokes' own cameras placed them.
  void moved(GpuFrame&, bool) override { sized_ = false; }

 private:
  // The silhouette segments' meshes, or (the segments computed elsewhere: parity) its own.
  const StrokeMeshes& stroke_meshes(GpuFrame& f) {
    if (const StrokeMeshes* shared = f.get(maybe(kStrokeMeshes))) return *shared;
    return own_meshes_ ? *own_meshes_ : own_meshes_.emplace(f.scene, f.get(kLineMeshes));
  }

  // Reads back what the GPU counted: its paths' bounds, by which the steps after size their
  // buffers (a frame that keeps its lines whole, or the first), checked against `lines` where
  // they stay whole. The frames after go by those buffers and read nothing back.
  void size_by_counts(const WindowLines* lines) {
    const RowCounts counts = RowCounts::read(counts_, styles_);
    if (silhouette_base(records_, counts.crease_rows) != counts.silhouette_base)  // refuses keys past 32 bits
      throw std::logic_error("id_image: the GPU's first silhouette key is not the CPU's");
    counts.add_bounds_to(table_);
    sized_ = true;
    const size_t made = size_t(counts.crease_rows) + counts.silhouette_rows + counts.decal_rows;
    if (lines && made != lines->paths.size())
      throw std::logic_error("id_image: the GPU made " + std::to_string(made) + " window paths, the CPU " +
                             std::to_string(lines->paths.size()));
  }

  // id_image.crease_ids: the window's size under strokes.crease_under_silhouettes, else 1 x 1
  // of 0 (nothing tests it), made where the frame holds the other size.
  static const Texture& crease_ids(GpuFrame& f, bool wanted) {
    const int width = wanted ? f.scene.width : 1, height = wanted ? f.scene.height : 1;
    const Texture* held = f.get(maybe(kCreaseIds));
    if (!held || held->width != width || held->height != height) {
      Texture made = make_texture(width, height, texture_format(find_output(kCreaseIds.name)));
      const GLuint zero[4] = {0, 0, 0, 0};
      glClearTexImage(made.id(), 0, GL_RG_INTEGER, GL_UNSIGNED_INT, zero);
      f.put(kCreaseIds, std::move(made));
    }
    return f.get(kCreaseIds);
  }

  // Rule 1: the G-buffer's faces,
  void draw_gbuffer_faces(const GpuFrame& f) {
    const GBufferTargets& g = f.get(kGBuffer);
    glUseProgram(gbuffer_program_.id());
    glProgramUniform1f(gbuffer_program_.id(), gbuffer_program_.uniform("near"), f.scene.camera.near);
    bind_textures(gbuffer_program_, {{"ids", &g.ids}, {"depth", &g.depth}});
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, gbuffer_first_keys_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  // then the sketchy objects' faces, in the order of their keys.
  void draw_sketchy_faces(const GpuFrame& f) {
    if (sketchy_.empty()) return;
    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_DEPTH_CLAMP);
    glUseProgram(faces_program_.id());
    glProgramUniform1f(faces_program_.id(), faces_program_.uniform("near"), f.scene.camera.near);
    for (const MeshBuffers& m : sketchy_) {
      if (m.faces == 0) continue;
      object_uniforms(faces_program_, f.scene, m.object);
      glProgramUniform1ui(faces_program_.id(), faces_program_.uniform("first_key"), first_key_[m.object] + 1);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m.positions.id());
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.corners.id());
      glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * m.faces));
    }
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_CLIP_DISTANCE0);
  }

  Program gbuffer_program_, faces_program_;
  Framebuffer fbo_;
  VertexArray empty_;
  Renderbuffer depth_;
  std::optional<StrokeMeshes> own_meshes_;
  SilhouettePoints silhouettes_;
  CreaseRows creases_;
  size_t records_;  // face records: the most silhouette paths
  SilhouetteRows rows_;
  DecalSurface decals_;
  MobileHatching mobile_;  // the mobile hatching groups' travel (Kalnins et al. 2002, §6.3)
  DecalRows decal_rows_;
  size_t styles_;                    // line styles: 3 and one per decal (PathTable::style_of)
  Buffer counts_;                    // RowCounts
  TableRows header_;                 // the table's header
  bool sized_ = false;               // whether a frame has sized the buffers (size_by_counts)
  IdLines lines_;                    // rules 2 and 3
  UploadedPaths table_;              // this frame's, kept until the next (its buffers across frames)
  std::vector<uint32_t> first_key_;  // per object, its first face key less one
  std::vector<MeshBuffers> sketchy_;
  Buffer gbuffer_first_keys_;  // gbuffer_first_keys
};

}  // namespace

PLUMBAGO_GPU_PASS(id_image, {{"id_image"}, {}, make_pass<IdImagePass>, Probe::Raster});

}  // namespace plumbago::gpu

// Silhouette paths on the GPU (Kalnins et al. 2002, §4.5), the twin of
// reference/strokes/silhouette_paths.cpp: the paths counted per tile of records, the tiles'
// sums scanned in one workgroup, then each path and each point written where the prefix
// sums place it (shaders/strokes/silhouette_paths.comp). Nothing is read back here.
#include "common/strokes/silhouette_paths.hpp"

#include <algorithm>

#include "common/strokes/strokes.hpp"
#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

namespace {

constexpr uint32_t kTile = 4096;  // records per workgroup of the tile steps (16 per invocation)

Program step(const char* name) {
  return Program::compute("strokes/silhouette_paths.comp", table_prelude() + "#define " + name + "\n");
}

class SilhouettePathsPass : public GpuPass {
 public:
  explicit SilhouettePathsPass(GpuFrame& f)
      : count_(step("STEP_COUNT")),
        tiles_(step("STEP_TILES")),
        paths_(step("STEP_PATHS")),
        points_(step("STEP_POINTS")),
        records_(first_faces(f.scene).back()),
        tile_count_((records_ + kTile - 1) / kTile),
        tile_sums_(make_buffer(nullptr, std::max<size_t>(tile_count_, 1) * sizeof(glm::uvec2))),
        first_point_(make_buffer(nullptr, std::max<size_t>(records_, 1) * sizeof(uint32_t))) {}

  void run(GpuFrame& f) override {
    const Texture* tables[] = {&table_target(f, silhouette_path_rows(records_), kSilhouettePaths),
                               &table_target(f, silhouette_point_rows(records_), kSilhouettePoints),
                               &table_target(f, silhouette_point_rows(records_), kSilhouetteCrossings)};
    // The frame reads the rows within the counts only; a dump shows the rest as 0.
    const float zero[4] = {0, 0, 0, 0};
    for (GLuint unit = 0; unit < 3; ++unit) {
      if (f.dump) glClearTexImage(tables[unit]->id(), 0, GL_RGBA, GL_FLOAT, zero);
      glBindImageTexture(unit, tables[unit]->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, tables[unit]->internal_format);
    }
    bind(f);
    over_tiles(count_);
    glUseProgram(tiles_.id());
    glDispatchCompute(1, 1, 1);
    barrier();
    over_tiles(paths_);
    dispatch_in_chunks(points_, records_, "first_record");
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }

 private:
  void bind(GpuFrame& f) {
    for (const Program* p : {&count_, &tiles_, &paths_, &points_}) {
      bind_textures(*p, {{"chains", &f.get(kChains)},
                         {"arcs", &f.get(kChainArcs)},
                         {"facing", &f.get(kSegmentFacing)},
                         {"slots", &f.get(kSegmentSlots)},
                         {"ends", &f.get(kSegmentEnds)}});
      glProgramUniform1ui(p->id(), p->uniform("records"), records_);
      glProgramUniform1ui(p->id(), p->uniform("tiles"), tile_count_);
      glProgramUniform1i(p->id(), p->uniform("keep_back_facing"), f.params<StrokesParams>().keep_back_facing);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, tile_sums_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, first_point_.id());
  }

  void over_tiles(const Program& p) {
    if (tile_count_ == 0) return;
    glUseProgram(p.id());
    glDispatchCompute(tile_count_, 1, 1);
    barrier();
  }

  static void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT); }

  Program count_, tiles_, paths_, points_;
  uint32_t records_, tile_count_;
  Buffer tile_sums_, first_point_;
};

}  // namespace

PLUMBAGO_GPU_PASS(silhouette_paths, {{"silhouette_paths"}, {}, make_pass<SilhouettePathsPass>, Probe::Compute});

}  // namespace plumbago::gpu

// Visibility of stroke samples on the GPU (Kalnins et al. 2002, §4.6), the twin of reference/strokes/visibility.cpp:
// a compute shader tests each batch of samples against the ID image where it lies, and
// only the flags come back (Kalnins et al. read the whole ID image back every frame).
#include "gpu/strokes/visibility.hpp"

#include "gpu/core/stage.hpp"

namespace plumbago::gpu {

SampleTest::SampleTest() : program_(Program::compute("strokes/visibility.comp")) {}

std::vector<uint8_t> SampleTest::operator()(const Texture& ids, const std::vector<VisibilitySample>& batch) {
  Buffer samples = make_buffer(batch.data(), batch.size() * sizeof(VisibilitySample));
  Buffer flags = make_buffer(nullptr, batch.size() * sizeof(uint32_t));
  glUseProgram(program_.id());
  glProgramUniform1ui(program_.id(), program_.uniform("sample_count"), GLuint(batch.size()));
  bind_textures(program_, {{"ids", &ids}});
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, samples.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, flags.id());
  dispatch_in_chunks(program_, batch.size(), "first_sample");
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<uint32_t> read(batch.size());
  read_buffer(flags, read.data(), read.size() * sizeof(uint32_t));
  return std::vector<uint8_t>(read.begin(), read.end());
}

namespace {

class VisibilityPass : public GpuPass {
 public:
  explicit VisibilityPass(GpuFrame&) {}

  void run(GpuFrame& f) override {
    const Texture& ids = f.get(kIds);
    auto test = [&](const std::vector<VisibilitySample>& batch) { return test_(ids, batch); };
    Visibility v = visible_runs(f.get(kWindowLines), f.params<StrokesParams>(), test);
    if (f.dump) f.put(kFlags, upload_texture(flags_image(v.flags), GL_RGBA8));
    f.put(kVisibleRuns, std::move(v));
  }

  void dump(GpuFrame& f, const std::vector<std::string>&, std::map<std::string, Image>& out) override {
    out[kFlags.name] = download_texture(f.get(kFlags), 1);
  }

 private:
  SampleTest test_;
};

}  // namespace

PLUMBAGO_GPU_PASS(visibility, {{"visibility"}, {}, make_pass<VisibilityPass>, Probe::Compute});

}  // namespace plumbago::gpu

#include "gpu/core/limits.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>

#include "common/core/frame.hpp"
#include "common/scene/gbuffer.hpp"
#include "gpu/gl/context.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/gl/timer.hpp"

namespace plumbago::gpu {

namespace {

// The median GPU time of `repeats` runs of `pass` (GL timestamps; wall clock on OSMesa).
// Each run ends with glFinish inside its span: llvmpipe bins the draws into one target and
// would otherwise run every repeat at the last span.
double median_ms(int repeats, const std::function<void()>& pass) {
  PassTimer timer;
  for (int i = 0; i < repeats; ++i) {
    timer.begin("probe");
    pass();
    glFinish();
    timer.end();
  }
  std::vector<double> ms;
  for (const PassTime& t : timer.results()) ms.push_back(t.ms);
  return median(ms);
}

// The scene's triangles in clip space, three vec4 a triangle.
std::vector<glm::vec4> clip_triangles(const Scene& scene) {
  glm::mat4 clip = scene.camera.projection(float(scene.width) / float(scene.height)) * scene.camera.view();
  std::vector<glm::vec4> out;
  for (const WorldObject& o : world_geometry(scene))
    for (const glm::uvec3& t : o.triangles)
      for (int k = 0; k < 3; ++k) out.push_back(clip * glm::vec4(o.positions[t[k]], 1.0f));
  return out;
}

double raster_ms(const Scene& scene, int repeats) {
  std::vector<glm::vec4> clip = clip_triangles(scene);
  Buffer positions = make_buffer(clip.data(), clip.size() * sizeof(glm::vec4));
  Texture target = make_texture(scene.width, scene.height, GL_R32UI);
  Renderbuffer depth = make_renderbuffer(scene.width, scene.height, GL_DEPTH_COMPONENT32F);
  Framebuffer fbo = make_framebuffer();
  VertexArray empty = make_vertex_array();
  Program program("util/probe_raster.vert", "util/probe_raster.frag");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  glViewport(0, 0, scene.width, scene.height);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, positions.id());
  glBindVertexArray(empty.id());
  double ms = median_ms(repeats, [&] {
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, zero);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(clip.size()));
  });
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return ms;
}

double fragment_ms(const Scene& scene, const Texture& source, bool fetch, int repeats) {
  Program program("util/fullscreen.vert", "util/probe.frag", fetch ? "#define FETCH3X3\n" : "");
  Texture target = make_texture(scene.width, scene.height, GL_R32F);
  FullscreenPass pass;
  if (!fetch) return median_ms(repeats, [&] { pass.draw(program, {}, target); });
  return median_ms(repeats, [&] { pass.draw(program, {{"source", &source}}, target); });
}

double compute_ms(const Scene& scene, const Texture& source, bool fetch, int repeats) {
  Program program = Program::compute("util/probe.comp", fetch ? "#define FETCH3X3\n" : "");
  Texture target = make_texture(scene.width, scene.height, GL_R32F);
  glUseProgram(program.id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  if (fetch) bind_textures(program, {{"source", &source}});
  return median_ms(repeats, [&] {
    glDispatchCompute(GLuint((scene.width + 7) / 8), GLuint((scene.height + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  });
}

// Wall clock: a readback waits for the GPU and copies on the CPU.
double readback_ms(const Scene& scene, int repeats) {
  Texture target = make_texture(scene.width, scene.height, GL_RGBA8);
  std::vector<uint8_t> pixels(size_t(scene.width) * size_t(scene.height) * 4);
  const uint8_t gray[4] = {128, 128, 128, 255};
  glClearTexImage(target.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, gray);  // storage really made, as a frame's is
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    glFinish();
    Stopwatch watch;
    glBindTexture(GL_TEXTURE_2D, target.id());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    ms.push_back(watch.ms());
  }
  return median(ms);
}

}  // namespace

const char* probe_name(Probe probe) {
  switch (probe) {
    case Probe::Fullscreen:
      return "fullscreen";
    case Probe::Fetch3x3:
      return "fetch3x3";
    case Probe::Compute:
      return "compute";
    case Probe::Compute3x3:
      return "compute3x3";
    case Probe::Raster:
      return "raster";
    case Probe::Readback:
      break;
  }
  return "readback";
}

double measure_probe(Probe probe, const Scene& scene, int repeats) {
  Texture source = make_texture(scene.width, scene.height, GL_R32F);
  double ms = 0;
  switch (probe) {
    case Probe::Fullscreen:
    case Probe::Fetch3x3:
      ms = fragment_ms(scene, source, probe == Probe::Fetch3x3, repeats);
      break;
    case Probe::Compute:
    case Probe::Compute3x3:
      ms = compute_ms(scene, source, probe == Probe::Compute3x3, repeats);
      break;
    case Probe::Raster:
      ms = raster_ms(scene, repeats);
      break;
    case Probe::Readback:
      ms = readback_ms(scene, repeats);
      break;
  }
  Context::get().check_errors(std::string("the ") + probe_name(probe) + " probe");
  return ms;
}

std::vector<ProbeTime> measure_limits(const Scene& scene, int repeats) {
  std::vector<ProbeTime> out;
  for (Probe p : kProbes) out.push_back({p, measure_probe(p, scene, repeats)});
  return out;
}

}  // namespace plumbago::gpu

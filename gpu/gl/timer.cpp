#include "gpu/gl/timer.hpp"

namespace plumbago::gpu {

#if PLUMBAGO_GL_OSMESA

void PassTimer::begin(const std::string& pass) {
  glFinish();
  spans_.push_back({pass, Query(), Query(), Stopwatch()});
}

void PassTimer::end() {
  glFinish();
  spans_.back().wall_ms = spans_.back().wall.ms();
}

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> out;
  for (const Span& s : spans_) out.push_back({s.pass, s.wall_ms});
  spans_.clear();
  return out;
}

#else

namespace {
GlName<detail::delete_query> timestamp() {
  GLuint id = 0;
  glGenQueries(1, &id);
  glQueryCounter(id, GL_TIMESTAMP);
  return GlName<detail::delete_query>(id);
}
}  // namespace

void PassTimer::begin(const std::string& pass) { spans_.push_back({pass, timestamp(), Query(), Stopwatch()}); }

void PassTimer::end() { spans_.back().stop = timestamp(); }

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> out;
  for (const Span& s : spans_) {
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(s.start.id(), GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(s.stop.id(), GL_QUERY_RESULT, &t1);
    out.push_back({s.pass, double(t1 - t0) * 1e-6});
  }
  spans_.clear();
  return out;
}

#endif

}  // namespace plumbago::gpu

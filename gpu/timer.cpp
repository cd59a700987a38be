#include "gpu/timer.hpp"

namespace plumbago::gpu {

PassTimer::Query PassTimer::timestamp() {
  GLuint id = 0;
  glCreateQueries(GL_TIMESTAMP, 1, &id);
  glQueryCounter(id, GL_TIMESTAMP);
  return Query(id);
}

void PassTimer::begin(const std::string& pass) { spans_.push_back({pass, timestamp(), Query()}); }

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

}  // namespace plumbago::gpu

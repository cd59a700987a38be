#include "gpu/timer.hpp"

namespace plumbago::gpu {

void PassTimer::begin(const std::string& pass) {
  GLuint id = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &id);
  queries_.push_back({pass, GlName<detail::delete_query>(id)});
  glBeginQuery(GL_TIME_ELAPSED, id);
}

void PassTimer::end() { glEndQuery(GL_TIME_ELAPSED); }

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> out;
  for (const Query& q : queries_) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(q.name.id(), GL_QUERY_RESULT, &ns);
    out.push_back({q.pass, double(ns) * 1e-6});
  }
  queries_.clear();
  return out;
}

}  // namespace plumbago::gpu

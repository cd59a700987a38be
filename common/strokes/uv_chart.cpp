// A mesh's (u, v) chart as a point-location table: see common/strokes/uv_chart.hpp.
#include "common/strokes/uv_chart.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

UvChart::UvChart(const Mesh& mesh, std::vector<glm::vec2> uvs) : mesh_(mesh), uvs_(std::move(uvs)) {
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3 && charted(f); ++k) lo_ = glm::min(lo_, corner(f, k)), hi_ = glm::max(hi_, corner(f, k));
  cells_ = std::clamp(int(std::sqrt(double(mesh.triangles.size()) / 2)), 1, 1024);
  // Each charted face in the cells its box meets, in face order: counted, then placed.
  auto each_cell = [&](uint32_t f, auto&& visit) {
    glm::dvec2 a(INFINITY), b(-INFINITY);
    for (int k = 0; k < 3; ++k) a = glm::min(a, corner(f, k)), b = glm::max(b, corner(f, k));
    const glm::ivec2 c0 = cell(a), c1 = cell(b);
    for (int j = c0.y; j <= c1.y; ++j)
      for (int i = c0.x; i <= c1.x; ++i) visit(size_t(j) * size_t(cells_) + size_t(i));
  };
  starts_.assign(size_t(cells_) * size_t(cells_) + 1, 0);
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    if (charted(f)) each_cell(f, [&](size_t c) { ++starts_[c + 1]; });
  for (size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
  faces_.resize(starts_.back());
  std::vector<uint32_t> next(starts_.begin(), starts_.end() - 1);
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    if (charted(f)) each_cell(f, [&](size_t c) { faces_[next[c]++] = f; });
  const std::optional<Hit> first = locate({lo_.x, (lo_.y + hi_.y) / 2}),
                           next_turn = locate({lo_.x + 1, (lo_.y + hi_.y) / 2});
  periodic_ = first && next_turn &&
              glm::distance(position(*first), position(*next_turn)) <= 1e-5 * double(mesh.bbox_diagonal());
}

std::optional<UvChart::Hit> UvChart::locate(glm::dvec2 uv) const {
  if (periodic_) uv.x = lo_.x + (uv.x - lo_.x - std::floor(uv.x - lo_.x));
  std::optional<Hit> hit = locate_in_chart(uv);
  if (!hit && periodic_) hit = locate_in_chart({uv.x + 1, uv.y});
  return hit;
}

glm::dvec3 UvChart::position(const Hit& h) const {
  return interpolate(h, [&](uint32_t v) { return mesh_.positions[v]; });
}

glm::dvec3 UvChart::normal(const Hit& h) const {
  return interpolate(h, [&](uint32_t v) { return mesh_.normals[v]; });
}

glm::dvec2 UvChart::uv(uint32_t face, const glm::dvec3& bary) const {
  return bary.x * corner(face, 0) + bary.y * corner(face, 1) + bary.z * corner(face, 2);
}

bool UvChart::charted(uint32_t f) const {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(corner(f, k).x) || !std::isfinite(corner(f, k).y)) return false;
  return true;
}

glm::ivec2 UvChart::cell(glm::dvec2 uv) const {
  glm::dvec2 t = (uv - lo_) / glm::max(hi_ - lo_, glm::dvec2(1e-300)) * double(cells_);
  return glm::clamp(glm::ivec2(glm::floor(t)), glm::ivec2(0), glm::ivec2(cells_ - 1));
}

// The barycentric coordinates of uv in each face of its cell; the deepest wins (the last of
// equals).
std::optional<UvChart::Hit> UvChart::locate_in_chart(glm::dvec2 uv) const {
  if (uv.x < lo_.x || uv.y < lo_.y || uv.x > hi_.x || uv.y > hi_.y) return std::nullopt;
  const glm::ivec2 c = cell(uv);
  const size_t bucket = size_t(c.y) * size_t(cells_) + size_t(c.x);
  std::optional<Hit> best;
  double deepest = -1e-9;
  for (uint32_t i = starts_[bucket]; i < starts_[bucket + 1]; ++i) {
    const uint32_t f = faces_[i];
    glm::dvec2 a = corner(f, 0), e1 = corner(f, 1) - a, e2 = corner(f, 2) - a, d = uv - a;
    double det = e1.x * e2.y - e1.y * e2.x;
    if (det == 0) continue;
    double b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
    double depth = std::min({1 - b1 - b2, b1, b2});
    if (depth >= deepest) deepest = depth, best = Hit{f, {1 - b1 - b2, b1, b2}};
  }
  return best;
}

template <class Of>
glm::dvec3 UvChart::interpolate(const Hit& h, Of of) const {
  const glm::uvec3& t = mesh_.triangles[h.face];
  return h.bary.x * glm::dvec3(of(t[0])) + h.bary.y * glm::dvec3(of(t[1])) + h.bary.z * glm::dvec3(of(t[2]));
}

}  // namespace plumbago

// Directions where the estimate has none (Lee §5.3): umbilic and flat
// vertices take d_min from their neighbors, front by front, as the average of the
// neighbors' directions projected to their tangent plane. Directions are lines, so the
// average is the main axis of sum w wᵀ over the projected neighbor directions w, signed
// like the first of them. A connected piece with no defined direction at all (a plane,
// a sphere) is seeded with the world axis that lies most in its tangent planes, where
// that axis projects to at least half its length; a plane gets a constant field and a
// sphere one along its great circles through the two poles of that axis. Fronts from
// different sides meet in seams, so the propagated directions are then smoothed
// (`curvature.direction_smoothing`, curvature.hpp).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

#include "common/curvature/curvature_internal.hpp"

namespace plumbago::curvature {

bool directions_undefined(float k_min, float k_max, const CurvatureParams& p, float bbox_diagonal) {
  double flat = bbox_diagonal > 0 ? double(p.flat_curvature) / double(bbox_diagonal) : 0.0;
  double spread = std::abs(double(k_max) - double(k_min));
  return !(spread >= double(p.umbilic_ratio) * (std::abs(double(k_max)) + std::abs(double(k_min))) + flat);
}

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit normals and finite curvatures; returns which vertices have a usable d_min (made
// unit and tangent).
std::vector<uint8_t> defined_directions(const CurvatureParams& p, float bbox_diagonal, Curvature& c) {
  std::vector<uint8_t> known(c.size(), 0);
  tbb::parallel_for(size_t(0), c.size(), [&](size_t v) {
    glm::dvec3 n = c.normal[v];
    double len = glm::length(n);
    n = finite(n) && len > 0 ? n / len : glm::dvec3(0, 0, 1);
    c.normal[v] = n;
    if (!std::isfinite(c.k_min[v]) || !std::isfinite(c.k_max[v])) c.k_min[v] = c.k_max[v] = 0;
    glm::dvec3 d = c.d_min[v];
    d -= glm::dot(d, n) * n;
    double d_len = glm::length(d);
    known[v] = finite(d) && d_len > 1e-6 && !directions_undefined(c.k_min[v], c.k_max[v], p, bbox_diagonal);
    if (known[v]) c.d_min[v] = d / d_len;
  });
  return known;
}

// The connected pieces of the graph of vertices without a known direction, as a piece
// index per such vertex, and whether each piece meets a known vertex: one that does not
// is a whole component of the vertex graph without any direction.
std::vector<uint32_t> unknown_pieces(const MeshTopology& topo, const std::vector<uint8_t>& known,
                                     std::vector<uint8_t>& meets_known) {
  std::vector<uint32_t> piece(topo.vertex_count(), UINT32_MAX), stack;
  meets_known.clear();
  for (uint32_t seed = 0; seed < piece.size(); ++seed) {
    if (known[seed] || piece[seed] != UINT32_MAX) continue;
    piece[seed] = uint32_t(meets_known.size());
    meets_known.push_back(0);
    stack.assign(1, seed);
    while (!stack.empty()) {
      uint32_t v = stack.back();
      stack.pop_back();
      for (uint32_t u : topo.neighbors_of(v)) {
        meets_known.back() |= known[u];
        if (!known[u] && piece[u] == UINT32_MAX) piece[u] = piece[seed], stack.push_back(u);
      }
    }
  }
  return piece;
}

void seed_components_without_directions(const MeshTopology& topo, Curvature& c, std::vector<uint8_t>& known) {
  std::vector<uint8_t> meets_known;
  std::vector<uint32_t> piece = unknown_pieces(topo, known, meets_known);
  auto without_direction = [&](size_t v) { return !known[v] && !meets_known[piece[v]]; };
  std::vector<std::array<double, 3>> normal_along_axis(meets_known.size(), {0, 0, 0});
  for (size_t v = 0; v < c.size(); ++v)
    if (without_direction(v))
      for (int a = 0; a < 3; ++a) normal_along_axis[piece[v]][a] += std::abs(c.normal[v][a]);
  for (size_t v = 0; v < c.size(); ++v) {
    if (!without_direction(v)) continue;
    const auto& along = normal_along_axis[piece[v]];
    glm::dvec3 axis(0);
    axis[int(std::min_element(along.begin(), along.end()) - along.begin())] = 1;
    glm::dvec3 n = c.normal[v], d = axis - glm::dot(axis, n) * n;
    if (glm::length(d) < 0.5) continue;
    c.d_min[v] = glm::normalize(d);
    known[v] = 1;
  }
}

// d_min of v from its known neighbors, or false if none of them projects to its plane.
bool direction_from_neighbors(uint32_t v, const MeshTopology& topo, const Curvature& c,
                              const std::vector<uint8_t>& known, glm::vec3& out) {
  glm::dvec3 t1, t2;
  tangent_basis(c.normal[v], t1, t2);
  double a = 0, b = 0, d = 0;
  glm::dvec2 first(0);
  for (uint32_t u : topo.neighbors_of(v)) {
    if (!known[u]) continue;
    glm::dvec2 w(glm::dot(glm::dvec3(c.d_min[u]), t1), glm::dot(glm::dvec3(c.d_min[u]), t2));
    a += w.x * w.x, b += w.x * w.y, d += w.y * w.y;
    if (first == glm::dvec2(0)) first = w;
  }
  if (first == glm::dvec2(0)) return false;
  double theta = 0.5 * std::atan2(2 * b, a - d);
  glm::dvec2 axis(std::cos(theta), std::sin(theta));
  if (glm::dot(axis, first) < 0) axis = -axis;
  out = axis.x * t1 + axis.y * t2;
  return true;
}

// Front by front: every unknown vertex next to a known one takes its neighbors' average,
// all of a front from the previous fronts only, so the result does not depend on order.
void propagate_fronts(const MeshTopology& topo, Curvature& c, std::vector<uint8_t>& known) {
  std::vector<uint8_t> queued(c.size(), 0);
  std::vector<uint32_t> front;
  auto enqueue_unknown_neighbors = [&](uint32_t v, std::vector<uint32_t>& into) {
    for (uint32_t u : topo.neighbors_of(v))
      if (!known[u] && !queued[u]) queued[u] = 1, into.push_back(u);
  };
  std::vector<uint8_t> next_to_known(c.size(), 0);  // the first front, found in parallel
  tbb::parallel_for(size_t(0), c.size(), [&](size_t v) {
    if (known[v]) return;
    for (uint32_t u : topo.neighbors_of(uint32_t(v))) next_to_known[v] |= known[u];
  });
  for (uint32_t v = 0; v < c.size(); ++v)
    if (next_to_known[v]) queued[v] = 1, front.push_back(v);
  while (!front.empty()) {
    std::vector<uint8_t> assigned(front.size(), 0);
    tbb::parallel_for(size_t(0), front.size(), [&](size_t i) {
      assigned[i] = direction_from_neighbors(front[i], topo, c, known, c.d_min[front[i]]);
    });
    std::vector<uint32_t> next;
    for (size_t i = 0; i < front.size(); ++i) {
      known[front[i]] = assigned[i];
      queued[front[i]] = assigned[i];
    }
    for (size_t i = 0; i < front.size(); ++i)
      if (assigned[i]) enqueue_unknown_neighbors(front[i], next);
    front.swap(next);
  }
}

// The mean line in v's tangent plane of its own d_min, its neighbors' (as they are now)
// and, with weight `hold` x (neighbors + 1), its estimated direction: the main axis of
// sum w wᵀ, signed like its own. False where they cancel.
bool mean_line(uint32_t v, const MeshTopology& topo, const Curvature& c, const glm::dvec3& estimate, double hold,
               glm::vec3& out) {
  glm::dvec3 t1, t2;
  tangent_basis(c.normal[v], t1, t2);
  const glm::dvec3 own = c.d_min[v];
  double a = 0, b = 0, d = 0, count = 1;
  auto add = [&](const glm::dvec3& line, double weight) {
    glm::dvec2 w(glm::dot(line, t1), glm::dot(line, t2));
    a += weight * w.x * w.x, b += weight * w.x * w.y, d += weight * w.y * w.y;
  };
  add(own, 1);
  for (uint32_t u : topo.neighbors_of(v)) add(c.d_min[u], 1), ++count;
  if (hold > 0) add(estimate, hold * count);
  if (!(std::hypot(a - d, 2 * b) > 1e-12)) return false;
  double theta = 0.5 * std::atan2(2 * b, a - d);
  glm::dvec3 axis = std::cos(theta) * t1 + std::sin(theta) * t2;
  out = glm::dot(axis, own) < 0 ? -axis : axis;
  return true;
}

// Sweeps of mean_line over the vertices whose direction is not held fixed (propagated, or
// estimated with firmness < 1), all of a sweep from the previous one (Jacobi: the same on
// any number of threads), until no direction turns by more than 0.01 degree or after
// `direction_smoothing` sweeps.
void smooth_directions(const MeshTopology& topo, const CurvatureParams& p, float bbox_diagonal,
                       const std::vector<uint8_t>& known, Curvature& c) {
  std::vector<uint32_t> free;
  std::vector<double> hold;
  std::vector<glm::dvec3> estimate;
  for (uint32_t v = 0; v < c.size(); ++v) {
    double f = direction_firmness(c.k_min[v], c.k_max[v], p, bbox_diagonal);
    if (!known[v] || f >= 1) continue;
    free.push_back(v), hold.push_back(f), estimate.push_back(c.d_min[v]);
  }
  std::vector<glm::vec3> next(free.size());
  const double still = std::cos(0.01 * std::numbers::pi / 180);
  for (int sweep = 0; sweep < p.direction_smoothing && !free.empty(); ++sweep) {
    std::vector<uint8_t> turned(free.size(), 0);
    tbb::parallel_for(size_t(0), free.size(), [&](size_t i) {
      next[i] = c.d_min[free[i]];
      if (mean_line(free[i], topo, c, estimate[i], hold[i], next[i]))
        turned[i] = glm::dot(glm::dvec3(next[i]), glm::dvec3(c.d_min[free[i]])) < still;
    });
    for (size_t i = 0; i < free.size(); ++i) c.d_min[free[i]] = next[i];
    if (std::find(turned.begin(), turned.end(), 1) == turned.end()) break;
  }
}

}  // namespace

void propagate_directions(const MeshTopology& topo, const CurvatureParams& p, float bbox_diagonal, Curvature& c) {
  std::vector<uint8_t> known = defined_directions(p, bbox_diagonal, c);
  seed_components_without_directions(topo, c, known);
  propagate_fronts(topo, c, known);
  smooth_directions(topo, p, bbox_diagonal, known, c);
  tbb::parallel_for(size_t(0), c.size(), [&](size_t v) {
    glm::dvec3 n = c.normal[v], t1, t2;
    tangent_basis(n, t1, t2);
    glm::dvec3 d = known[v] ? glm::dvec3(c.d_min[v]) : t1;
    d -= glm::dot(d, n) * n;
    d = glm::length(d) > 1e-6 ? glm::normalize(d) : t1;
    c.d_min[v] = d;
    c.d_max[v] = glm::cross(n, d);
  });
}

}  // namespace plumbago::curvature

namespace plumbago {

double direction_firmness(float k_min, float k_max, const CurvatureParams& p, float bbox_diagonal) {
  double flat = bbox_diagonal > 0 ? double(p.flat_curvature) / double(bbox_diagonal) : 0.0;
  double threshold = double(p.umbilic_ratio) * (std::abs(double(k_max)) + std::abs(double(k_min))) + flat;
  double spread = std::abs(double(k_max) - double(k_min));
  if (!(spread >= threshold)) return 0.0;
  if (!(threshold > 0) || !(p.direction_firm > 1)) return 1.0;
  return std::clamp((spread / threshold - 1) / (double(p.direction_firm) - 1), 0.0, 1.0);
}

}  // namespace plumbago

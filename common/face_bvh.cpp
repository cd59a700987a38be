#include "common/face_bvh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace plumbago {
namespace {

constexpr uint32_t kLeafFaces = 4;

glm::vec3 centroid(const Mesh& mesh, uint32_t f) {
  const auto& t = mesh.triangles[f];
  return (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0f;
}

}  // namespace

// A complete binary tree of `leaf_depth_` levels below the root: every node splits its
// faces in two halves at the median of their centroids along the longest side of the
// centroids' box, so the leaves hold at most kLeafFaces faces and a node's index says
// where its children are.
FaceBvh::FaceBvh(const Mesh& mesh, const std::vector<uint32_t>& tags) {
  const uint32_t n = uint32_t(mesh.triangles.size());
  while ((uint64_t(n) + (uint64_t(1) << leaf_depth_) - 1) >> leaf_depth_ > kLeafFaces) ++leaf_depth_;
  nodes_.resize((size_t(2) << leaf_depth_) - 1);
  std::vector<uint32_t> faces(n);
  std::iota(faces.begin(), faces.end(), 0u);
  build(mesh, faces, 0, 0, n, 0);
  entries_.resize(n);
  tbb::parallel_for(uint32_t(0), n, [&](uint32_t i) {
    Entry& e = entries_[i];
    for (int k = 0; k < 3; ++k) e.corner[k] = mesh.positions[mesh.triangles[faces[i]][k]];
    e.face = faces[i], e.tag = tags[faces[i]];
  });
}

void FaceBvh::build(const Mesh& mesh, std::vector<uint32_t>& faces, uint32_t node, uint32_t first, uint32_t count,
                    int depth) {
  const auto begin = faces.begin() + first, end = begin + count;
  if (depth == leaf_depth_) {
    Node& leaf = nodes_[node];
    leaf.lo = glm::vec3(std::numeric_limits<float>::max()), leaf.hi = -leaf.lo;
    for (auto f = begin; f != end; ++f)
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& p = mesh.positions[mesh.triangles[*f][k]];
        leaf.lo = glm::min(leaf.lo, p), leaf.hi = glm::max(leaf.hi, p);
      }
    leaf.first = first, leaf.count = count;
    return;
  }
  glm::vec3 lo(std::numeric_limits<float>::max()), hi = -lo;
  for (auto f = begin; f != end; ++f) lo = glm::min(lo, centroid(mesh, *f)), hi = glm::max(hi, centroid(mesh, *f));
  const glm::vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const uint32_t half = count / 2;
  std::nth_element(begin, begin + half, end,
                   [&](uint32_t a, uint32_t b) { return centroid(mesh, a)[axis] < centroid(mesh, b)[axis]; });
  const uint32_t left = 2 * node + 1, right = 2 * node + 2;
  auto build_left = [&] { build(mesh, faces, left, first, half, depth + 1); };
  auto build_right = [&] { build(mesh, faces, right, first + half, count - half, depth + 1); };
  if (count > 4096)
    tbb::parallel_invoke(build_left, build_right);
  else
    build_left(), build_right();
  Node& inner = nodes_[node];
  inner.lo = glm::min(nodes_[left].lo, nodes_[right].lo), inner.hi = glm::max(nodes_[left].hi, nodes_[right].hi);
  inner.first = 0, inner.count = 0;
}

}  // namespace plumbago

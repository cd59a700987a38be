// A bounding volume hierarchy over a mesh's triangles that finds the triangles near a
// sphere's surface: the curvature ball (SPEC §1.1) needs only the faces the sphere cuts,
// since the sums over the faces wholly inside come from the dual tree's subtree sums
// (curvature_ball_flux.cpp). A node wholly inside the sphere or wholly outside it is not
// opened, so a query costs in proportion to the sphere's boundary, not its area.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "common/mesh.hpp"

namespace plumbago {

class FaceBvh {
 public:
  // A face as the leaves keep it, in the leaves' order, so that a query reads memory in
  // order; `tag` is the caller's number for the face.
  struct Entry {
    glm::vec3 corner[3];
    uint32_t face, tag;
  };

  FaceBvh(const Mesh& mesh, const std::vector<uint32_t>& tags);

  // Calls f(entry) for the faces of every leaf whose box is neither wholly inside the
  // ball (c, r) nor wholly beyond r of c: every face that has a corner farther than r and
  // a corner or a point of a side within r is among them, with others near the sphere.
  template <class F>
  void for_each_face_near_sphere(const glm::dvec3& c, double r, F&& f) const;

  // The faces in the leaves' order: neighbors in it are near each other in space.
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  struct Node {
    glm::vec3 lo;
    uint32_t first;  // leaf: its first entry (node i's children are 2i + 1, 2i + 2)
    glm::vec3 hi;
    uint32_t count;  // leaf: number of entries; inner node: 0
  };
  void build(const Mesh& mesh, std::vector<uint32_t>& faces, uint32_t node, uint32_t first, uint32_t count,
             int depth);
  std::vector<Node> nodes_;  // complete binary tree in heap order
  std::vector<Entry> entries_;
  int leaf_depth_ = 0;
};

template <class F>
void FaceBvh::for_each_face_near_sphere(const glm::dvec3& c, double r, F&& f) const {
  if (entries_.empty()) return;
  // Margins of 2e-9 on both sides: a face of a node near either threshold is tested by the
  // caller exactly, whatever the rounding of the box's distances.
  const double inside = r * r * (1 - 2e-9), outside = r * r * (1 + 2e-9);
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t i = stack[--top];
    const Node& n = nodes_[i];
    double near = 0, far = 0;
    for (int k = 0; k < 3; ++k) {
      const double lo = double(n.lo[k]) - c[k], hi = double(n.hi[k]) - c[k];
      near += lo > 0 ? lo * lo : hi < 0 ? hi * hi : 0.0;
      far += std::max(lo * lo, hi * hi);
    }
    if (near > outside || far <= inside) continue;
    if (n.count == 0) {
      stack[top++] = 2 * i + 2;
      stack[top++] = 2 * i + 1;
      continue;
    }
    for (uint32_t k = n.first; k < n.first + n.count; ++k) f(entries_[k]);
  }
}

}  // namespace plumbago

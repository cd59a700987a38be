// A hierarchy of connected face clusters that lets the tensor's geodesic ball (SPEC §1.1)
// add the faces deep inside it a cluster at a time instead of face by face.
//
// Level 1 groups up to 8 faces, each next level up to 8 clusters of the level below,
// always grown across edges of positive length, so every cluster is connected through
// such edges. Each cluster keeps a sphere holding all its corners (and its children's
// spheres), the sums of its faces (area, area-weighted normal), the tensor sum of the
// edges it owns (an edge belongs to the cluster of its face[0]), and the faces outside
// it across its positive-length edges.
//
// Why a cluster inside the ball can be added whole, with the same sums as growing the
// ball face by face: its corners are inside, so its faces count whole and its edges reach
// into the ball over their whole length; one of its faces being reached, all are (through
// its positive-length edges); and the faces beyond it are reached through its boundary.
// The ball skips, at face level, the tensor of an edge whose owner's level-1 cluster is
// inside: that cluster is then reached (across this very edge, unless the edge has no
// length and so no term) and adds the edge with its sums.
#pragma once

#include <vector>

#include "common/curvature_internal.hpp"

namespace plumbago::curvature {

struct FaceClusters {
  struct Node {
    glm::dvec3 center;
    double radius;
    int32_t parent;  // -1 at the top
    uint32_t boundary_begin, boundary_end;  // into boundary_faces
    BallSums sums;
  };
  std::vector<Node> nodes;
  std::vector<uint32_t> face_node;       // each face's level-1 cluster
  std::vector<uint32_t> boundary_faces;  // per node: the faces across its positive-length edges

  // Wholly inside the ball (c, r), with a margin far above round-off (a cluster that
  // misses it by less is grown face by face, which is exact anyway).
  bool inside(uint32_t node, const glm::dvec3& c, double r) const {
    const Node& n = nodes[node];
    double room = r * (1 - 1e-9) - n.radius;  // |center - c| + radius <= r
    glm::dvec3 d = n.center - c;
    return room >= 0 && glm::dot(d, d) <= room * room;
  }
  // The highest cluster around face f wholly inside the ball, or -1.
  int32_t highest_inside(uint32_t f, const glm::dvec3& c, double r) const {
    int32_t node = int32_t(face_node[f]);
    if (!inside(uint32_t(node), c, r)) return -1;
    while (nodes[size_t(node)].parent >= 0 && inside(uint32_t(nodes[size_t(node)].parent), c, r))
      node = nodes[size_t(node)].parent;
    return node;
  }
};

FaceClusters build_face_clusters(const Mesh& mesh, const MeshTopology& topo, const std::vector<double>& beta_per_length);

}  // namespace plumbago::curvature

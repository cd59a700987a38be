// The pieces of the curvature tensor's ball (SPEC §1.1) that its two ways of summing
// share: grown face by face (curvature_ball.cpp), or from the dual tree's subtree sums
// and the faces the sphere cuts (curvature_ball_flux.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/curvature_internal.hpp"
#include "common/face_bvh.hpp"

namespace plumbago::curvature {

// Where a face stands in the current vertex's ball: queued as the `position`-th face
// (stamp = the current vertex's), or not yet (any other stamp).
struct FaceMark {
  uint32_t stamp = 0, position = 0;
};

// Per-thread marks of the faces queued for the current vertex (only the ball uses them),
// and the cut faces' records of the flux ball.
struct Scratch {
  // A face the sphere cuts: its sides that reach into the ball (bit k for side k) and
  // the fraction of each inside it.
  struct CutFace {
    uint32_t reach;
    double fraction[3];
  };
  std::vector<FaceMark> mark;
  std::vector<uint32_t> queue;
  std::vector<CutFace> cut;     // the flux ball's, for the faces in queue
  std::vector<uint32_t> stack;  // the flux ball's walk along the cut faces
  uint32_t stamp = 0;
  explicit Scratch(size_t faces) : mark(faces) {}
  void next_vertex() {
    if (++stamp == 0) {
      std::fill(mark.begin(), mark.end(), FaceMark{});
      stamp = 1;
    }
    queue.clear(), cut.clear();
  }
  bool queued(uint32_t f) const { return mark[f].stamp == stamp; }
  bool enqueue_face(uint32_t f) {
    if (queued(f)) return false;
    mark[f] = {stamp, uint32_t(queue.size())};
    queue.push_back(f);
    return true;
  }
  // An edge is counted by the first of its faces to leave the queue: the face at
  // `position` counts its side towards `other` unless `other` left the queue before it.
  bool counts_side(int32_t other, uint32_t position) const {
    return other < 0 || !queued(uint32_t(other)) || mark[uint32_t(other)].position > position;
  }
};

// What the ball reads about a face, in one record: the ball visits faces in no useful
// order, and one record is two cache lines where the mesh, the topology and the edge
// coefficients would be five or six. Each side's beta / |e| is kept in both faces of
// its edge, and each side knows the face across it, so the ball never reads an edge.
struct BallFace {
  glm::vec3 corner[3];
  int32_t neighbor[3];             // the face across side k (corner k to k + 1), -1 if none
  double beta_per_length[3];       // of side k's edge
  glm::dvec3 twice_area_normal;    // N
  double N_length;
};

struct Surface {
  const Mesh& mesh;
  const MeshTopology& topo;
  std::vector<double> beta_per_length;
  std::vector<BallFace> faces;  // for the ball only
};

// The sums over v's ball (c, r) without visiting the faces wholly inside it (docs/curvature.md,
// "The ball from its boundary"): a face's dual-tree subtree sum holds the whole-face
// terms of every face below it, so the faces wholly inside the ball add up to the
// subtree sums that cross the ball's boundary, and only the faces the sphere cuts are
// clipped. Exact where the cut faces form one band joined by sides that reach into the
// ball (then the ball is the one piece of v's part of the mesh inside the sphere);
// elsewhere `sums` says no and the ball is grown face by face.
class BallFlux {
 public:
  explicit BallFlux(const Surface& g);
  bool sums(uint32_t v, const glm::dvec3& c, double r, Scratch& s, BallSums& out) const;
  // The vertices in an order where neighbors are near in space (consecutive balls then
  // cut mostly the same faces, which stay in the cache).
  std::vector<uint32_t> vertex_order() const;

 private:
  struct DualForest {
    std::vector<uint32_t> root;         // per face: the root of its tree (its piece of the mesh)
    std::vector<uint32_t> parent_edge;  // per face: the edge to its parent, ~0 at a root
    std::vector<uint32_t> order;        // breadth first, parents before children
  };
  static DualForest dual_forest(const Surface& g);
  const Surface& g_;
  DualForest forest_;
  FaceBvh bvh_;                     // tagged with the faces' roots
  std::vector<BallSums> subtree_;   // per face: whole-face terms summed over its subtree
};

}  // namespace plumbago::curvature

// Per-pixel parity bounds of the G-buffer where its triangles are slivers in the window
// (reference/core/stage.hpp BoundFn; docs/stages.md, "gbuffer"). A rasterizer snaps every
// window corner to its subpixel grid: OpenGL 4.5 asks for at least 4 bits
// (GL_SUBPIXEL_BITS), so a corner may move by delta = 2^-5 px in x and in y. The
// barycentrics of a pixel center then move by at most, to first order,
//   d_lambda <= 5 sqrt(2) delta L / (2 A),
// L the triangle's longest window edge and A its window area: a sub-triangle's doubled area
// moves by at most 2 sqrt(2) delta L, the whole one's by 3 sqrt(2) delta L, and lambda <= 1.
// Perspective-correct interpolation multiplies that by at most d_max / d_min over the
// corners (at most 1 in all). An attribute a interpolated from the corners moves by at most
// 2 d_lambda max_i |a_i - a_0| (the changes sum to 0); a unit normal by twice that over the
// interpolated normal's length. A sliver narrower than delta may be replaced by its
// neighbour at a pixel center, so each pixel takes the largest bound of the triangles the
// reference sees at it and its eight neighbours. Well-shaped triangles get bounds far
// below the tolerances; a 100,000-gon's fan or a fan of edge-on fins gets what it needs.
//
// Where the snapped edge is an occluding one, what lies across it is not the same surface: a
// border, or a silhouette edge (its two faces turn opposite ways in the window), passing
// within sqrt(2) delta of a pixel center and not behind the surface the ray found there, may
// give the center to the surface in front of it or behind it, at any depth and with any
// attributes (the edge of a sliver of a thin sheet over the body behind it: the Ogre's
// loincloth). No bound holds there: the pixel's bound is infinite, which leaves it out of
// the comparison, and the count of pixels over the tolerance reports it.
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/core/stage.hpp"
#include "common/mesh/mesh_topology.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/strokes/strokes.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

constexpr double kSnapPx = 1.0 / 32;  // half a step of the 4 subpixel bits GL guarantees

struct SliverBound {
  double d_lambda;      // the barycentrics', perspective included (at most 1)
  double depth_spread;  // max |d_i - d_0| of the corners' linear view depths
};

SliverBound sliver_bound(const WorldObject& obj, const glm::uvec3& tri, const WindowProjection& project) {
  glm::dvec3 w[3];
  for (int k = 0; k < 3; ++k) w[k] = project(glm::dvec3(obj.positions[tri[k]]));
  glm::dvec2 e0 = glm::dvec2(w[1] - w[0]), e1 = glm::dvec2(w[2] - w[0]), e2 = glm::dvec2(w[2] - w[1]);
  double twice_area = std::abs(e0.x * e1.y - e0.y * e1.x);
  double longest = std::max({glm::length(e0), glm::length(e1), glm::length(e2)});
  double near = std::min({w[0].z, w[1].z, w[2].z}), far = std::max({w[0].z, w[1].z, w[2].z});
  double screen = 5 * std::sqrt(2.0) * kSnapPx * longest;
  double spread = std::max(std::abs(w[1].z - w[0].z), std::abs(w[2].z - w[0].z));
  if (!(near > 0) || screen >= twice_area) return {1, spread};
  return {std::min(1.0, screen / twice_area * far / near), spread};
}

// How far an attribute moves at pixel (x, y) of `g` whose triangle is `tri`.
using AttributeBound = double (*)(const WorldObject& obj, const glm::uvec3& tri, const GBuffer& g, int x, int y,
                                  SliverBound b);

template <class Value, class Distance>
double spread(const glm::uvec3& tri, Value value, Distance distance) {
  return std::max(distance(value(tri[1]), value(tri[0])), distance(value(tri[2]), value(tri[0])));
}

double bary_moves(const WorldObject&, const glm::uvec3&, const GBuffer&, int, int, SliverBound b) { return b.d_lambda; }

// The normalized depth of docs/conventions.md, (d - near) / (far - near).
double depth_moves(const WorldObject&, const glm::uvec3&, const GBuffer& g, int, int, SliverBound b) {
  return 2 * b.d_lambda * b.depth_spread / (g.far - g.near);
}

double gouraud_moves(const WorldObject& obj, const glm::uvec3& tri, const GBuffer&, int, int, SliverBound b) {
  return 2 * b.d_lambda *
         spread(
             tri, [&](uint32_t v) { return obj.gouraud[v]; }, [](float a, float b) { return std::abs(a - b); });
}

double normal_moves(const WorldObject& obj, const glm::uvec3& tri, const GBuffer& g, int x, int y, SliverBound b) {
  if (obj.flat) return 0;
  glm::vec3 n(0);
  for (int k = 0; k < 3; ++k) n += g.bary.at(x, y, k) * obj.normals[tri[k]];
  double moved = 2 * b.d_lambda *
                 spread(
                     tri, [&](uint32_t v) { return obj.normals[v]; },
                     [](glm::vec3 a, glm::vec3 b) { return double(glm::length(a - b)); });
  return std::min(2.0, 2 * moved / std::max(double(glm::length(n)), 1e-9));
}

// Twice the window area of each face of `obj`, positive where it runs counter-clockwise
// (faces the eye).
std::vector<double> window_areas(const WorldObject& obj, const WindowProjection& project) {
  std::vector<double> out;
  for (const glm::uvec3& t : obj.triangles) {
    glm::dvec3 w[3];
    for (int k = 0; k < 3; ++k) w[k] = project(glm::dvec3(obj.positions[t[k]]));
    out.push_back((w[1].x - w[0].x) * (w[2].y - w[0].y) - (w[1].y - w[0].y) * (w[2].x - w[0].x));
  }
  return out;
}

// Marks the pixels whose centers lie within `reach` of the window segment a -> b (x, y and
// linear depth) where the segment there is not behind the reference's surface by more than
// a depth discontinuity (kDepthJump): past that, parity's band along the discontinuity
// leaves the pixel out already.
void mark_near_segment(glm::dvec3 a, glm::dvec3 b, double reach, const GBuffer& g, Image& mask) {
  glm::dvec2 a2(a), ab = glm::dvec2(b) - a2;
  double ab2 = glm::dot(ab, ab);
  int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - reach))),
      x1 = std::min(mask.width - 1, int(std::max(a.x, b.x) + reach));
  int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - reach))),
      y1 = std::min(mask.height - 1, int(std::max(a.y, b.y) + reach));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      glm::dvec2 c(x + 0.5, y + 0.5);
      double t = ab2 > 0 ? std::clamp(glm::dot(c - a2, ab) / ab2, 0.0, 1.0) : 0.0;
      if (glm::distance(c, a2 + t * ab) > reach) continue;
      double depth = 1 / ((1 - t) / a.z + t / b.z);  // 1/d is affine in the window
      if (g.ids.at(x, y, 0) == 0 || depth <= g.depth.at(x, y) * (1 + kDepthJump)) mask.at(x, y) = 1;
    }
}

// 1 at the pixels within sqrt(2) snap of an occluding edge (a border, or an edge whose two
// faces turn opposite ways in the window) that is not behind the reference's surface there.
Image near_occluding_edges(const ReferenceFrame& f, const std::vector<WorldObject>& world,
                           const WindowProjection& project) {
  const GBuffer& g = f.get(kGBuffer);
  Image mask(g.ids.width, g.ids.height, 1);
  for (size_t o = 0; o < world.size(); ++o) {
    MeshTopology topology = build_topology(*f.ordinary.objects[o].mesh);
    std::vector<double> area = window_areas(world[o], project);
    for (const MeshTopology::Edge& e : topology.edges) {
      bool border = e.face[1] < 0;
      if (!border && area[size_t(e.face[0])] * area[size_t(e.face[1])] > 0) continue;
      glm::dvec3 a = project(glm::dvec3(world[o].positions[e.from])), b = project(glm::dvec3(world[o].positions[e.to]));
      if (a.z > 0 && b.z > 0) mark_near_segment(a, b, std::sqrt(2.0) * kSnapPx, g, mask);
    }
  }
  return mask;
}

// The bound image of one attribute: its own triangle's at each covered pixel, the largest
// over the 3x3 neighbourhood; infinite within reach of an occluding edge in front.
Image gbuffer_bound(const ReferenceFrame& f, AttributeBound moves) {
  const GBuffer& g = f.get(kGBuffer);
  std::vector<WorldObject> world = world_geometry(f.ordinary);
  WindowProjection project(f.ordinary.camera, g.ids.width, g.ids.height);
  Image own(g.ids.width, g.ids.height, 1);
  for (int y = 0; y < own.height; ++y)
    for (int x = 0; x < own.width; ++x) {
      uint32_t object = g.ids.at(x, y, 0);
      if (object == 0) continue;
      const WorldObject& obj = world[object - 1];
      const glm::uvec3& tri = obj.triangles[g.ids.at(x, y, 1)];
      own.at(x, y) = float(moves(obj, tri, g, x, y, sliver_bound(obj, tri, project)));
    }
  Image occluding = near_occluding_edges(f, world, project);
  Image out(own.width, own.height, 1);
  for (int y = 0; y < own.height; ++y)
    for (int x = 0; x < own.width; ++x) {
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = std::clamp(x + dx, 0, own.width - 1), ny = std::clamp(y + dy, 0, own.height - 1);
          out.at(x, y) = std::max(out.at(x, y), own.at(nx, ny));
        }
      if (occluding.at(x, y) > 0) out.at(x, y) = std::numeric_limits<float>::infinity();
    }
  return out;
}

}  // namespace

PLUMBAGO_REFERENCE_BOUND(gbuffer_bary, kGBuffer.bary.name,
                         [](const ReferenceFrame& f) { return gbuffer_bound(f, bary_moves); });
PLUMBAGO_REFERENCE_BOUND(gbuffer_depth, kGBuffer.depth.name,
                         [](const ReferenceFrame& f) { return gbuffer_bound(f, depth_moves); });
PLUMBAGO_REFERENCE_BOUND(gbuffer_normal, kGBuffer.normal.name,
                         [](const ReferenceFrame& f) { return gbuffer_bound(f, normal_moves); });
PLUMBAGO_REFERENCE_BOUND(gbuffer_gouraud, kGBuffer.gouraud.name,
                         [](const ReferenceFrame& f) { return gbuffer_bound(f, gouraud_moves); });

}  // namespace plumbago::reference

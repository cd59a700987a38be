// Mobile hatching (Kalnins et al. 2002, §6.3): hatching groups that move on the surface as
// the view changes, "suggestive of light cast from somewhere behind the camera". A group
// drawn in mobile mode (a stroke file's hatching strokes with "mobile": true) implies a
// pseudo-light opposite its local normal: a light for highlights, a "dark light" for
// shading.
//
// 1. When the renderer reads the scene (MobileHatching's constructor), per mobile group, on
//    the object most of its drawn points lie on, in its parameterization: the mesh's own
//    (Mesh::uvs), else CGAL's LSCM on the disk-like patch under the group, within 3/8 of
//    the mesh's box diagonal, u along the drawing camera's right
//    (common/mesh/patch_parameterization.hpp):
//    - its projected points (common/strokes/decal.hpp) in (u, v): (1) projected into uv
//      space, (2) their convex hull, (3) its centroid c (the polygon's area centroid),
//      (4) n_c, the surface normal at c, in the view space of the camera it was drawn in;
//    - it travels on the u-line through c (v = c.v), and its extent w is the hull's in u.
// 2. Every frame, along the u-line, kMobileSamples samples of the normal n(u) (the mesh's
//    vertex normals interpolated, in the current view space), smoothed by a box kernel of
//    the group's extent w ("to reduce sensitivity to minor surface variations"; n_c is
//    smoothed the same way), give l(u) = n_c . n(u). The smoothing is in object space, so
//    the smoothed normals are sampled once, with the group; a frame turns them into its view. At each local maximum of
//    l (refined by the parabola through it and its neighbours) with l >= T (hatching.mobile_threshold, the paper's 1/2)
//    and no higher l within w/2 of it (copies nearer than that would overlap; on a coarse
//    mesh's LSCM patch l(u) ripples, and each ripple would be a copy), a copy of the group is placed: its points moved
//    by u* - c.u in (u, v) and put back on the surface where (u, v) lies on a face (elsewhere missed, which splits a
//    hatch as a decal's miss does). Its alpha is multiplied by clamp((l - T) / hatching.mobile_fade, 0, 1): the fade
//    "as l(u) approaches T". Its "extent is governed by the width of the peak": its points' u about c is scaled by the
//    peak's width over the drawn peak's (l in the view it was drawn in, at c), clamped to
//    [1/4, 4]; a peak's width is the samples about its maximum while l falls and stays at
//    or over T.
//    A u-line is periodic (period 1) where the chart's lowest u and that plus 1 are the
//    same point of the surface (a torus, sphere, cylinder or cone about its axis).
// A group's level of detail is measured where it was drawn.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "common/strokes/decal.hpp"

namespace plumbago {

// Samples of l(u) along a group's u-line each frame.
constexpr int kMobileSamples = 256;

class UvChart;
struct HatchGroup;

class MobileHatching {
 public:
  // The mobile groups of `scene` (hatching_groups), from their projected strokes `surface`
  // (decal_samples' order). Throws SceneError naming the stroke file, group and object when
  // a group's object has no (u, v) and no disk-like patch lies under it (a group on no
  // surface is left out).
  MobileHatching(const Scene& scene, const DecalSurface& surface);
  ~MobileHatching();
  MobileHatching(MobileHatching&&) noexcept;

  // Whether surface stroke `decal` is a mobile group's.
  bool moves(size_t decal) const;

  // A group this frame (2. above), in hatching_groups' order (stationary groups: none):
  // its centroid c in (u, v), and per copy the u of its maximum, l there, its alpha and
  // its scale in u (the peak's width over the drawn peak's).
  struct Placement {
    glm::dvec2 c{0.0};
    std::vector<double> u, l, alpha, scale;
  };
  std::vector<Placement> place(const Scene& scene, double threshold, double fade) const;

  // The copies of mobile surface stroke `decal` at `placements` (place's): one a maximum,
  // its points moved along the u-line; with each, its alpha.
  struct Copy {
    ProjectedDecal decal;
    double alpha;
  };
  std::vector<Copy> copies(const DecalSurface& surface, size_t decal, const std::vector<Placement>& placements) const;
  // Where copy m of placement `p` moves a point at `uv` of its group's chart: to
  // (u_m + scale_m (u - c.u), v).
  static glm::dvec2 moved(const Placement& p, size_t m, glm::dvec2 uv) {
    return {p.u[m] + p.scale[m] * (uv.x - p.c.x), uv.y};
  }

  // The chart mobile surface stroke `decal`'s group travels on, and the object it lies on
  // (its points elsewhere are missed in a copy); for any other stroke no chart.
  struct Travel {
    const UvChart* chart = nullptr;
    uint32_t object = kMissed;
  };
  Travel travel(size_t decal) const;

 private:
  struct Group;
  std::optional<Group> make_group(const Scene& scene, const DecalSurface& surface, const HatchGroup& g, int index);
  const Group* group_of(size_t decal) const;
  std::vector<std::shared_ptr<const UvChart>> charts_;  // per scene object, made where a group needs it
  std::vector<Group> groups_;
};

}  // namespace plumbago

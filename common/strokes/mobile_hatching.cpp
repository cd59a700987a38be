// Mobile hatching (Kalnins et al. 2002, §6.3): see common/strokes/mobile_hatching.hpp.
#include "common/strokes/mobile_hatching.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/mesh/patch_parameterization.hpp"
#include "common/strokes/hatching.hpp"
#include "common/strokes/uv_chart.hpp"

namespace plumbago {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The area centroid of the convex hull of `points` (its vertex mean where it has no area)
// and its extent in u.
std::pair<glm::dvec2, double> hull_centroid(const std::vector<glm::dvec2>& points) {
  std::vector<Kernel::Point_2> in, hull;
  for (glm::dvec2 p : points) in.emplace_back(p.x, p.y);
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));
  double area = 0, lo = INFINITY, hi = -INFINITY;
  glm::dvec2 sum(0.0), mean(0.0);
  for (size_t i = 0; i < hull.size(); ++i) {
    glm::dvec2 a(hull[i].x(), hull[i].y()), b(hull[(i + 1) % hull.size()].x(), hull[(i + 1) % hull.size()].y());
    double cross = a.x * b.y - a.y * b.x;
    area += cross, sum += (a + b) * cross, mean += a / double(hull.size());
    lo = std::min(lo, a.x), hi = std::max(hi, a.x);
  }
  return {std::abs(area) > 1e-14 ? sum / (3 * area) : mean, hi - lo};
}

// The object-space normal at (u, v) smoothed along the u-line by a box of `width`
// (kMobileSamples / 8 samples across it, those on the surface), unnormalized; zero where
// none is.
glm::dvec3 smoothed_normal(const UvChart& chart, glm::dvec2 uv, double width) {
  constexpr int kAcross = kMobileSamples / 8;
  glm::dvec3 sum(0.0);
  for (int k = 0; k < kAcross; ++k) {
    double t = kAcross > 1 ? double(k) / (kAcross - 1) - 0.5 : 0.0;
    if (auto hit = chart.locate({uv.x + t * width, uv.y})) sum += glm::normalize(chart.normal(*hit));
  }
  return sum;
}

// Object space to the view space of `camera`, for normals (the transform's inverse transpose).
glm::dmat3 normal_to_view(const SceneObject& o, const Camera& camera) {
  return glm::dmat3(glm::dmat4(camera.view())) * glm::transpose(glm::inverse(glm::dmat3(glm::dmat4(o.transform))));
}

// Where `object`'s mesh has no (u, v): LSCM on the disk-like patch under the group's points
// `on` it (common/mesh/patch_parameterization.hpp), within 3/8 of the mesh's box diagonal of
// them, u along the drawing camera's right in object space. Throws std::runtime_error.
std::shared_ptr<const UvChart> patch_chart(const SceneObject& object, const Camera& drawn,
                                           const std::vector<const DecalPoint*>& on) {
  std::vector<uint32_t> seeds;
  for (const DecalPoint* p : on) seeds.push_back(p->face);
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(drawn.forward()), glm::dvec3(drawn.up)));
  const glm::dvec3 along = glm::inverse(glm::dmat3(glm::dmat4(object.transform))) * right;
  const Mesh& mesh = *object.mesh;
  return std::make_shared<const UvChart>(mesh, patch_uvs(mesh, seeds, 0.375 * double(mesh.bbox_diagonal()), along));
}

// A group's u-line (v = c.v): its kMobileSamples samples of u and, at each, the normal
// smoothed over the group's extent `width`, in object space (zero where none is). They depend
// on the surface alone, so they are made once, with the group.
class ULine {
 public:
  ULine(const UvChart& chart, glm::dvec2 c, double width)
      : periodic(chart.periodic()), normals(kMobileSamples), extent(width) {
    // A chart of one u (degenerate) still samples a line, of a tiny step.
    step = std::max(chart.u_span(), 1e-12) / (periodic ? kMobileSamples : kMobileSamples - 1);
    u0 = chart.u_lowest();
    for (int i = 0; i < kMobileSamples; ++i) normals[size_t(i)] = smoothed_normal(chart, {u0 + i * step, c.y}, width);
  }
  bool periodic;
  std::vector<glm::dvec3> normals;
  double extent, step = 1, u0 = 0;
};

// l(u) = n_c . n(u) at the samples of a group's u-line, n(u) its smoothed normals seen from
// `to_view` (2. of mobile_hatching.hpp); -inf where the line leaves the surface.
class Profile {
 public:
  Profile(const ULine& line, glm::dvec3 n_c, const glm::dmat3& to_view)
      : periodic_(line.periodic),
        l_(kMobileSamples, -INFINITY),
        step_(line.step),
        u0_(line.u0),
        // half the group's extent in samples: at least 1, less than half the line
        reach_(int(std::clamp(std::floor(line.extent / (2 * line.step)), 1.0, kMobileSamples / 2.0 - 1))) {
    for (size_t i = 0; i < l_.size(); ++i)
      if (glm::length(line.normals[i]) > 0) l_[i] = glm::dot(n_c, glm::normalize(to_view * line.normals[i]));
  }
  double u(double i) const { return u0_ + i * step_; }
  int nearest(double u) const { return int(std::lround((u - u0_) / step_)); }
  // Sample i's l; past the ends, a periodic line wraps and an open one has none.
  double at(int i) const {
    if (periodic_) return l_[size_t((i % kMobileSamples + kMobileSamples) % kMobileSamples)];
    return i < 0 || i >= kMobileSamples ? -INFINITY : l_[size_t(i)];
  }
  // The maxima at or over `threshold`, as (fractional sample, l): each refined by the
  // parabola through it and its neighbours; a plateau counts once, at its first sample; and
  // of maxima within half the group's extent of each other (copies that would overlap), the
  // highest, the first of equals.
  std::vector<std::pair<double, double>> maxima(double threshold) const {
    std::vector<std::pair<double, double>> out;
    for (int i = periodic_ ? 0 : 1; i < (periodic_ ? kMobileSamples : kMobileSamples - 1); ++i) {
      const double a = at(i - 1), b = at(i), c = at(i + 1);
      if (!(b >= threshold && b > a && b >= c) || overtopped(i)) continue;
      const double curve = a - 2 * b + c;
      out.emplace_back(i + (std::isfinite(a) && std::isfinite(c) && curve < 0 ? 0.5 * (a - c) / curve : 0.0), b);
    }
    return out;
  }
  // Whether a sample within reach of maximum i stands higher (on its left: as high).
  bool overtopped(int i) const {
    for (int j = 2; j <= reach_; ++j)
      if (at(i - j) >= at(i) || at(i + j) > at(i)) return true;
    return false;
  }
  // The width in u of the peak at or next to sample i (climbed to its top first): the
  // samples on each side while l falls and stays at or over `threshold` (at least one).
  double peak_width(int i, double threshold) const {
    for (int k = 0; k < kMobileSamples && at(i - 1) > at(i); ++k) --i;
    for (int k = 0; k < kMobileSamples && at(i + 1) > at(i); ++k) ++i;
    int lo = i, hi = i;
    while (hi - lo < kMobileSamples && at(lo - 1) >= threshold && at(lo - 1) <= at(lo)) --lo;
    while (hi - lo < kMobileSamples && at(hi + 1) >= threshold && at(hi + 1) <= at(hi)) ++hi;
    return std::max(hi - lo, 1) * step_;
  }

 private:
  bool periodic_;
  std::vector<double> l_;
  double step_ = 1, u0_ = 0;
  int reach_;
};

}  // namespace

struct MobileHatching::Group {
  int index;  // in hatching_groups
  uint32_t object;
  std::shared_ptr<const UvChart> chart;  // its object's own (u, v), or the patch's under it
  std::vector<size_t> decals;            // its surface strokes
  glm::dvec2 c;                          // the centroid of its points' hull in (u, v)
  glm::dvec3 n_c;                        // the smoothed normal at c, in the view space of the camera it was drawn in
  ULine line;                            // its u-line's smoothed normals
  Profile drawn;                         // l(u) in that view: its peak at c is the drawn one
};

MobileHatching::MobileHatching(const Scene& scene, const DecalSurface& surface) : charts_(scene.objects.size()) {
  const std::vector<HatchGroup> groups = hatching_groups(scene);
  for (int g = 0; g < int(groups.size()); ++g)
    if (groups[g].mobile)
      if (std::optional<Group> group = make_group(scene, surface, groups[g], g)) groups_.push_back(std::move(*group));
}

// 1. of mobile_hatching.hpp for group `g` (index `index`), its chart made where none is yet;
// none where the group lies on no surface (as a stationary group's, its hatches draw nothing).
std::optional<MobileHatching::Group> MobileHatching::make_group(const Scene& scene, const DecalSurface& surface,
                                                                const HatchGroup& g, int index) {
  std::vector<size_t> decals;
  std::vector<const DecalPoint*> hit;
  for (size_t d = 0; d < surface.size(); ++d) {
    if (surface[d].hatch.group != index) continue;
    decals.push_back(d);
    for (const DecalPoint& p : surface[d].points)
      if (p.object != kMissed) hit.push_back(&p);
  }
  const StrokeFile& file = scene.stroke_files[g.files[0]];
  auto refuse = [&](const std::string& why) {
    throw SceneError(file.source + ": hatching group " + std::to_string(g.number) + ": " + why);
  };
  std::vector<uint32_t> objects;
  for (const DecalPoint* p : hit) objects.push_back(p->object);
  const uint32_t object = most_common_object(objects);
  if (object == kMissed) return std::nullopt;
  const Mesh& mesh = *scene.objects[object].mesh;
  std::vector<const DecalPoint*> on;  // its points on that object
  for (const DecalPoint* p : hit)
    if (p->object == object) on.push_back(p);
  std::shared_ptr<const UvChart> own;
  if (mesh.uvs.empty()) {
    try {
      own = patch_chart(scene.objects[object], file.camera, on);
    } catch (const std::runtime_error& e) {
      refuse("object " + std::to_string(object) + " (" + mesh.name + ") has no (u, v) of its own, and " + e.what());
    }
  } else {
    if (!charts_[object]) charts_[object] = std::make_shared<const UvChart>(mesh, mesh.uvs);
    own = charts_[object];
  }
  const UvChart& chart = *own;
  std::vector<glm::dvec2> uv;
  for (const DecalPoint* p : on) uv.push_back(chart.uv(p->face, p->bary));
  auto [c, width] = hull_centroid(uv);
  glm::dvec3 n = smoothed_normal(chart, c, width);
  if (glm::length(n) == 0) refuse("the centroid of a mobile group's (u, v) hull lies off its object's chart");
  const glm::dmat3 drawn_view = normal_to_view(scene.objects[object], file.camera);
  const glm::dvec3 n_c = glm::normalize(drawn_view * n);
  ULine line(chart, c, width);
  Profile drawn(line, n_c, drawn_view);
  return Group{index, object, own, std::move(decals), c, n_c, std::move(line), std::move(drawn)};
}

MobileHatching::~MobileHatching() = default;
MobileHatching::MobileHatching(MobileHatching&&) noexcept = default;

MobileHatching::Travel MobileHatching::travel(size_t decal) const {
  const Group* g = group_of(decal);
  return g ? Travel{g->chart.get(), g->object} : Travel{};
}

const MobileHatching::Group* MobileHatching::group_of(size_t decal) const {
  for (const Group& g : groups_)
    if (std::find(g.decals.begin(), g.decals.end(), decal) != g.decals.end()) return &g;
  return nullptr;
}

bool MobileHatching::moves(size_t decal) const { return group_of(decal) != nullptr; }

std::vector<MobileHatching::Placement> MobileHatching::place(const Scene& scene, double threshold, double fade) const {
  std::vector<Placement> out(hatching_groups(scene).size());
  for (const Group& g : groups_) {
    const Profile now(g.line, g.n_c, normal_to_view(scene.objects[g.object], scene.camera));
    const double drawn_width = g.drawn.peak_width(g.drawn.nearest(g.c.x), threshold);
    Placement& p = out[size_t(g.index)];
    p.c = g.c;
    for (auto [i, l] : now.maxima(threshold)) {
      p.u.push_back(now.u(i));
      p.l.push_back(l);
      p.alpha.push_back(fade > 0 ? std::clamp((l - threshold) / fade, 0.0, 1.0) : 1.0);
      p.scale.push_back(std::clamp(now.peak_width(int(std::lround(i)), threshold) / drawn_width, 0.25, 4.0));
    }
  }
  return out;
}

std::vector<MobileHatching::Copy> MobileHatching::copies(const DecalSurface& surface, size_t decal,
                                                         const std::vector<Placement>& placements) const {
  std::vector<Copy> out;
  const Group* g = group_of(decal);
  if (!g) return out;
  const UvChart& chart = *g->chart;
  const Placement& p = placements.at(size_t(g->index));
  for (size_t m = 0; m < p.u.size(); ++m) {
    ProjectedDecal copy = surface[decal];
    for (DecalPoint& point : copy.points) {
      if (point.object != g->object) {
        point.object = kMissed;
        continue;
      }
      std::optional<UvChart::Hit> hit = chart.locate(moved(p, m, chart.uv(point.face, point.bary)));
      if (hit)
        point.face = hit->face, point.bary = hit->bary;
      else
        point.object = kMissed;
    }
    out.push_back({std::move(copy), p.alpha[m]});
  }
  return out;
}

}  // namespace plumbago

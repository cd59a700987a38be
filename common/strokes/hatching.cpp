// Hatching groups (Kalnins et al. 2002, §6): see common/strokes/hatching.hpp.
#include "common/strokes/hatching.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/scene/animation.hpp"
#include "common/strokes/decal.hpp"
#include "common/strokes/strokes.hpp"

namespace plumbago {

namespace {

[[noreturn]] void refuse(const StrokeFile& file, int number, const std::string& what) {
  throw SceneError(file.source + ": hatching group " + std::to_string(number) + ": " + what);
}

// The group's strokes of one stroke file.
std::vector<const DrawnStroke*> strokes_of(const StrokeFile& file, int number) {
  std::vector<const DrawnStroke*> out;
  for (const DrawnStroke& s : file.strokes)
    if (s.role == StrokeRole::Hatching && s.group == number) out.push_back(&s);
  return out;
}

// A structured group's drawn hatches, each run the first one's way, ordered across.
std::vector<std::vector<DrawnPoint>> ordered_hatches(const std::vector<const DrawnStroke*>& strokes) {
  std::vector<std::vector<DrawnPoint>> hatches;
  glm::dvec2 first = strokes[0]->points.back().window - strokes[0]->points.front().window, mean(0.0);
  for (const DrawnStroke* s : strokes) {
    hatches.push_back(s->points);
    glm::dvec2 d = s->points.back().window - s->points.front().window;
    if (glm::dot(d, first) < 0) std::reverse(hatches.back().begin(), hatches.back().end()), d = -d;
    if (glm::length(d) > 0) mean += glm::normalize(d);
  }
  glm::dvec2 across(-mean.y, mean.x);
  auto place = [&](const std::vector<DrawnPoint>& h) {
    return glm::dot(resampled_evenly(h, 2)[1].window, across);  // the middle, by arc length
  };
  std::stable_sort(hatches.begin(), hatches.end(), [&](const auto& a, const auto& b) { return place(a) < place(b); });
  return hatches;
}

// "New stroke paths linearly interpolate those of their neighbours": a and b at the same
// arc-length fractions, mixed by w.
std::vector<DrawnPoint> between(const std::vector<DrawnPoint>& a, const std::vector<DrawnPoint>& b, double w) {
  size_t segments = std::max<size_t>(1, size_t(std::ceil(std::max(drawn_length(a), drawn_length(b)) / kDecalStepPx)));
  std::vector<DrawnPoint> ra = resampled_evenly(a, segments), rb = resampled_evenly(b, segments), out;
  for (size_t k = 0; k < ra.size(); ++k)
    out.push_back(
        {ra[k].window + w * (rb[k].window - ra[k].window), ra[k].pressure + w * (rb[k].pressure - ra[k].pressure)});
  return out;
}

void add_structured(const Scene& scene, const HatchGroup& g, int index, std::vector<HatchPolyline>& out) {
  std::vector<const DrawnStroke*> strokes = strokes_of(scene.stroke_files[g.files[0]], g.number);
  std::vector<std::vector<DrawnPoint>> hatches = ordered_hatches(strokes);
  const DrawnStroke* first = strokes[0];
  const int between_count = 1 << kMaxHatchLevel;
  for (size_t i = 0; i < hatches.size(); ++i) {
    out.push_back({g.files[0], first, {index, double(i)}, hatches[i]});
    if (i + 1 == hatches.size()) break;
    for (int j = 1; j < between_count; ++j) {
      double w = double(j) / between_count;
      out.push_back({g.files[0], first, {index, double(i) + w}, between(hatches[i], hatches[i + 1], w)});
    }
  }
}

}  // namespace

std::vector<HatchGroup> hatching_groups(const Scene& scene) {
  std::map<int, HatchGroup> groups;
  for (uint32_t f = 0; f < scene.stroke_files.size(); ++f)
    for (const DrawnStroke& s : scene.stroke_files[f].strokes) {
      if (s.role != StrokeRole::Hatching) continue;
      auto [it, added] = groups.emplace(s.group, HatchGroup{s.group, s.free, s.mobile, {f}, 0});
      HatchGroup& g = it->second;
      if (g.free != s.free) refuse(scene.stroke_files[f], s.group, "mixes free and structured strokes");
      if (g.mobile != s.mobile) refuse(scene.stroke_files[f], s.group, "mixes mobile and stationary strokes");
      if (!g.free && g.files[0] != f)
        refuse(scene.stroke_files[f], s.group,
               "a structured group is drawn in one stroke file, and it is also in " +
                   scene.stroke_files[g.files[0]].source);
      if (g.free && g.files.back() != f) g.files.push_back(f);
      if (!g.free) ++g.hatches;
    }
  std::vector<HatchGroup> out;
  for (auto& [number, g] : groups) out.push_back(g);
  return out;
}

std::vector<HatchPolyline> hatch_polylines(const Scene& scene) {
  std::vector<HatchPolyline> out;
  std::vector<HatchGroup> groups = hatching_groups(scene);
  for (int g = 0; g < int(groups.size()); ++g) {
    if (!groups[g].free) {
      add_structured(scene, groups[g], g, out);
      continue;
    }
    for (size_t level = 0; level < groups[g].files.size(); ++level)
      for (const DrawnStroke* s : strokes_of(scene.stroke_files[groups[g].files[level]], groups[g].number))
        out.push_back({groups[g].files[level], s, {g, double(level)}, s->points});
  }
  return out;
}

double given_value(float value) { return std::round(double(value) * 1e6) / 1e6; }

double HatchLod::progress(double time_s, double fade_s) const {
  fade_s = given_value(float(fade_s));
  if (from == to || fade_s <= 0) return 1;
  return std::clamp((time_s - start_s) / fade_s, 0.0, 1.0);
}

double HatchLevels::at(int level) const { return sigma.empty() ? std::ldexp(1.0, level) : sigma[size_t(level)]; }

HatchLod hatch_lod_step(const HatchLod& state, double sigma, double time_s, const HatchLevels& levels,
                        const HatchingParams& p) {
  if (state.progress(time_s, p.fade_s) < 1) return state;  // a transition runs to its end
  int level = state.to;
  double t_plus = given_value(p.t_plus), t_minus = std::min(given_value(p.t_minus), t_plus);
  if (level < levels.highest && sigma >= levels.at(level + 1) * t_plus / 2) return {level, level + 1, time_s};
  if (level > levels.lowest && sigma < levels.at(level) * t_minus / 2) return {level, level - 1, time_s};
  return {level, level, state.start_s};
}

HatchLod hatch_lod_settled(double sigma, const HatchLevels& levels, const HatchingParams& p) {
  HatchingParams instant = p;
  instant.fade_s = 0;
  HatchLod state;
  for (int k = levels.lowest; k <= levels.highest; ++k) {  // each step moves one level, or none
    HatchLod next = hatch_lod_step(state, sigma, 0, levels, instant);
    if (next.to == state.to) break;
    state = next;
  }
  return {state.to, state.to, 0};
}

namespace {

// The group's scale in one camera and window (2. of hatching.hpp).
class GroupScale {
 public:
  GroupScale(const Scene& scene, const HatchGroup& g, int index, const std::vector<ProjectedDecal>& surface)
      : scene_(scene), group_(g) {
    for (const ProjectedDecal& d : surface)
      if (d.hatch.group == index && (g.free ? d.hatch.position == 0 : d.hatch.position == std::floor(d.hatch.position)))
        add_anchor(d);
    object_ = most_common_object(objects_);
    if (object_ != kMissed) bound_object();
    const StrokeFile& drawn = scene.stroke_files[g.files[0]];
    drawn_ = measure(drawn.camera, drawn.width, drawn.height);
  }

  // sigma in `camera` over the scene's window.
  double sigma(const Camera& camera) const {
    double now = measure(camera, scene_.width, scene_.height);
    return drawn_ > 0 && std::isfinite(now / drawn_) ? now / drawn_ : 1.0;
  }

  // The object most of the drawn points meet (kMissed when none does).
  uint32_t object() const { return object_; }

  HatchLevels levels(int max_level) const {
    HatchLevels out;
    if (!group_.free) {
      out.lowest = group_.hatches > 2 ? -int(std::floor(std::log2(double(group_.hatches - 1)))) : 0;
      out.highest = max_level;
      return out;
    }
    for (uint32_t f : group_.files) {
      const StrokeFile& file = scene_.stroke_files[f];
      out.sigma.push_back(drawn_ > 0 ? measure(file.camera, file.width, file.height) / drawn_ : 1.0);
    }
    out.highest = int(out.sigma.size()) - 1;
    return out;
  }

 private:
  // The objects of the drawn points; structured: the drawn hatches' middle surface points.
  void add_anchor(const ProjectedDecal& d) {
    std::vector<const DecalPoint*> hit;
    for (const DecalPoint& p : d.points)
      if (p.object != kMissed) hit.push_back(&p);
    for (const DecalPoint* p : hit) objects_.push_back(p->object);
    if (!hit.empty() && !group_.free) backbone_.push_back(decal_point_world(scene_, *hit[hit.size() / 2]));
  }

  double measure(const Camera& camera, int width, int height) const {
    return group_.free ? screen_diameter(camera, height) : backbone_length(camera, width, height);
  }

  double backbone_length(const Camera& camera, int width, int height) const {
    WindowProjection project(camera, width, height);
    double length = 0;
    for (size_t k = 1; k < backbone_.size(); ++k) {
      glm::dvec3 a = project(backbone_[k - 1]), b = project(backbone_[k]);
      if (a.z > 0 && b.z > 0) length += glm::distance(glm::dvec2(a), glm::dvec2(b));
    }
    return length;
  }

  // The object's bounding sphere's diameter in px at its distance (§5.4's sigma_m).
  double screen_diameter(const Camera& camera, int height) const {
    if (object_ == kMissed) return 0;
    double distance = glm::distance(center_, glm::dvec3(camera.eye));
    double half_fov = glm::radians(double(camera.fov_deg)) / 2;
    return distance > 0 ? 2 * radius_ / (distance * std::tan(half_fov)) * height / 2 : 0;
  }

  // The bounding sphere of the object's box (Mesh::bbox_min/max) placed in the world.
  void bound_object() {
    const SceneObject& o = scene_.objects[object_];
    glm::dvec3 lo(INFINITY), hi(-INFINITY), a(o.mesh->bbox_min()), b(o.mesh->bbox_max());
    for (int k = 0; k < 8; ++k) {
      glm::dvec3 corner(k & 1 ? b.x : a.x, k & 2 ? b.y : a.y, k & 4 ? b.z : a.z);
      glm::dvec3 w(glm::dmat4(o.transform) * glm::dvec4(corner, 1.0));
      lo = glm::min(lo, w), hi = glm::max(hi, w);
    }
    center_ = (lo + hi) / 2.0, radius_ = glm::distance(lo, hi) / 2;
  }

  const Scene& scene_;
  const HatchGroup& group_;
  std::vector<glm::dvec3> backbone_;
  std::vector<uint32_t> objects_;
  uint32_t object_ = kMissed;
  glm::dvec3 center_{0.0};
  double radius_ = 0;
  double drawn_ = 0;
};

bool in_level(const HatchTag& tag, bool free, int level) {
  if (free) return tag.position <= level;
  double x = std::ldexp(tag.position, level);
  return std::abs(x - std::round(x)) < 1e-9;
}

}  // namespace

std::vector<HatchGroupState> hatch_states(const Scene& scene, const std::vector<ProjectedDecal>& surface,
                                          const HatchingParams& p) {
  std::vector<HatchGroupState> out;
  std::vector<HatchGroup> groups = hatching_groups(scene);
  if (groups.empty()) return out;
  std::vector<Camera> cameras = path_cameras(scene);
  for (int g = 0; g < int(groups.size()); ++g) {
    GroupScale scale(scene, groups[g], g, surface);
    HatchLevels levels = scale.levels(p.max_level);
    HatchLod lod = hatch_lod_settled(scale.sigma(cameras[0]), levels, p);
    for (size_t k = 1; k < cameras.size(); ++k)
      lod = hatch_lod_step(lod, scale.sigma(cameras[k]), scene.animation->time_s(int(k)), levels, p);
    double now = scene.animation ? scene.animation->time_s(scene.frame) : 0.0;
    out.push_back({groups[g].number, groups[g].free, groups[g].mobile, scale.object(), scale.sigma(cameras.back()), lod,
                   lod.progress(now, p.fade_s)});
  }
  return out;
}

std::vector<HatchWeight> hatch_weights(const std::vector<HatchGroupState>& states,
                                       const std::vector<ProjectedDecal>& surface) {
  std::vector<HatchWeight> out(surface.size());
  for (size_t d = 0; d < surface.size(); ++d) {
    const HatchTag& tag = surface[d].hatch;
    if (tag.group < 0) continue;
    const HatchGroupState& g = states[size_t(tag.group)];
    double p = g.progress;
    out[d].alpha = (1 - p) * in_level(tag, g.free, g.lod.from) + p * in_level(tag, g.free, g.lod.to);
    double density = (1 - p) * std::ldexp(1.0, g.lod.from) + p * std::ldexp(1.0, g.lod.to);
    if (!g.free) out[d].width = std::clamp(g.sigma / density, 0.25, 4.0);
  }
  return out;
}

}  // namespace plumbago

// Visibility of stroke samples (Kalnins et al. 2002, §4.6, §4.1): see common/strokes/visibility.hpp.
#include "common/strokes/visibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/util/memory_budget.hpp"

namespace plumbago {

namespace {

constexpr double kLocatedPx = 1.0;  // Kalnins et al. 2002, §4.1: a visibility change is located within 1 px

// The point at window arc length s of a path (a closed path wraps).
struct PathPoint {
  glm::dvec2 window;
  size_t segment;  // from point `segment` to the next
  double t;        // where along it, in the window
};

PathPoint point_at(const WindowPath& p, double s) {
  size_t n = p.window.size();
  if (p.closed && p.length_px > 0) s = std::fmod(std::fmod(s, p.length_px) + p.length_px, p.length_px);
  size_t k = size_t(std::upper_bound(p.arc_px.begin(), p.arc_px.end(), s) - p.arc_px.begin());
  k = k == 0 ? 0 : k - 1;
  if (!p.closed) k = std::min(k, n - 2);
  size_t next = (k + 1) % n;
  double length = (k + 1 < n ? p.arc_px[k + 1] : p.length_px) - p.arc_px[k];
  double t = length > 0 ? std::clamp((s - p.arc_px[k]) / length, 0.0, 1.0) : 0.0;
  return {p.window[k] + t * (p.window[next] - p.window[k]), k, t};
}

}  // namespace

size_t segment_at(const WindowPath& p, double s) { return point_at(p, s).segment; }

glm::dvec3 world_at(const WindowPath& p, double s) {
  PathPoint at = point_at(p, s);
  size_t next = (at.segment + 1) % p.window.size();
  // 1/d is affine in the window: weigh the ends perspective-correctly.
  double wa = (1 - at.t) / p.depth[at.segment], wb = at.t / p.depth[next];
  return (wa * p.world[at.segment] + wb * p.world[next]) / (wa + wb);
}

VisibilitySample sample_at(const WindowPath& p, double s) {
  PathPoint at = point_at(p, s);
  VisibilitySample v{
      glm::vec2(at.window), p.kind == LineKind::Silhouette ? kSilhouetteSample : kCreaseSample, p.key, {0, 0}, 0, 0};
  if (p.kind == LineKind::Decal) {  // Kalnins et al. 2002, §3, §4.5: the face of the nearer end
    v.kind = kDecalSample;
    v.faces[0] = at.t < 0.5 ? p.front_faces[at.segment].x : p.front_faces[at.segment].y;
  } else if (p.kind == LineKind::Hatching) {  // Kalnins et al. 2002, §6: the faces of both ends
    v.kind = kHatchingSample;
    v.faces[0] = p.front_faces[at.segment].x, v.faces[1] = p.front_faces[at.segment].y;
  } else if (v.kind == kSilhouetteSample) {
    double wrapped = p.closed && p.length_px > 0 ? std::fmod(s, p.length_px) : s;
    v.byte = p.length_px > 0 ? uint32_t(std::clamp(std::floor(255.0 * wrapped / p.length_px), 0.0, 255.0)) : 0;
    v.byte_window = uint32_t(std::min(255.0, std::ceil(2.0 * std::max(2.0, 256.0 / std::max(p.length_px, 1e-9)))));
    if (p.closed) v.byte_window |= 0x100u;  // flag: compare around the seam
  } else {
    v.faces[0] = p.front_faces[at.segment].x, v.faces[1] = p.front_faces[at.segment].y;
  }
  return v;
}

namespace {

constexpr double kWindowMargin = 4;  // px around the window where samples are taken (the test reaches 2)

// Arc lengths of the first round of samples of a path: every `step` px (multiples of it)
// where the path runs within kWindowMargin of the window, and one sample where it leaves or
// enters that, which tests hidden: no run spans a stretch off the window, and such a
// stretch, however long, costs no samples.
std::vector<double> sample_arcs(const WindowPath& p, double step, double width, double height) {
  std::vector<double> s;
  auto add = [&](double at) {
    if (s.empty() || at > s.back()) s.push_back(at);
  };
  size_t n = p.window.size(), segments = p.closed ? n : n - 1;
  for (size_t k = 0; k < segments; ++k) {
    glm::dvec2 a = p.window[k], b = p.window[(k + 1) % n];
    double s0 = p.arc_px[k], length = glm::distance(a, b), t0, t1;
    if (!clip_to_window(a, b, width, height, kWindowMargin, t0, t1)) continue;
    if (t0 > 0) add(s0 + t0 * length);  // enters: on the margin's edge
    for (double i = std::ceil((s0 + t0 * length) / step); i * step <= s0 + t1 * length && i * step < p.length_px; ++i)
      add(i * step);
    if (t1 < 1) add(s0 + t1 * length);  // leaves
  }
  if (s.empty()) s.push_back(0);
  if (!p.closed && s.back() < p.length_px) s.push_back(p.length_px);
  return s;
}

struct Tested {
  double s;
  bool visible;
};

// An interval of a path whose ends disagree, narrowed by bisection.
struct Change {
  uint32_t path;
  Tested a, b;  // a.s < b.s (b.s may pass a closed path's length)
};

// What the samples would take, against the memory budget before any is made: each
// sample's arc length and flag (Tested, and a byte of Visibility::flags), and its record
// three times at most (the first round's batch, a bisection round's, which tests at most
// one sample per change, and the GPU's copy).
void check_visibility_memory(const WindowLines& lines, double step) {
  double samples = 0, length = 0;
  for (const WindowPath& p : lines.paths) samples += first_round_bound(p, step, lines.width, lines.height);
  for (const WindowPath& p : lines.paths) length += p.length_px;
  char what[200];
  std::snprintf(what, sizeof what, "the visibility samples of %zu lines (%.3g px long, every strokes.vis_step_px %g)",
                lines.paths.size(), length, step);
  check_memory_budget(what, samples * double(sizeof(Tested) + 1 + 3 * sizeof(VisibilitySample)));
}

class RunBuilder {
 public:
  RunBuilder(const WindowLines& lines, const StrokesParams& p, const SampleTest& test) : lines_(lines), test_(test) {
    check_visibility_memory(lines, p.vis_step_px);
    for (uint32_t i = 0; i < lines.paths.size(); ++i) {
      std::vector<double> s = sample_arcs(lines.paths[i], p.vis_step_px, lines.width, lines.height);
      first_.push_back(tested_.size());
      for (double at : s) tested_.push_back({at, false}), batch_.push_back(sample_at(lines.paths[i], at));
    }
    first_.push_back(tested_.size());
    out_.flags = run_batch();
    out_.samples = tested_.size();
    for (size_t k = 0; k < tested_.size(); ++k) tested_[k].visible = out_.flags[k];
  }

  Visibility build() {
    std::vector<Change> changes = first_changes();
    while (bisect(changes)) {
    }
    for (uint32_t i = 0; i < lines_.paths.size(); ++i) add_runs(i, changes);
    return std::move(out_);
  }

 private:
  std::vector<uint8_t> run_batch() {
    std::vector<uint8_t> f = batch_.empty() ? std::vector<uint8_t>{} : test_(batch_);
    batch_.clear();
    return f;
  }

  std::vector<Change> first_changes() const {
    std::vector<Change> changes;
    for (uint32_t i = 0; i < lines_.paths.size(); ++i) {
      const WindowPath& p = lines_.paths[i];
      size_t a = first_[i], n = first_[i + 1] - a;
      for (size_t k = 0; k + 1 < n; ++k)
        if (tested_[a + k].visible != tested_[a + k + 1].visible)
          changes.push_back({i, tested_[a + k], tested_[a + k + 1]});
      Tested last = tested_[a + n - 1], wrap = {tested_[a].s + p.length_px, tested_[a].visible};
      if (p.closed && n > 1 && last.visible != wrap.visible) changes.push_back({i, last, wrap});
    }
    return changes;
  }

  // One round: every change still wider than 1 px tested at its midpoint. False when none is.
  bool bisect(std::vector<Change>& changes) {
    std::vector<Change*> open;
    for (Change& c : changes)
      if (c.b.s - c.a.s > kLocatedPx)
        open.push_back(&c), batch_.push_back(sample_at(lines_.paths[c.path], (c.a.s + c.b.s) / 2));
    if (open.empty()) return false;
    std::vector<uint8_t> f = run_batch();
    for (size_t k = 0; k < open.size(); ++k) {
      Tested mid{(open[k]->a.s + open[k]->b.s) / 2, f[k] != 0};
      (mid.visible == open[k]->a.visible ? open[k]->a : open[k]->b) = mid;
    }
    return true;
  }

  // The runs of path i between its located changes.
  void add_runs(uint32_t i, const std::vector<Change>& changes) {
    const WindowPath& p = lines_.paths[i];
    std::vector<Tested> bounds;  // at each change, the side it turns to
    for (const Change& c : changes)
      if (c.path == i) bounds.push_back({(c.a.s + c.b.s) / 2, c.b.visible});
    bool starts_visible = tested_[first_[i]].visible;
    if (bounds.empty()) {
      if (starts_visible) add_run(i, 0, p.length_px, p.closed, false, false);
      return;
    }
    if (!p.closed) {
      if (starts_visible) add_run(i, 0, bounds.front().s, false, false, true);
      for (size_t k = 0; k < bounds.size(); ++k)
        if (bounds[k].visible)
          add_run(i, bounds[k].s, k + 1 < bounds.size() ? bounds[k + 1].s : p.length_px, false, true,
                  k + 1 < bounds.size());
      return;
    }
    for (size_t k = 0; k < bounds.size(); ++k) {  // closed: each run ends at the next change, around the seam
      if (!bounds[k].visible) continue;
      double end = k + 1 < bounds.size() ? bounds[k + 1].s : bounds.front().s + p.length_px;
      add_run(i, bounds[k].s, end, false, true, true);
    }
  }

  void add_run(uint32_t i, double s0, double s1, bool closed, bool occluded_start, bool occluded_end) {
    out_.runs.push_back(run_along(lines_.paths[i], i, s0, s1, closed, occluded_start, occluded_end));
  }

  const WindowLines& lines_;
  const SampleTest& test_;
  std::vector<Tested> tested_;  // the first round, path after path
  std::vector<size_t> first_;   // each path's first sample in tested_, and the end
  std::vector<VisibilitySample> batch_;
  Visibility out_;
};

bool holds(uint32_t value, const VisibilitySample& s) {
  if (value == 0) return false;
  if (s.kind == kDecalSample) return value == s.faces[0];
  if (s.kind == kHatchingSample) return value == s.faces[0] || value == s.faces[1];
  if (s.kind == kCreaseSample) return value == s.key || value == s.faces[0] || value == s.faces[1];
  if (value >> 8 != s.key) return false;
  int d = std::abs(int(value & 0xffu) - int(s.byte));
  if (s.byte_window & 0x100u) d = std::min(d, 256 - d);
  return d <= int(s.byte_window & 0xffu);
}

}  // namespace

bool sample_visible(const ImageU32& keys, const VisibilitySample& s) {
  bool near_window = s.window.x > -2 && s.window.y > -2 && s.window.x < keys.width + 2 && s.window.y < keys.height + 2;
  if (!near_window) return false;  // NaN too
  int x = int(std::floor(s.window.x)), y = int(std::floor(s.window.y)), r = s.kind == kHatchingSample ? 2 : 1;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      int px = x + dx, py = y + dy;
      if (px >= 0 && py >= 0 && px < keys.width && py < keys.height && holds(keys.at(px, py), s)) return true;
    }
  return false;
}

bool sample_visible(const ImageU32& keys, const ImageU32* crease_keys, const VisibilitySample& s) {
  if (sample_visible(keys, s)) return true;
  if (!crease_keys || s.kind != kCreaseSample) return false;
  int x = int(std::floor(s.window.x)), y = int(std::floor(s.window.y));  // NaN: not in the window
  return x >= 0 && y >= 0 && x < crease_keys->width && y < crease_keys->height && holds(crease_keys->at(x, y), s);
}

double first_round_bound(const WindowPath& p, double step, double width, double height) {
  // Clear of the margin's edges by more than rounding moves a point: no edge sample.
  auto clear = [&](glm::dvec2 q) {
    const double in = kWindowMargin - 1e-3;
    return q.x > -in && q.y > -in && q.x < width + in && q.y < height + in;
  };
  double bound = 3;
  size_t n = p.window.size(), segments = p.closed ? n : n - 1;
  for (size_t k = 0; k < segments; ++k) {
    glm::dvec2 a = p.window[k], b = p.window[(k + 1) % n];
    double t0, t1;
    if (clip_to_window(a, b, width, height, kWindowMargin, t0, t1))
      bound += (t1 - t0) * glm::distance(a, b) / step + (clear(a) && clear(b) ? 2 : 4);
  }
  return bound;
}

double length_in_margin(const WindowPath& p, double width, double height) {
  double length = 0;
  size_t n = p.window.size(), segments = p.closed ? n : n - 1;
  for (size_t k = 0; k < segments; ++k) {
    glm::dvec2 a = p.window[k], b = p.window[(k + 1) % n];
    double t0, t1;
    if (clip_to_window(a, b, width, height, kWindowMargin, t0, t1)) length += (t1 - t0) * glm::distance(a, b);
  }
  return length;
}

VisibleRun run_along(const WindowPath& p, uint32_t i, double s0, double s1, bool closed, bool occluded_start,
                     bool occluded_end) {
  VisibleRun run{i, s0, s1, closed, occluded_start, occluded_end, {}};
  if (closed) {
    run.window = p.window;
    return run;
  }
  run.window.push_back(point_at(p, s0).window);
  for (int lap = 0; lap < (p.closed ? 2 : 1); ++lap)  // a closed path's run may pass the seam once
    for (size_t k = 0; k < p.window.size(); ++k) {
      double s = p.arc_px[k] + lap * p.length_px;
      if (s > s0 && s < s1) run.window.push_back(p.window[k]);
    }
  run.window.push_back(point_at(p, s1).window);
  return run;
}

VisibleRun run_from_row(const WindowPath& path, uint32_t i, double s0, double s1, uint32_t flags, bool with_window) {
  const bool closed = flags & 1u, occluded_start = flags & 2u, occluded_end = flags & 4u;
  s0 = occluded_start ? s0 : 0.0, s1 = occluded_end ? s1 : path.length_px;
  if (!with_window) return {i, s0, s1, closed, occluded_start, occluded_end, {}};
  return run_along(path, i, s0, s1, closed, occluded_start, occluded_end);
}

Visibility visible_runs(const WindowLines& lines, const StrokesParams& p, const SampleTest& test) {
  return RunBuilder(lines, p, test).build();
}

Image flags_image(const std::vector<uint8_t>& flags) {
  Image out = table_image(flags.size(), 1);
  for (size_t k = 0; k < flags.size(); ++k) out.data[k] = flags[k] ? 1.0f : 0.0f;
  return out;
}

std::pair<Image, Image> run_tables(const std::vector<VisibleRun>& runs) {
  Image paths = table_image(runs.size(), 2), ends = table_image(runs.size(), 2);
  for (size_t k = 0; k < runs.size(); ++k) {
    const VisibleRun& r = runs[k];
    paths.data[2 * k] = float(r.path + 1);
    paths.data[2 * k + 1] = float(r.closed + 2 * r.occluded_start + 4 * r.occluded_end);
    ends.data[2 * k] = float(r.s0), ends.data[2 * k + 1] = float(r.s1);
  }
  return {std::move(paths), std::move(ends)};
}

}  // namespace plumbago

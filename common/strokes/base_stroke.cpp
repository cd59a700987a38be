#include "common/strokes/base_stroke.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace plumbago {

namespace {

constexpr double kSamePoint = 1e-6;   // px: closer input points are one point (1.)
constexpr double kPiecesPerPx = 4.0;  // dense pieces per px of control polygon (2.)
constexpr int kMinPieces = 4, kMaxPieces = 4096;
constexpr double kMaxSamples = 1e7;      // refuse runs that would take more samples
constexpr double kSameArcLength = 1e-9;  // px: sample arc lengths closer than this are one
// px: an even sample this close to a pen change, or a change this close to an end, is dropped:
// shorter segments have no reliable direction in float (tests/strokes/stroke_ribbon_test.cpp)
constexpr double kNearPenChange = 0.05;
constexpr double kDegenerate = 1e-9;  // px: shorter segments have no direction of their own

// 1. Finite points, repeats merged; a closed run's last point equal to its first dropped.
std::vector<glm::dvec2> distinct_points(const std::vector<glm::dvec2>& in, bool closed) {
  std::vector<glm::dvec2> out;
  for (const glm::dvec2& p : in)
    if (std::isfinite(p.x) && std::isfinite(p.y) && (out.empty() || glm::distance(out.back(), p) > kSamePoint))
      out.push_back(p);
  if (closed && out.size() > 1 && glm::distance(out.front(), out.back()) <= kSamePoint) out.pop_back();
  return out;
}

// A cubic Hermite span: p(t) = h00 p0 + h10 m0 + h01 p1 + h11 m1, t in [0, 1].
struct Span {
  glm::dvec2 p0, m0, p1, m1;

  glm::dvec2 at(double t) const {
    double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1;
  }
  // Length of the Bézier control polygon p0, p0 + m0/3, p1 - m1/3, p1.
  double control_length() const {
    return glm::length(m0) / 3 + glm::distance(p0 + m0 / 3.0, p1 - m1 / 3.0) + glm::length(m1) / 3;
  }
};

// v_i = (p_{i+1} - p_{i-1}) / (|p_{i+1} - p_i| + |p_i - p_{i-1}|): the tangent per px of chord.
glm::dvec2 vertex_velocity(glm::dvec2 prev, glm::dvec2 here, glm::dvec2 next) {
  return (next - prev) / (glm::distance(next, here) + glm::distance(here, prev));
}

// The spans of the non-uniform Catmull-Rom spline through p (>= 2 distinct points;
// closed needs >= 3), with parabolic end slopes when open.
std::vector<Span> catmull_rom_spans(const std::vector<glm::dvec2>& p, bool closed) {
  size_t n = p.size(), spans = closed ? n : n - 1;
  if (n == 2) return {{p[0], p[1] - p[0], p[1], p[1] - p[0]}};
  auto velocity = [&](size_t i) { return vertex_velocity(p[(i + n - 1) % n], p[i], p[(i + 1) % n]); };
  std::vector<Span> out;
  for (size_t i = 0; i < spans; ++i) {
    glm::dvec2 a = p[i], b = p[(i + 1) % n];
    double d = glm::distance(a, b);
    bool first = !closed && i == 0, last = !closed && i + 1 == spans;
    glm::dvec2 m0 = first ? glm::dvec2(0) : velocity(i) * d;
    glm::dvec2 m1 = last ? glm::dvec2(0) : velocity((i + 1) % n) * d;
    if (first) m0 = 2.0 * (b - a) - m1;  // parabolic end slopes
    if (last) m1 = 2.0 * (b - a) - m0;
    out.push_back({a, m0, b, m1});
  }
  return out;
}

// 2. The spline as a dense polyline and its cumulative arc length.
struct DenseCurve {
  std::vector<glm::dvec2> points;
  std::vector<double> s;

  double length() const { return s.back(); }

  // The point at arc length `at` (clamped to [0, length]), linear between dense points.
  glm::dvec2 point_at(double at) const {
    at = std::clamp(at, 0.0, length());
    size_t i = size_t(std::upper_bound(s.begin(), s.end(), at) - s.begin());
    i = std::clamp<size_t>(i, 1, s.size() - 1) - 1;
    double piece = s[i + 1] - s[i];
    return piece > 0 ? glm::mix(points[i], points[i + 1], (at - s[i]) / piece) : points[i];
  }
};

DenseCurve dense_curve(const std::vector<Span>& spans) {
  DenseCurve c{{spans.front().p0}, {0.0}};
  for (const Span& span : spans) {
    double pieces = std::ceil(kPiecesPerPx * span.control_length());
    int m = int(std::clamp(pieces, double(kMinPieces), double(kMaxPieces)));
    for (int k = 1; k <= m; ++k) {
      glm::dvec2 q = span.at(double(k) / m);
      c.s.push_back(c.s.back() + glm::distance(c.points.back(), q));
      c.points.push_back(q);
    }
  }
  return c;
}

// 3. k L / n for k = 0..n, n = ceil(L / spacing): equal steps of spacing or a little less.
std::vector<double> even_arc_lengths(double length, double spacing) {
  double steps = std::ceil(length / spacing - 1e-9);
  if (!(steps <= kMaxSamples))
    throw std::invalid_argument("a run of " + std::to_string(length) + " px would take more than 1e7 samples");
  int n = std::max(1, int(steps));
  std::vector<double> s;
  for (int k = 0; k <= n; ++k) s.push_back(length * k / n);
  return s;
}

std::vector<glm::dvec2> points_at(const DenseCurve& c, const std::vector<double>& s) {
  std::vector<glm::dvec2> out;
  for (double at : s) out.push_back(c.point_at(at));
  return out;
}

// 4. Where the offsets are stamped along a run: at s itself, or, where the run carries a
// brush parameter and the example repeats, at the brush parameter t(s) (Kalnins et al. 2003:
// the offsets follow the texture over the surface). An example made to span its run stays on s.
struct StampParameter {
  const BrushParameter* knots = nullptr;  // t over polyline arc length; null: s
  double polyline_per_spline = 1.0;

  double at(double s) const { return knots ? brush_t(*knots, s * polyline_per_spline) : s; }

  // The range of at(s) over s in [0, L]: its ends' and the knots' between.
  std::pair<double, double> range(double L) const {
    double lo = std::min(at(0), at(L)), hi = std::max(at(0), at(L));
    for (const glm::dvec2& k : knots ? *knots : BrushParameter{})
      if (k.x > 0 && k.x < L * polyline_per_spline) lo = std::min(lo, k.y), hi = std::max(hi, k.y);
    return {lo, hi};
  }

  // The arc lengths where at(s) = c: on each piece of the knots (brush_t's, the first and last
  // extended), where it crosses c.
  std::vector<double> where(double c) const {
    if (!knots) return {c};
    std::vector<double> out;
    const BrushParameter& k = *knots;
    const double inf = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i + 1 < k.size(); ++i) {
      if (!(k[i + 1].x > k[i].x) || k[i + 1].y == k[i].y) continue;  // a jump, or flat: no crossing
      double x = k[i].x + (c - k[i].y) * (k[i + 1].x - k[i].x) / (k[i + 1].y - k[i].y);
      double from = i == 0 ? -inf : k[i].x, to = i + 2 == k.size() ? inf : k[i + 1].x;  // [from, to)
      if (x >= from && x < to) out.push_back(x / polyline_per_spline);
    }
    return out;
  }
};

// 4. The arc lengths in (0, L) where the pen lifts or lands: the ends of each lift of
// nonzero length, (k + t_i) L_drawn to (k + t_next) L_drawn, in every period k over the
// stamp parameter's range (an example that does not repeat: k = 0, and a lift from its last
// offset does not end), each where the stamp parameter takes it.
std::vector<double> pen_changes(const OffsetExample& e, double length, const StampParameter& stamp) {
  std::vector<double> out;
  const auto& o = e.offsets;
  auto [lo, hi] = stamp.range(length);
  double first = e.repeats ? std::floor(lo / e.length_px) - 1 : 0, last = e.repeats ? std::floor(hi / e.length_px) : 0;
  double after_last = e.repeats ? o[0].t + 1 : std::numeric_limits<double>::infinity();  // held: no end
  for (double k = first; k <= last; ++k)
    for (size_t i = 0; i < o.size(); ++i) {
      double next_t = i + 1 < o.size() ? o[i + 1].t : after_last;
      if (!o[i].pen_up || !(next_t > o[i].t)) continue;
      for (double c : {(k + o[i].t) * e.length_px, (k + next_t) * e.length_px})
        for (double s : stamp.where(c))
          if (s > 0 && s < length) out.push_back(s);
    }
  return out;
}

// True when `s` lies within kNearPenChange of one of the sorted `changes`.
bool near_any(double s, const std::vector<double>& changes) {
  auto at = std::lower_bound(changes.begin(), changes.end(), s - kNearPenChange);
  return at != changes.end() && *at < s + kNearPenChange;
}

// 3. and 4.: the even samples plus the pen changes, sorted, without repeats; an even sample
// near a change gives way to it, a change near an end of the run to the end.
std::vector<double> sample_arc_lengths(double length, const StrokeStyle& style, const StampParameter& stamp) {
  std::vector<double> s = even_arc_lengths(length, style.sample_px);
  if (!style.offsets) return s;
  std::vector<double> changes = pen_changes(*style.offsets, length, stamp);
  std::erase_if(changes, [&](double c) { return c < kNearPenChange || c > length - kNearPenChange; });
  std::sort(changes.begin(), changes.end());
  std::erase_if(s, [&](double at) { return at > 0 && at < length && near_any(at, changes); });
  s.insert(s.end(), changes.begin(), changes.end());
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end(), [](double a, double b) { return b - a < kSameArcLength; }), s.end());
  return s;
}

glm::dvec2 left_normal(glm::dvec2 d) { return {-d.y, d.x}; }

// The left unit normal of each segment p_j -> p_{j+1}; a degenerate segment takes the
// previous one's (the first valid one's, before any); empty when all are degenerate.
std::vector<glm::dvec2> segment_normals(const std::vector<glm::dvec2>& p) {
  if (p.size() < 2) return {};
  std::vector<glm::dvec2> out(p.size() - 1);
  std::vector<bool> valid(out.size(), false);
  std::optional<glm::dvec2> previous;
  for (size_t j = 0; j < out.size(); ++j) {
    glm::dvec2 d = p[j + 1] - p[j];
    double len = glm::length(d);
    valid[j] = len > kDegenerate;
    if (valid[j]) previous = left_normal(d / len);
    if (previous) out[j] = *previous;
  }
  if (!previous) return {};
  size_t first = size_t(std::find(valid.begin(), valid.end(), true) - valid.begin());
  std::fill(out.begin(), out.begin() + std::ptrdiff_t(first), out[first]);
  return out;
}

// 6. Miter-free vertex normals: the normalized sum of the normals of the segments on
// either side (cyclic: p's last point is its first again); a hairpin takes the previous.
std::vector<glm::dvec2> vertex_normals(const std::vector<glm::dvec2>& p, bool cyclic) {
  std::vector<glm::dvec2> seg = segment_normals(p);
  if (seg.empty()) return {};
  size_t m = p.size();
  std::vector<glm::dvec2> out(m);
  for (size_t i = 0; i < m; ++i) {
    bool has_prev = i > 0 || cyclic, has_next = i + 1 < m || cyclic;
    glm::dvec2 prev = i > 0 ? seg[i - 1] : seg.back(), next = i + 1 < m ? seg[i] : seg.front();
    glm::dvec2 sum = (has_prev ? prev : glm::dvec2(0)) + (has_next ? next : glm::dvec2(0));
    double len = glm::length(sum);
    out[i] = len > 1e-9 ? sum / len : (has_prev ? prev : next);
  }
  return out;
}

// 5. The factors of Kalnins et al. 2002, §4.1, each 1 outside its range.
double taper(double dl, double T) { return dl < T ? std::sqrt(std::max(0.0, 1 - std::pow((T - dl) / T, 2))) : 1.0; }
double fade(double dl, double F) { return dl < F ? std::pow(std::max(0.0, 1 - std::pow((F - dl) / F, 2)), 1.5) : 1.0; }
double halo_base(double dh, double H) {
  return dh < H ? std::max(0.0, 1 - std::pow((H - dh) / H, 2)) : 1.0;
}  // 1 - h^2
double flare(double dl, double L, double f) { return 1 + f * (1 - 2 * dl / L); }

// Distance from arc length s to the nearer end caused by occlusion; infinite when none.
double occluded_end_distance(double s, double L, const StrokeRun& run) {
  double d = std::numeric_limits<double>::infinity();
  if (run.occluded_start) d = std::min(d, s);
  if (run.occluded_end) d = std::min(d, L - s);
  return d;
}

struct Shape {
  double width, alpha;
};

// 5. Width and alpha at arc length s of a run of length L, with the offsets' pressure.
Shape shape_at(double s, double L, bool has_ends, const StrokeRun& run, const StrokeStyle& st, double pressure) {
  double w = st.width_px, a = st.alpha;
  if (has_ends) {
    double dl = std::max(0.0, std::min(s, L - s)), dh = occluded_end_distance(s, L, run);
    w *= taper(dl, st.taper_px) * flare(dl, L, st.flare) * std::pow(halo_base(dh, st.halo_px), 0.25);
    a *= fade(dl, st.fade_px) * std::pow(halo_base(dh, st.halo_px), 5);
  }
  if (st.pressure_width) w *= pressure;
  if (st.pressure_alpha) a *= pressure;
  if (w < 2) return {2.0, a * w * w / 4};  // thin-stroke rule: drawn 2 px wide
  return {w, a};
}

// The length of the polyline through p (a loop's closing segment included).
double polyline_length(const std::vector<glm::dvec2>& p, bool closed) {
  double length = closed ? glm::distance(p.back(), p.front()) : 0.0;
  for (size_t j = 0; j + 1 < p.size(); ++j) length += glm::distance(p[j], p[j + 1]);
  return length;
}

std::vector<StrokeSample> ribbon_samples(const StrokeRun& run, const StrokeStyle& style, const DenseCurve& curve,
                                         double polyline_px, bool closed) {
  double L = curve.length();
  bool brushed = run.brush.size() >= 2;  // fewer knots: t = s (brush_t)
  StampParameter brush{brushed ? &run.brush : nullptr, brushed ? polyline_px / L : 1.0};
  StampParameter along = style.offsets && style.offsets->repeats ? brush : StampParameter{};
  std::vector<double> s = sample_arc_lengths(L, style, along);
  std::vector<glm::dvec2> base = points_at(curve, s);
  std::vector<glm::dvec2> normals = vertex_normals(base, closed);
  if (normals.empty()) return {};
  auto stamp = [&](double at) {
    return style.offsets ? rubber_stamp(*style.offsets, along.at(at), L) : StampedOffset{0.0, 1.0, true};
  };
  std::vector<StrokeSample> out;
  for (size_t j = 0; j < s.size(); ++j) {
    StampedOffset o = stamp(s[j]);
    Shape shape = shape_at(s[j], L, !closed, run, style, o.pressure);
    bool down = j + 1 < s.size() && stamp(0.5 * (s[j] + s[j + 1])).pen_down;
    out.push_back(
        {base[j] + normals[j] * o.displacement_px, base[j], s[j], brush.at(s[j]), shape.width, shape.alpha, down});
  }
  return out;
}

RibbonVertex vertex(glm::dvec2 p, double u, double v, double alpha) {
  return {glm::vec2(p), glm::vec2(float(u), float(v)), float(alpha)};
}

// 6. The triangles of the strip through samples [a, b] (b > a), appended to `out`.
void append_strip(const std::vector<StrokeSample>& samples, size_t a, size_t b, bool cyclic, double period,
                  std::vector<RibbonVertex>& out) {
  std::vector<glm::dvec2> p;
  for (size_t j = a; j <= b; ++j) p.push_back(samples[j].position);
  std::vector<glm::dvec2> n = vertex_normals(p, cyclic);
  if (n.empty()) return;
  std::vector<RibbonVertex> strip;  // R0 L0 R1 L1 ...
  for (size_t j = a; j <= b; ++j) {
    const StrokeSample& q = samples[j];
    glm::dvec2 half = n[j - a] * (q.width / 2);
    strip.push_back(vertex(q.position - half, q.t / period, 0.0, q.alpha));
    strip.push_back(vertex(q.position + half, q.t / period, 1.0, q.alpha));
  }
  for (size_t k = 0; k + 2 < strip.size(); ++k) {  // GL's strip order: odd triangles swap their first two
    if (k % 2 == 0)
      out.insert(out.end(), {strip[k], strip[k + 1], strip[k + 2]});
    else
      out.insert(out.end(), {strip[k + 1], strip[k], strip[k + 2]});
  }
}

}  // namespace

std::vector<glm::dvec2> catmull_rom_resample(const std::vector<glm::dvec2>& points, double spacing_px, bool closed) {
  if (!(spacing_px > 0) || !std::isfinite(spacing_px))
    throw std::invalid_argument("catmull_rom_resample: spacing " + std::to_string(spacing_px) + " px is not positive");
  std::vector<glm::dvec2> p = distinct_points(points, closed);
  if (p.size() < 2) return p;
  bool loop = closed && p.size() >= 3;
  DenseCurve curve = dense_curve(catmull_rom_spans(p, loop));
  std::vector<double> s = even_arc_lengths(curve.length(), spacing_px);
  if (loop) s.pop_back();  // the first sample again
  return points_at(curve, s);
}

double brush_t(const BrushParameter& knots, double s) {
  if (knots.size() < 2) return s;
  auto it = std::upper_bound(knots.begin(), knots.end(), s, [](double x, const glm::dvec2& k) { return x < k.x; });
  size_t k = std::clamp(size_t(it - knots.begin()), size_t(1), knots.size() - 1) - 1;
  const glm::dvec2 &a = knots[k], &b = knots[k + 1];
  return b.x > a.x ? a.y + (s - a.x) * (b.y - a.y) / (b.x - a.x) : b.y;  // two knots at one s: a jump
}

StampedOffset rubber_stamp(const OffsetExample& example, double s, double run_length) {
  const auto& o = example.offsets;
  double t = s / example.length_px;
  double scale = example.scales ? std::min(run_length / example.length_px, 1.0) : 1.0;
  if (example.repeats)
    t -= std::floor(t);  // (s mod L_drawn) / L_drawn
  else
    t = std::clamp(t, 0.0, 1.0);
  // Segment i runs from offset i to the next, the last one to the first of the next period.
  size_t count = size_t(
      std::upper_bound(o.begin(), o.end(), t, [](double x, const StrokeOffset& e) { return x < e.t; }) - o.begin());
  if (!example.repeats && (count == 0 || count == o.size())) {  // held before the first offset, after the last
    const StrokeOffset& held = count == 0 ? o.front() : o.back();
    return {held.displacement_px * scale, held.pressure, count == 0 || !held.pen_up};
  }
  if (count == 0) t += 1;  // before the first offset: on the last segment, from the period before
  size_t i = (count + o.size() - 1) % o.size();
  bool wraps = i + 1 == o.size();
  const StrokeOffset& next = o[wraps ? 0 : i + 1];
  double t_next = wraps ? next.t + 1 : next.t;
  double f = t_next > o[i].t ? (t - o[i].t) / (t_next - o[i].t) : 0.0;
  return {std::lerp(o[i].displacement_px, next.displacement_px, f) * scale, std::lerp(o[i].pressure, next.pressure, f),
          !o[i].pen_up};
}

BaseStrokeSamples base_stroke_samples(const StrokeRun& run, const StrokeStyle& style) {
  validate_stroke_style(style, "base_stroke");
  std::vector<glm::dvec2> p = distinct_points(run.points, run.closed);
  if (p.size() < 2) return {};
  bool closed = run.closed && p.size() >= 3;
  DenseCurve curve = dense_curve(catmull_rom_spans(p, closed));
  return {ribbon_samples(run, style, curve, polyline_length(p, closed), closed), curve.length(), closed};
}

Ribbon ribbon(const BaseStrokeSamples& stroke, const StrokeStyle& style) {
  Ribbon out{{}, glm::vec3(style.color_r, style.color_g, style.color_b)};
  const std::vector<StrokeSample>& samples = stroke.samples;
  if (samples.size() < 2) return out;
  bool whole = std::all_of(samples.begin(), samples.end() - 1, [](const StrokeSample& q) { return q.pen_down_after; });
  for (size_t a = 0; a + 1 < samples.size();) {  // each maximal run of drawn segments is one strip
    if (!samples[a].pen_down_after) {
      ++a;
      continue;
    }
    size_t b = a + 1;
    while (b + 1 < samples.size() && samples[b].pen_down_after) ++b;
    append_strip(samples, a, b, stroke.closed && whole, style.texture_period_px, out.triangles);
    a = b;
  }
  return out;
}

Ribbon base_stroke(const StrokeRun& run, const StrokeStyle& style) {
  return ribbon(base_stroke_samples(run, style), style);
}

}  // namespace plumbago

#include "common/curvature/ball_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace plumbago {
namespace {

double cross2(glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; }

// Where the line p + t (q - p) is within distance r of c: t in [t0, t1]. False if nowhere.
template <class V>
bool ball_interval(const V& p, const V& q, const V& c, double r, double& t0, double& t1) {
  V d = q - p, m = p - c;
  double a = glm::dot(d, d), b = glm::dot(m, d), k = glm::dot(m, m) - r * r;
  if (a <= 0) return false;
  double disc = b * b - a * k;
  if (disc <= 0) return false;
  double s = std::sqrt(disc);
  t0 = (-b - s) / a;
  t1 = (-b + s) / a;
  return true;
}

double angle2(glm::dvec2 u, glm::dvec2 v) { return std::atan2(cross2(u, v), glm::dot(u, v)); }

// The angle from u to v within 0.071 rad, without atan2: the "diamond" pseudo-angle
// y / (|x| + |y|) of z = (u.v, u x v), scaled to radians (exact at multiples of pi/4).
double rough_angle2(glm::dvec2 u, glm::dvec2 v) {
  double x = glm::dot(u, v), y = cross2(u, v), norm = std::abs(x) + std::abs(y);
  if (!(norm > 0)) return 0;
  double quarter = 0.5 * std::numbers::pi * y / norm;  // in [-pi/2, pi/2]
  return x >= 0 ? quarter : std::copysign(std::numbers::pi, y) - quarter;
}

// Twice the signed area of triangle ∩ disk (disk at the origin, radius r), summed along
// the triangle's boundary, cut where it crosses the circle: a piece inside the disk adds
// its triangle with the origin (a cross product), a piece outside the disk's sector over
// it (r² times its angle). Consecutive outside pieces form a run from `from` to `to`
// whose angle needs one atan2: the angle from `from` to `to` is the sum of the pieces'
// angles up to whole turns, and the pieces' rough angles (each within 0.071 rad) pick
// the turn.
class BoundaryWalk {
 public:
  explicit BoundaryWalk(double r) : r_(r), r2_(r * r) {}

  // Side uv, whose corners are inside the disk or not.
  void side(const glm::dvec2& u, const glm::dvec2& v, bool u_in, bool v_in) {
    if (u_in && v_in) return inside(u, v);
    double t0, t1;
    if (!ball_interval(u, v, glm::dvec2(0), r_, t0, t1) || t1 <= 0 || t0 >= 1) return outside(u, v);
    glm::dvec2 a = u_in ? u : u + t0 * (v - u), b = v_in ? v : u + t1 * (v - u);
    if (!u_in) outside(u, a);
    inside(a, b);
    if (!v_in) outside(b, v);
  }

  double twice_area() {
    end_run();
    return twice_area_;
  }

 private:
  void inside(const glm::dvec2& a, const glm::dvec2& b) {
    end_run();
    twice_area_ += cross2(a, b);
  }
  void outside(const glm::dvec2& a, const glm::dvec2& b) {
    if (pieces_++ == 0) from_ = a;
    to_ = b;
    rough_ += rough_angle2(a, b);
  }
  void end_run() {
    if (pieces_ == 0) return;
    double angle = angle2(from_, to_);
    if (pieces_ > 1) angle += 2 * std::numbers::pi * std::nearbyint((rough_ - angle) / (2 * std::numbers::pi));
    twice_area_ += r2_ * angle;
    pieces_ = 0, rough_ = 0;
  }

  double r_, r2_, twice_area_ = 0, rough_ = 0;
  glm::dvec2 from_{0}, to_{0};
  int pieces_ = 0;
};

// Signed area of triangle ∩ disk(origin, r). The walk starts at a corner inside the disk
// where there is one, so that no run is split in two (two atan2) at the start.
double disk_triangle_area(const glm::dvec2 (&corner)[3], double r) {
  bool in[3];
  for (int k = 0; k < 3; ++k) in[k] = glm::dot(corner[k], corner[k]) <= r * r;
  const int first = in[0] ? 0 : in[1] ? 1 : in[2] ? 2 : 0;
  BoundaryWalk walk(r);
  for (int j = 0; j < 3; ++j) {
    int k = (first + j) % 3, l = (k + 1) % 3;
    walk.side(corner[k], corner[l], in[k], in[l]);
  }
  return 0.5 * walk.twice_area();
}

}  // namespace

double segment_fraction_in_ball(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& c, double r) {
  double t0, t1;
  if (!ball_interval(p, q, c, r, t0, t1)) return 0;
  return std::max(std::min(t1, 1.0) - std::max(t0, 0.0), 0.0);
}

double segment_length_in_ball(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& c, double r) {
  return segment_fraction_in_ball(p, q, c, r) * glm::length(q - p);
}

double triangle_area_in_ball(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d, const glm::dvec3& c,
                             double r) {
  glm::dvec3 N = glm::cross(b - a, d - a);
  return triangle_area_in_ball(a, b, d, c, r, N, glm::length(N));
}

double triangle_area_in_ball(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d, const glm::dvec3& c,
                             double r, const glm::dvec3& N, double N_length) {
  if (!(N_length > 0)) return 0;
  glm::dvec3 n = N / N_length;
  double h = glm::dot(c - a, n);
  if (std::abs(h) >= r) return 0;
  double rho = std::sqrt(r * r - h * h);
  glm::dvec3 x = glm::normalize(b - a), y = glm::cross(n, x), o = c - h * n;
  auto planar = [&](const glm::dvec3& p) { return glm::dvec2(glm::dot(p - o, x), glm::dot(p - o, y)); };
  const glm::dvec2 corner[3] = {planar(a), planar(b), planar(d)};
  return std::clamp(disk_triangle_area(corner, rho), 0.0, 0.5 * N_length);
}

}  // namespace plumbago

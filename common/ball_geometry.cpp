#include "common/ball_geometry.hpp"

#include <algorithm>
#include <cmath>

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

// Signed area of disk(origin, r) ∩ triangle(origin, u, v): the part of segment uv inside
// the disk contributes its triangle with the origin, the parts outside a circular sector.
// Each term's angle is below pi, so atan2 is never ambiguous.
double disk_sector_triangle_area(const glm::dvec2& u, const glm::dvec2& v, double r) {
  double r2 = r * r;
  bool u_in = glm::dot(u, u) <= r2, v_in = glm::dot(v, v) <= r2;
  if (u_in && v_in) return 0.5 * cross2(u, v);
  double t0, t1;
  if (!ball_interval(u, v, glm::dvec2(0), r, t0, t1) || t1 <= 0 || t0 >= 1) return 0.5 * r2 * angle2(u, v);
  glm::dvec2 a = u_in ? u : u + t0 * (v - u), b = v_in ? v : u + t1 * (v - u);
  double area = 0.5 * cross2(a, b);
  if (!u_in) area += 0.5 * r2 * angle2(u, a);
  if (!v_in) area += 0.5 * r2 * angle2(b, v);
  return area;
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
  glm::dvec3 n = glm::cross(b - a, d - a);
  double twice_area = glm::length(n);
  if (!(twice_area > 0)) return 0;
  n /= twice_area;
  double h = glm::dot(c - a, n);
  if (std::abs(h) >= r) return 0;
  double rho = std::sqrt(r * r - h * h);
  glm::dvec3 x = glm::normalize(b - a), y = glm::cross(n, x), o = c - h * n;
  auto planar = [&](const glm::dvec3& p) { return glm::dvec2(glm::dot(p - o, x), glm::dot(p - o, y)); };
  glm::dvec2 pa = planar(a), pb = planar(b), pd = planar(d);
  double area = disk_sector_triangle_area(pa, pb, rho) + disk_sector_triangle_area(pb, pd, rho) +
                disk_sector_triangle_area(pd, pa, rho);
  return std::clamp(area, 0.0, 0.5 * twice_area);
}

}  // namespace plumbago

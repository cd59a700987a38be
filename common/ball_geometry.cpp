#include "common/ball_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {
namespace {

constexpr double kPi = 3.14159265358979323846;

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
  double quarter = 0.5 * kPi * y / norm;  // in [-pi/2, pi/2]
  return x >= 0 ? quarter : std::copysign(kPi, y) - quarter;
}

// The boundary of the triangle in the disk's plane (disk at the origin), cut where it
// crosses the circle: a piece inside the disk adds its triangle with the origin, a
// piece outside adds the disk's sector over it (Σ signed areas = area of triangle ∩ disk).
struct BoundaryPiece {
  glm::dvec2 from, to;
  bool outside;
};

// The pieces of side uv: inside the disk, outside, or outside-inside-outside.
int side_pieces(const glm::dvec2& u, const glm::dvec2& v, double r, BoundaryPiece* out) {
  double r2 = r * r;
  bool u_in = glm::dot(u, u) <= r2, v_in = glm::dot(v, v) <= r2;
  if (u_in && v_in) return out[0] = {u, v, false}, 1;
  double t0, t1;
  if (!ball_interval(u, v, glm::dvec2(0), r, t0, t1) || t1 <= 0 || t0 >= 1) return out[0] = {u, v, true}, 1;
  glm::dvec2 a = u_in ? u : u + t0 * (v - u), b = v_in ? v : u + t1 * (v - u);
  int n = 0;
  if (!u_in) out[n++] = {u, a, true};
  out[n++] = {a, b, false};
  if (!v_in) out[n++] = {b, v, true};
  return n;
}

// Sum of the angles of consecutive outside pieces (a run from `from` to `to` along the
// triangle's boundary) with one atan2: the angle from `from` to `to` is that sum up to
// whole turns, and the pieces' rough angles (each within 0.071 rad) pick the turn.
struct OutsideRun {
  glm::dvec2 from, to;
  double rough = 0;
  int pieces = 0;
  void add(const BoundaryPiece& p) {
    if (pieces++ == 0) from = p.from;
    to = p.to;
    rough += rough_angle2(p.from, p.to);
  }
  double angle() const {
    double principal = angle2(from, to);
    return principal + 2 * kPi * std::round((rough - principal) / (2 * kPi));
  }
};

// Signed area of triangle (u, v, w) ∩ disk(origin, r), as the sum over its boundary
// pieces, with one atan2 per run of outside pieces instead of one per piece.
double disk_triangle_area(const glm::dvec2 (&corner)[3], double r) {
  BoundaryPiece piece[9];
  int n = 0;
  for (int k = 0; k < 3; ++k) n += side_pieces(corner[k], corner[(k + 1) % 3], r, piece + n);
  int first = 0;  // after an inside piece, so that no run is split in two (two atan2) at the start
  for (int i = 0; i < n; ++i)
    if (!piece[i].outside) {
      first = i + 1;
      break;
    }
  double twice_area = 0, sector_angle = 0;
  OutsideRun run;
  for (int j = 0; j < n; ++j) {
    const BoundaryPiece& p = piece[(first + j) % n];
    if (p.outside) {
      run.add(p);
      continue;
    }
    if (run.pieces) sector_angle += run.angle(), run = {};
    twice_area += cross2(p.from, p.to);
  }
  if (run.pieces) sector_angle += run.angle();
  return 0.5 * (twice_area + r * r * sector_angle);
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

#include "tests/support/analytic_surfaces.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include "common/util/random.hpp"

namespace plumbago::testing {
namespace {

using std::numbers::pi;

// Of a cell, per grid direction. A triangle of a jittered unit grid keeps at least
// 1 - 6 kJitter of its doubled area, so below 1/6 none flips.
constexpr double kJitter = 0.15;
// Strongly irregular meshes (issue 19): a spread of 0.9 of a cell, so triangles fold.
constexpr double kStrongJitter = 0.45;

const char* meshing_name(Meshing m) {
  return m == Meshing::Regular ? "regular" : m == Meshing::Irregular ? "irregular" : "strong";
}
double jitter(Meshing m) { return m == Meshing::Strong ? kStrongJitter : kJitter; }

// Quad (a, b, c, d), counter-clockwise seen from outside, as two triangles: diagonal a-c
// on regular meshes, a random one on irregular meshes.
void add_quad(Mesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d, Meshing meshing, Rng& rng) {
  if (meshing != Meshing::Regular && rng.uniform() < 0.5) {
    mesh.triangles.push_back({a, b, d});
    mesh.triangles.push_back({b, c, d});
  } else {
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
  }
}

// A (nu x nv)-cell grid over [0,1]^2, wrapping in u and/or v, mapped by `map(u, v)`
// with d(map)/du x d(map)/dv pointing outside. Irregular: parameters jittered (not
// across an open border).
template <class Map>
Mesh grid_mesh(int nu, int nv, bool wrap_u, bool wrap_v, Map map, Meshing meshing, Rng& rng) {
  Mesh mesh;
  int cu = wrap_u ? nu : nu + 1, cv = wrap_v ? nv : nv + 1;
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) {
      double u = double(i) / nu, v = double(j) / nv;
      if (meshing != Meshing::Regular) {
        double du = rng.uniform(-jitter(meshing), jitter(meshing)) / nu;
        double dv = rng.uniform(-jitter(meshing), jitter(meshing)) / nv;
        if (wrap_u || (i > 0 && i < nu)) u += du;
        if (wrap_v || (j > 0 && j < nv)) v += dv;
      }
      mesh.positions.push_back(glm::vec3(map(u, v)));
    }
  auto index = [&](int i, int j) { return uint32_t((j % cv) * cu + (i % cu)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      add_quad(mesh, index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1), meshing, rng);
  compute_normals(mesh);
  return mesh;
}

// The cube [-1,1]^3 as n x n grids per face, shared border vertices, each lattice point
// sent through `map` (given the cube point and the rng).
template <class Map>
Mesh cube_grid_mesh(int n, Map map, Meshing meshing, Rng& rng) {
  static const glm::dvec3 axes[6][3] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
  Mesh mesh;
  std::map<std::tuple<int, int, int>, uint32_t> lattice;
  auto vertex = [&](const glm::dvec3(&f)[3], int s, int t) {
    glm::dvec3 q = f[0] + (2.0 * s / n - 1) * f[1] + (2.0 * t / n - 1) * f[2];
    glm::ivec3 key = glm::ivec3(glm::round((q + 1.0) * 0.5 * double(n)));
    auto [it, added] = lattice.try_emplace({key.x, key.y, key.z}, uint32_t(mesh.positions.size()));
    if (added) mesh.positions.push_back(glm::vec3(map(q, rng)));
    return it->second;
  };
  for (const auto& f : axes)
    for (int t = 0; t < n; ++t)
      for (int s = 0; s < n; ++s)
        add_quad(mesh, vertex(f, s, t), vertex(f, s + 1, t), vertex(f, s + 1, t + 1), vertex(f, s, t + 1), meshing,
                 rng);
  compute_normals(mesh);
  return mesh;
}

// A point of the unit sphere from a point of the cube, spread more evenly than q/|q|.
glm::dvec3 spherified_cube(const glm::dvec3& q) {
  glm::dvec3 s = q * q;
  return {q.x * std::sqrt(1 - s.y / 2 - s.z / 2 + s.y * s.z / 3),
          q.y * std::sqrt(1 - s.z / 2 - s.x / 2 + s.z * s.x / 3),
          q.z * std::sqrt(1 - s.x / 2 - s.y / 2 + s.x * s.y / 3)};
}

// Unit sphere points for an n-cell cube-sphere; irregular: the cube point moved by up
// to kJitter of a cell along each axis and put back on the cube (the largest coordinate
// scaled to +-1) before it goes to the sphere.
Mesh unit_cube_sphere(int n, Meshing meshing, Rng& rng) {
  auto map = [&](glm::dvec3 q, Rng& r) {
    if (meshing != Meshing::Regular) {
      q += (2.0 * jitter(meshing) / n) * glm::dvec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
      q /= std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    }
    return spherified_cube(q);
  };
  return cube_grid_mesh(n, map, meshing, rng);
}

int cells(double length, double edge) { return std::max(3, int(std::ceil(length / edge))); }

}  // namespace

SurfaceTruth implicit_surface_truth(const glm::dvec3& gradient, const glm::dmat3& hessian) {
  double g = glm::length(gradient);
  glm::dvec3 n = gradient / g;
  glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  glm::dvec3 t1 = glm::normalize(glm::cross(n, helper)), t2 = glm::cross(n, t1);
  // Second fundamental form II(t, t) = tᵀ H t / |grad F|, positive bending away from n.
  double a = glm::dot(t1, hessian * t1) / g, b = glm::dot(t1, hessian * t2) / g, d = glm::dot(t2, hessian * t2) / g;
  double mean = 0.5 * (a + d), deviation = std::hypot(0.5 * (a - d), b);
  double theta = 0.5 * std::atan2(2 * b, a - d);  // direction of the larger eigenvalue
  glm::dvec3 d_max = std::cos(theta) * t1 + std::sin(theta) * t2;
  return {n, mean - deviation, mean + deviation, glm::cross(d_max, n), d_max};
}

AnalyticSurface analytic_ellipsoid(glm::dvec3 semi_axes, double edge, Meshing meshing, uint32_t seed) {
  std::string name = std::string("ellipsoid/") + meshing_name(meshing);
  Rng rng(seed, name);
  double largest = std::max({semi_axes.x, semi_axes.y, semi_axes.z});
  Mesh mesh = unit_cube_sphere(cells(0.5 * pi * largest, edge), meshing, rng);
  for (auto& p : mesh.positions) p = glm::vec3(glm::dvec3(p) * semi_axes);
  compute_normals(mesh);
  mesh.name = "procedural:" + name;
  glm::dvec3 inverse_square = 1.0 / (semi_axes * semi_axes);
  auto truth = [inverse_square](const glm::dvec3& p) {
    return implicit_surface_truth(
        2.0 * p * inverse_square,
        glm::dmat3(2.0 * inverse_square.x, 0, 0, 0, 2.0 * inverse_square.y, 0, 0, 0, 2.0 * inverse_square.z));
  };
  return {name, std::move(mesh), truth};
}

AnalyticSurface analytic_sphere(double radius, double edge, Meshing meshing, uint32_t seed) {
  AnalyticSurface s = analytic_ellipsoid(glm::dvec3(radius), edge, meshing, seed);
  s.name = std::string("sphere/") + meshing_name(meshing);
  s.mesh.name = "procedural:" + s.name;
  return s;
}

AnalyticSurface analytic_cylinder(double radius, double height, double edge, Meshing meshing, uint32_t seed) {
  std::string name = std::string("cylinder/") + meshing_name(meshing);
  Rng rng(seed, name);
  auto map = [&](double u, double v) {
    double phi = 2 * pi * u;
    return glm::dvec3(radius * std::cos(phi), radius * std::sin(phi), height * v);
  };
  Mesh mesh = grid_mesh(cells(2 * pi * radius, edge), cells(height, edge), true, false, map, meshing, rng);
  mesh.name = "procedural:" + name;
  auto truth = [radius](const glm::dvec3& p) {
    glm::dvec3 n = glm::normalize(glm::dvec3(p.x, p.y, 0));
    return SurfaceTruth{n, 0.0, 1.0 / radius, {0, 0, 1}, glm::cross(n, glm::dvec3(0, 0, 1))};
  };
  return {name, std::move(mesh), truth};
}

AnalyticSurface analytic_torus(double R, double r, double edge, Meshing meshing, uint32_t seed) {
  std::string name = std::string("torus/") + meshing_name(meshing);
  Rng rng(seed, name);
  auto map = [&](double u, double v) {
    double phi = 2 * pi * u, theta = 2 * pi * v;
    double w = R + r * std::cos(theta);
    return glm::dvec3(w * std::cos(phi), w * std::sin(phi), r * std::sin(theta));
  };
  Mesh mesh = grid_mesh(cells(2 * pi * R, edge), cells(2 * pi * r, edge), true, true, map, meshing, rng);
  mesh.name = "procedural:" + name;
  // Around the tube k = 1/r; along the parallels k = cos(theta) / (R + r cos(theta)).
  auto truth = [R, r](const glm::dvec3& p) {
    double phi = std::atan2(p.y, p.x), w = std::hypot(p.x, p.y);
    double theta = std::atan2(p.z, w - R);
    glm::dvec3 n(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta));
    glm::dvec3 parallel(-std::sin(phi), std::cos(phi), 0), meridian = glm::cross(n, parallel);
    return SurfaceTruth{n, std::cos(theta) / (R + r * std::cos(theta)), 1.0 / r, parallel, meridian};
  };
  return {name, std::move(mesh), truth};
}

AnalyticSurface analytic_saddle(double s, double edge, Meshing meshing, uint32_t seed) {
  std::string name = std::string("saddle/") + meshing_name(meshing);
  Rng rng(seed, name);
  auto map = [&](double u, double v) {
    double x = 2 * u - 1, y = 2 * v - 1;
    return glm::dvec3(x, y, s * (x * x - y * y));
  };
  Mesh mesh = grid_mesh(cells(2, edge), cells(2, edge), false, false, map, meshing, rng);
  mesh.name = "procedural:" + name;
  // F = z - s (x^2 - y^2), gradient towards +z.
  auto truth = [s](const glm::dvec3& p) {
    return implicit_surface_truth({-2 * s * p.x, 2 * s * p.y, 1}, glm::dmat3(-2 * s, 0, 0, 0, 2 * s, 0, 0, 0, 0));
  };
  return {name, std::move(mesh), truth};
}

Mesh subdivided_cube(int n) {
  Rng unused(1, "subdivided-cube");
  Mesh mesh = cube_grid_mesh(
      n, [](const glm::dvec3& q, Rng&) { return q; }, Meshing::Regular, unused);
  mesh.name = "procedural:cube";
  return mesh;
}

Mesh schwarz_lantern(double radius, double height, int around, int rings) {
  Mesh mesh;
  mesh.name = "procedural:schwarz-lantern";
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < around; ++i) {
      double phi = (2 * pi * i + pi * (j % 2)) / around;
      mesh.positions.emplace_back(radius * std::cos(phi), radius * std::sin(phi), height * j / rings);
    }
  auto index = [&](int i, int j) { return uint32_t(j * around + (i % around)); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      // Ring j+1 is turned by half a step: forward on even j, back on odd j.
      int up = j % 2 == 0 ? i : i + 1;
      mesh.triangles.push_back({index(i, j), index(i + 1, j), index(up, j + 1)});
      mesh.triangles.push_back({index(up, j + 1), index(i + 1, j), index(up + 1, j + 1)});
    }
  compute_normals(mesh);
  return mesh;
}

}  // namespace plumbago::testing

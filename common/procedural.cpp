#include "common/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace plumbago {

namespace {

constexpr float kPi = 3.14159265358979f;

int segments(float base, float resolution) { return std::max(3, int(std::lround(base * resolution))); }

// A (u, v) grid wrapped onto a surface; u wraps when `wrap_u`, v when `wrap_v`.
template <class Surface>
Mesh grid_surface(int nu, int nv, bool wrap_u, bool wrap_v, Surface surface) {
  Mesh m;
  int cols = wrap_u ? nu : nu + 1, rows = wrap_v ? nv : nv + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) m.positions.push_back(surface(float(i) / float(nu), float(j) / float(nv)));
  auto at = [&](int i, int j) { return unsigned((j % rows) * cols + (i % cols)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

Mesh torus(float res) {
  return grid_surface(segments(96, res), segments(48, res), true, true, [](float u, float v) {
    float th = 2 * kPi * u, ph = 2 * kPi * v, R = 1.0f, r = 0.4f;
    return glm::vec3((R + r * std::cos(ph)) * std::cos(th), (R + r * std::cos(ph)) * std::sin(th), r * std::sin(ph));
  });
}

Mesh plane(float res) {
  return grid_surface(segments(16, res), segments(16, res), false, false,
                      [](float u, float v) { return glm::vec3(2 * u - 1, 2 * v - 1, 0); });
}

// Icosahedron subdivided until its edges are short, projected onto the unit sphere: no
// poles, nearly uniform triangles.
Mesh sphere(float res) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2;
  Mesh m;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  int levels = std::clamp(int(std::lround(4 + std::log2(std::max(res, 0.0625f)))), 0, 7);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<unsigned, unsigned>, unsigned> midpoint;
    auto mid = [&](unsigned a, unsigned b) {
      auto key = std::minmax(a, b);
      auto [it, added] = midpoint.emplace(key, unsigned(m.positions.size()));
      if (added) m.positions.push_back((m.positions[a] + m.positions[b]) * 0.5f);
      return it->second;
    };
    std::vector<glm::uvec3> finer;
    for (const auto& f : m.triangles) {
      unsigned ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    m.triangles = std::move(finer);
  }
  for (auto& p : m.positions) p = glm::normalize(p);
  return m;
}

// A closed profile (counter-clockwise seen from +z) extruded from z0 to z1 in `rows`
// rows, with flat fan caps: sharp 90-degree creases where walls meet caps.
void add_extrusion(Mesh& m, const std::vector<glm::vec2>& profile, float z0, float z1, int rows) {
  unsigned n = unsigned(profile.size()), base = unsigned(m.positions.size());
  for (int r = 0; r <= rows; ++r)
    for (const auto& p : profile) m.positions.push_back({p, z0 + (z1 - z0) * float(r) / float(rows)});
  for (unsigned r = 0; r < unsigned(rows); ++r)
    for (unsigned i = 0; i < n; ++i) {
      unsigned a = base + r * n + i, b = base + r * n + (i + 1) % n;
      m.triangles.push_back({a, b, b + n});
      m.triangles.push_back({a, b + n, a + n});
    }
  glm::vec2 c(0);
  for (const auto& p : profile) c += p / float(n);
  unsigned bottom = unsigned(m.positions.size()), top = bottom + 1, top_ring = base + unsigned(rows) * n;
  m.positions.push_back({c, z0});
  m.positions.push_back({c, z1});
  for (unsigned i = 0; i < n; ++i) {
    m.triangles.push_back({bottom, base + (i + 1) % n, base + i});
    m.triangles.push_back({top, top_ring + i, top_ring + (i + 1) % n});
  }
}

std::vector<glm::vec2> circle(glm::vec2 center, float radius, int n) {
  std::vector<glm::vec2> p;
  for (int i = 0; i < n; ++i) {
    float a = 2 * kPi * float(i) / float(n);
    p.push_back(center + radius * glm::vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

Mesh cylinder(float res) {
  Mesh m;
  add_extrusion(m, circle({0, 0}, 0.5f, segments(64, res)), -1.0f, 1.0f, segments(8, res));
  return m;
}

// A slab whose profile is a rectangle with one half-round end (flat walls running
// tangentially into a smooth cylindrical patch, sharp creases at the caps), with a
// cylindrical boss standing on its top: creases next to smooth patches, as on fandisk.
Mesh cad_part(float res) {
  std::vector<glm::vec2> profile;
  int round = segments(32, res), straight = segments(12, res);
  for (int i = 0; i <= straight; ++i) profile.push_back({-1.2f + 1.2f * float(i) / float(straight), -0.6f});
  for (int i = 1; i < round; ++i) {
    float a = -kPi / 2 + kPi * float(i) / float(round);
    profile.push_back({0.6f * std::cos(a), 0.6f * std::sin(a)});
  }
  for (int i = 0; i <= straight; ++i) profile.push_back({-1.2f * float(i) / float(straight), 0.6f});
  for (int i = 1; i < straight / 2; ++i) profile.push_back({-1.2f, 0.6f - 1.2f * float(i) / float(straight / 2)});
  Mesh m;
  add_extrusion(m, profile, -0.25f, 0.25f, segments(4, res));
  add_extrusion(m, circle({-0.6f, 0.0f}, 0.3f, segments(48, res)), 0.25f, 0.65f, segments(6, res));
  return m;
}

}  // namespace

Mesh make_procedural(const std::string& kind, float resolution) {
  if (!(resolution > 0 && resolution <= 16)) throw std::invalid_argument("procedural resolution must be in (0, 16]");
  Mesh m = kind == "torus"      ? torus(resolution)
           : kind == "sphere"   ? sphere(resolution)
           : kind == "cad"      ? cad_part(resolution)
           : kind == "plane"    ? plane(resolution)
           : kind == "cylinder" ? cylinder(resolution)
                                : throw std::invalid_argument("unknown procedural mesh '" + kind +
                                                              "' (torus, sphere, cad, plane, cylinder)");
  m.name = "procedural:" + kind;
  weld_vertices(m);
  compute_normals(m);
  return m;
}

}  // namespace plumbago

#include "common/mesh/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace plumbago {

namespace {

int segments(float base, float resolution) { return std::max(3, int(std::lround(base * resolution))); }

// A (u, v) grid wrapped onto a surface; u wraps when `wrap_u`, v when `wrap_v`.
template <class Surface>
Mesh grid_surface(int nu, int nv, bool wrap_u, bool wrap_v, Surface surface) {
  Mesh m;
  int cols = wrap_u ? nu : nu + 1, rows = wrap_v ? nv : nv + 1;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) m.positions.push_back(surface(float(i) / float(nu), float(j) / float(nv)));
  auto at = [&](int i, int j) { return unsigned((j % rows) * cols + (i % cols)); };
  auto uv = [&](int i, int j) { return glm::vec2(float(i) / float(nu), float(j) / float(nv)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {  // a wrapped corner keeps u (or v) = 1: the seam is per corner
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      m.uvs.insert(m.uvs.end(), {uv(i, j), uv(i + 1, j), uv(i + 1, j + 1), uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)});
    }
  return m;
}

// Per corner, (u, v) = (the angle about z over 2 pi, in [0, 1), and a coordinate along z);
// a face across the seam at u = 0 takes u past 1 on its far corners, and a corner on the axis
// the mean u of the other two: a chart without a cut through any face.
glm::vec2 about_z(glm::vec3 p, float v) {
  float u = std::atan2(p.y, p.x) / (2 * std::numbers::pi_v<float>);
  return {u < 0 ? u + 1 : u, v};
}
void add_uvs_about_z(Mesh& m, float (*v_of)(glm::vec3)) {
  for (const glm::uvec3& t : m.triangles) {
    glm::vec2 c[3];
    bool on_axis[3];
    for (int k = 0; k < 3; ++k) {
      glm::vec3 p = m.positions[t[k]];
      c[k] = about_z(p, v_of(p));
      on_axis[k] = p.x == 0 && p.y == 0;
    }
    float lo = 1, hi = 0;
    for (int k = 0; k < 3; ++k)
      if (!on_axis[k]) lo = std::min(lo, c[k].x), hi = std::max(hi, c[k].x);
    for (int k = 0; k < 3; ++k)
      if (!on_axis[k] && hi - lo > 0.5f && c[k].x < 0.5f) c[k].x += 1;
    for (int k = 0; k < 3; ++k)
      if (on_axis[k]) c[k].x = (c[(k + 1) % 3].x + c[(k + 2) % 3].x) / 2;
    m.uvs.insert(m.uvs.end(), c, c + 3);
  }
}

Mesh torus(float res) {
  return grid_surface(segments(96, res), segments(48, res), true, true, [](float u, float v) {
    float th = 2 * std::numbers::pi_v<float> * u, ph = 2 * std::numbers::pi_v<float> * v, R = 1.0f, r = 0.4f;
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
  m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
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
  add_uvs_about_z(m, [](glm::vec3 p) { return std::acos(std::clamp(-p.z, -1.0f, 1.0f)) / std::numbers::pi_v<float>; });
  return m;
}

// A ring of vertices around a closed profile at height z; returns its first vertex.
unsigned add_ring(Mesh& m, const std::vector<glm::vec2>& profile, float z) {
  unsigned first = unsigned(m.positions.size());
  for (const auto& p : profile) m.positions.push_back({p, z});
  return first;
}

// Quads between two rings of n vertices, both counter-clockwise seen from +z, facing
// along (ring direction) x (from ring a to ring b): outward for a wall from a lower ring
// to an upper one, upward for a flat annulus from an outer ring to an inner one.
void stitch(Mesh& m, unsigned a, unsigned b, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    unsigned j = (i + 1) % n;
    m.triangles.push_back({a + i, a + j, b + j});
    m.triangles.push_back({a + i, b + j, b + i});
  }
}

// A flat cap: a fan from `apex` to a ring of n vertices, facing +z or -z.
void add_fan(Mesh& m, unsigned ring, unsigned n, glm::vec3 apex, bool facing_up) {
  unsigned c = unsigned(m.positions.size());
  m.positions.push_back(apex);
  for (unsigned i = 0; i < n; ++i) {
    unsigned j = (i + 1) % n;
    m.triangles.push_back(facing_up ? glm::uvec3(c, ring + i, ring + j) : glm::uvec3(c, ring + j, ring + i));
  }
}

// A closed profile (counter-clockwise seen from +z) swept from z0 up to z1 in `rows`
// rows; returns the first vertex of each of its rows + 1 rings, bottom to top.
std::vector<unsigned> add_wall(Mesh& m, const std::vector<glm::vec2>& profile, float z0, float z1, int rows) {
  std::vector<unsigned> rings;
  for (int r = 0; r <= rows; ++r) rings.push_back(add_ring(m, profile, z0 + (z1 - z0) * float(r) / float(rows)));
  for (int r = 0; r < rows; ++r) stitch(m, rings[r], rings[r + 1], unsigned(profile.size()));
  return rings;
}

glm::vec2 direction(float angle) { return {std::cos(angle), std::sin(angle)}; }

std::vector<glm::vec2> circle(glm::vec2 center, float radius, int n) {
  std::vector<glm::vec2> p;
  for (int i = 0; i < n; ++i)
    p.push_back(center + radius * direction(2 * std::numbers::pi_v<float> * float(i) / float(n)));
  return p;
}

// v of a cylinder's or cone's side: z in [-1, 1] as [0, 1]; of a flat cap, its radius in a
// strip of its own below (the base) or above (a cylinder's top), so that no chart overlaps.
float cone_v(glm::vec3 p) { return p.z <= -1 ? glm::length(glm::vec2(p)) - 0.5f : (p.z + 1) / 2; }
float cylinder_v(glm::vec3 p) { return p.z >= 1 ? 1.5f - glm::length(glm::vec2(p)) : cone_v(p); }

Mesh cylinder(float res) {
  int n = segments(64, res);
  Mesh m;
  auto rings = add_wall(m, circle({0, 0}, 0.5f, n), -1.0f, 1.0f, segments(8, res));
  add_fan(m, rings.front(), unsigned(n), {0, 0, -1}, false);
  add_fan(m, rings.back(), unsigned(n), {0, 0, 1}, true);
  add_uvs_about_z(m, cylinder_v);
  return m;
}

// A cone along z: its base a disc of radius 0.5 at z = -1, its apex at z = 1, the side in
// rings that shrink toward the apex (the snowman's nose and trees, Kalnins et al. Fig. 8).
Mesh cone(float res) {
  int n = segments(64, res), rows = segments(12, res);
  Mesh m;
  std::vector<unsigned> rings;
  for (int r = 0; r < rows; ++r) {
    float t = float(r) / float(rows);
    rings.push_back(add_ring(m, circle({0, 0}, 0.5f * (1 - t), n), -1 + 2 * t));
  }
  for (int r = 0; r + 1 < rows; ++r) stitch(m, rings[r], rings[r + 1], unsigned(n));
  add_fan(m, rings.front(), unsigned(n), {0, 0, -1}, false);
  add_fan(m, rings.back(), unsigned(n), {0, 0, 1}, true);
  add_uvs_about_z(m, cone_v);
  return m;
}

// The box [lo, hi] as a rectangular wall along z with two capped fans: 12 crease edges.
void add_box(Mesh& m, glm::vec3 lo, glm::vec3 hi) {
  auto rings = add_wall(m, {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}}, lo.z, hi.z, 1);
  glm::vec2 center = (glm::vec2(lo) + glm::vec2(hi)) * 0.5f;
  add_fan(m, rings.front(), 4, {center, lo.z}, false);
  add_fan(m, rings.back(), 4, {center, hi.z}, true);
}

// The unit cube [-0.5, 0.5]^3: 12 crease edges (Kalnins et al. 2002, §4.5); flat faces, so the resolution
// changes nothing.
Mesh cube(float) {
  Mesh m;
  add_box(m, glm::vec3(-0.5f), glm::vec3(0.5f));
  return m;
}

// A brick storefront, the stand-in for the building of Kalnins et al. 2002 (Fig. 6, Table 1:
// 16K faces, 7,000 strokes): a wall 6 wide and 4 high (x in [-3, 3], y in [0, 4]) faced
// with staggered bricks standing out of it toward +z, left open at a door, two shop
// windows and three upper windows, where the wall behind shows. Every brick is a box of
// 12 creases. `resolution` scales the number of bricks along each axis.
Mesh storefront(float res) {
  struct Opening {
    float x0, x1, y0, y1;
  };
  const Opening openings[] = {{-0.6f, 0.6f, 0.0f, 2.2f},  {-2.6f, -1.0f, 0.8f, 2.4f}, {1.0f, 2.6f, 0.8f, 2.4f},
                              {-2.4f, -1.2f, 2.9f, 3.7f}, {-0.6f, 0.6f, 2.9f, 3.7f},  {1.2f, 2.4f, 2.9f, 3.7f}};
  const float mortar = 0.02f, brick_w = 0.16f / res, brick_h = 0.07f / res, depth = 0.06f;
  Mesh m;
  add_box(m, {-3.0f, 0.0f, -0.3f}, {3.0f, 4.0f, 0.0f});
  auto in_opening = [&](float x0, float x1, float y0, float y1) {
    for (const Opening& o : openings)
      if (x1 > o.x0 && x0 < o.x1 && y1 > o.y0 && y0 < o.y1) return true;
    return false;
  };
  const int rows = int(4.0f / (brick_h + mortar));
  for (int r = 0; r < rows; ++r) {
    float y0 = r * (brick_h + mortar) + mortar, y1 = y0 + brick_h;
    for (float x0 = -3.0f + mortar - (r % 2) * 0.5f * (brick_w + mortar); x0 < 3.0f - mortar; x0 += brick_w + mortar) {
      float a = std::max(x0, -3.0f + mortar), b = std::min(x0 + brick_w, 3.0f - mortar);
      if (b - a > 0.25f * brick_w && !in_opening(a, b, y0, y1)) add_box(m, {a, y0, 0.0f}, {b, y1, depth});
    }
  }
  return m;
}

// Where the ray from `from` at `angle` leaves the slab's outline: the rectangle
// [-1.2, 0] x [-0.6, 0.6] joined to the disc of radius 0.6 around the origin. Both hold
// `from`, so the ray leaves their union where it leaves the later of the two.
glm::vec2 slab_outline(glm::vec2 from, float angle) {
  const glm::vec2 lo(-1.2f, -0.6f), hi(0.0f, 0.6f);
  glm::vec2 d = direction(angle);
  float t_rect = INFINITY;
  for (int c = 0; c < 2; ++c)
    if (d[c] != 0) t_rect = std::min(t_rect, ((d[c] > 0 ? hi[c] : lo[c]) - from[c]) / d[c]);
  float bd = glm::dot(from, d);  // |from + t d| = 0.6, the larger root
  float t_disc = -bd + std::sqrt(std::max(bd * bd - glm::dot(from, from) + 0.36f, 0.0f));
  return from + std::max(t_rect, t_disc) * d;
}

// One closed surface like a machined part: a slab with one half-round end (flat walls
// running tangentially into a smooth cylindrical patch) and a cylindrical boss standing
// on its top. Creases are sharp by geometry (walls meet caps at 90 degrees, the boss's
// foot is a concave 90-degree crease), as on fandisk. Outline and boss are sampled on
// the same rays from the boss's axis, so the slab's top is a strip between the two rings;
// n is a multiple of 8 so that rays pass through the outline's corners and tangent points.
Mesh cad_part(float res) {
  const glm::vec2 axis(-0.6f, 0.0f);
  const unsigned n = 8 * unsigned(segments(12, res));
  std::vector<glm::vec2> outline, boss;
  for (unsigned k = 0; k < n; ++k) {
    float angle = 2 * std::numbers::pi_v<float> * float(k) / float(n);
    outline.push_back(slab_outline(axis, angle));
    boss.push_back(axis + 0.3f * direction(angle));
  }
  Mesh m;
  auto slab = add_wall(m, outline, -0.25f, 0.25f, segments(4, res));
  auto post = add_wall(m, boss, 0.25f, 0.65f, segments(6, res));
  add_fan(m, slab.front(), n, {axis, -0.25f}, false);
  stitch(m, slab.back(), post.front(), n);  // the slab's top, around the boss's foot
  add_fan(m, post.back(), n, {axis, 0.65f}, true);
  return m;
}

using Maker = Mesh (*)(float resolution);

const std::vector<std::pair<std::string, Maker>>& makers() {
  static const std::vector<std::pair<std::string, Maker>> table = {
      {"torus", torus},       {"sphere", sphere}, {"cad", cad_part},          {"plane", plane},
      {"cylinder", cylinder}, {"cube", cube},     {"storefront", storefront}, {"cone", cone}};
  return table;
}

}  // namespace

const std::vector<std::string>& procedural_kinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> k;
    for (const auto& [name, make] : makers()) k.push_back(name);
    return k;
  }();
  return kinds;
}

Mesh make_procedural(const std::string& kind, float resolution) {
  if (!(resolution > 0 && resolution <= 16)) throw std::invalid_argument("procedural resolution must be in (0, 16]");
  auto it = std::find_if(makers().begin(), makers().end(), [&](const auto& entry) { return entry.first == kind; });
  if (it == makers().end()) {
    std::string known;
    for (const auto& k : procedural_kinds()) known += (known.empty() ? "" : ", ") + k;
    throw std::invalid_argument("unknown procedural mesh '" + kind + "' (" + known + ")");
  }
  Mesh m = it->second(resolution);
  m.name = "procedural:" + kind;
  weld_vertices(m);
  compute_normals(m);
  return m;
}

}  // namespace plumbago

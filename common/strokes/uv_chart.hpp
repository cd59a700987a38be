// A mesh's (u, v) chart as a point-location table (Kalnins et al. 2002, §6.3: a mobile hatching
// group travels in its surface's parameterization): which face holds a point of the chart, and
// where. A uniform grid of buckets over the chart's box, each listing the faces whose (u, v) box
// meets it (kept flat: the GPU backend uploads the same table and locates in it itself,
// shaders/strokes/decal_rows.comp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "common/mesh/mesh.hpp"

namespace plumbago {

class UvChart {
 public:
  struct Hit {
    uint32_t face;
    glm::dvec3 bary;
  };

  // `uvs` per face corner of `mesh` (Mesh::uvs, or a patch's: non-finite on the faces off it).
  UvChart(const Mesh& mesh, std::vector<glm::vec2> uvs);

  // The face holding `uv`, the one it lies deepest in where several do (an edge); on a
  // periodic chart u is taken modulo 1 first, then 1 further (a face across the seam).
  std::optional<Hit> locate(glm::dvec2 uv) const;

  glm::dvec3 position(const Hit& h) const;
  glm::dvec3 normal(const Hit& h) const;
  glm::dvec2 uv(uint32_t face, const glm::dvec3& bary) const;
  // Periodic: u's period is 1 (the chart's lowest u and that plus 1 are one point of the surface).
  bool periodic() const { return periodic_; }
  double u_lowest() const { return lo_.x; }
  double u_span() const { return periodic_ ? 1.0 : hi_.x - lo_.x; }

  // The table: the chart's box, its cells a side, per face corner its (u, v), and per cell
  // (row-major from lo) its faces, faces()[starts()[c], starts()[c + 1]).
  const Mesh& mesh() const { return mesh_; }
  glm::dvec2 lo() const { return lo_; }
  glm::dvec2 hi() const { return hi_; }
  int cells() const { return cells_; }
  const std::vector<glm::vec2>& corner_uvs() const { return uvs_; }
  const std::vector<uint32_t>& starts() const { return starts_; }
  const std::vector<uint32_t>& faces() const { return faces_; }

 private:
  glm::dvec2 corner(uint32_t f, int k) const { return glm::dvec2(uvs_[3 * size_t(f) + size_t(k)]); }
  bool charted(uint32_t f) const;
  glm::ivec2 cell(glm::dvec2 uv) const;
  std::optional<Hit> locate_in_chart(glm::dvec2 uv) const;
  template <class Of>
  glm::dvec3 interpolate(const Hit& h, Of of) const;

  const Mesh& mesh_;
  std::vector<glm::vec2> uvs_;
  glm::dvec2 lo_{INFINITY}, hi_{-INFINITY};
  int cells_ = 1;
  std::vector<uint32_t> starts_, faces_;
  bool periodic_ = false;
};

}  // namespace plumbago

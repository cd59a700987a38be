// The ID reference image, CPU reference (Kalnins et al. 2002, §4.6): the G-buffer's faces, then the
// triangles of common/strokes/id_image.hpp through the scalar rasterizer, each pixel keeping the
// nearest (largest z = near / d).
#include "common/strokes/id_image.hpp"

#include <optional>

#include "reference/core/stage.hpp"
#include "reference/strokes/decal.hpp"
#include "reference/strokes/raster.hpp"

namespace plumbago::reference {

namespace {

// Per pixel: the key of the nearest (largest z) triangle; for the depth ties, its z and the
// largest z of another key, each with its triangle's z slope; and the largest z of a
// triangle whose edge passes within a subpixel of the pixel center (covered or not).
struct IdRaster {
  ImageU32 key;
  Image nearest, runner_up;  // 2 ch: z, |grad z| (per pixel)
  Image edge_z;
};

const double kSubpixel = 1.0 / double(1 << kSubpixelBits);

// |grad z| of a window-space triangle, per pixel.
float z_slope(const IdVertex* t) {
  glm::dvec2 e1 = glm::dvec2(t[1].window - t[0].window), e2 = glm::dvec2(t[2].window - t[0].window);
  double det = e1.x * e2.y - e1.y * e2.x, dz1 = t[1].z - t[0].z, dz2 = t[2].z - t[0].z;
  if (det == 0) return 0;
  return float(glm::length(glm::dvec2(dz1 * e2.y - dz2 * e1.y, dz2 * e1.x - dz1 * e2.x)) / std::abs(det));
}

// Draws one triangle into the band [y0, y1), GL_GREATER.
void draw(const IdVertex* t, IdRaster& r, int y0, int y1) {
  float slope = z_slope(t);
  auto fragment = [&](int x, int y, glm::dvec3 w, bool edge) {
    float z = float(w[0] * t[0].z + w[1] * t[1].z + w[2] * t[2].z);
    if (edge) r.edge_z.at(x, y) = std::max(r.edge_z.at(x, y), z);
    if (!(w[0] >= 0 && w[1] >= 0 && w[2] >= 0)) return;  // just outside: only the edge's mark
    uint32_t& key = r.key.at(x, y);
    float* nearest = &r.nearest.at(x, y);
    float* runner_up = &r.runner_up.at(x, y);
    if (z > nearest[0]) {
      if (key != t[0].key && nearest[0] > 0) runner_up[0] = nearest[0], runner_up[1] = nearest[1];
      nearest[0] = z, nearest[1] = slope, key = t[0].key;
    } else if (t[0].key != key && z > runner_up[0]) {
      runner_up[0] = z, runner_up[1] = slope;
    }
  };
  rasterize_triangle(t[0].window, t[1].window, t[2].window, {0, y0, r.key.width, y1}, kSubpixel, fragment);
}

// Where another rasterizer may keep another key: the two nearest surfaces lie within what
// float interpolation can swap (kDepthTie relative, plus each triangle's z change over a
// subpixel step), or a triangle at least as near has an edge within a subpixel of the
// pixel center (rounding decides its coverage).
bool ambiguous(const IdRaster& r, size_t i) {
  const float* nearest = &r.nearest.data[2 * i];
  const float* runner_up = &r.runner_up.data[2 * i];
  float margin = float(kDepthTie) * nearest[0] + float((nearest[1] + runner_up[1]) * kSubpixel);
  bool tie = runner_up[0] > 0 && nearest[0] - runner_up[0] <= margin;
  return tie || (r.edge_z.data[i] > 0 && r.edge_z.data[i] >= nearest[0] - margin);
}

IdRaster empty_raster(int width, int height) {
  return {ImageU32(width, height, 1), Image(width, height, 2), Image(width, height, 2), Image(width, height, 1)};
}

// Rule 1 on the G-buffer: each pixel's face key at z = near / d, its z slope 0 (both backends
// read the same depth at the pixel center: no rasterizer rounds it).
void draw_gbuffer_faces(const GBuffer& g, const std::vector<uint32_t>& first_keys, double near, IdRaster& r) {
  for (int y = 0; y < g.ids.height; ++y)
    for (int x = 0; x < g.ids.width; ++x) {
      if (g.background(x, y)) continue;
      r.key.at(x, y) = first_keys.at(g.ids.at(x, y, 0) - 1) + g.ids.at(x, y, 1);
      r.nearest.at(x, y) = face_z(near, g.depth.at(x, y));
    }
}

void draw_triangles(const std::vector<IdVertex>& v, IdRaster& r) {
  draw_in_bands(
      v, r.key.height, [](const IdVertex& x) { return x.window; },
      [&](const IdVertex* t, int y0, int y1) { draw(t, r, y0, y1); });
}

// The key image and where rounding decides it, as they stand.
void put_keys(ReferenceFrame& f, const IdRaster& r, Buffer keys, Slot<Image> ambiguity) {
  f.put(keys, key_channels(r.key));
  Image ties(r.key.width, r.key.height, 1);
  for (size_t i = 0; i < ties.data.size(); ++i) ties.data[i] = ambiguous(r, i);
  f.put(ambiguity, std::move(ties));
}

// Where the rounding of a rasterizer decides (ambiguous above), the backends may keep either key.
Image ambiguity_bound(Image ambiguous) {
  for (float& b : ambiguous.data) b *= 65536.0f;
  return ambiguous;
}

}  // namespace

PLUMBAGO_REFERENCE_STAGE(id_image, [](ReferenceFrame& f) {
  auto p = f.params<StrokesParams>();
  DecalSurface decals;  // by rays (Kalnins et al. 2002, §3)
  std::optional<SurfaceStrokes> strokes;
  if (has_decals(f.scene)) decals = project_decals_by_rays(f.scene), strokes = surface_strokes(f.scene, decals);
  f.put(kWindowLines,
        window_lines(f.scene, p, LineObjects::Strokes, &f.get(kLineMeshes), strokes ? &*strokes : nullptr));
  const WindowLines& lines = f.get(kWindowLines);
  IdRaster r = empty_raster(f.scene.width, f.scene.height);
  draw_gbuffer_faces(f.get(kGBuffer), gbuffer_first_keys(f.scene), f.scene.camera.near, r);
  draw_triangles(id_sketchy_face_triangles(f.scene, lines), r);
  std::vector<IdVertex> line_triangles = id_line_triangles(f.scene, lines, p, IdLineRule::CreasesAndBorders);
  if (p.crease_under_silhouettes) {
    draw_triangles(line_triangles, r);
    put_keys(f, r, kCreaseIds, kAmbiguousCreaseIds);
    line_triangles.clear();
  } else {  // nothing tests it: 1 x 1 of 0, and the lines drawn at once
    f.put(kCreaseIds, Image(1, 1, 2));
    f.put(kAmbiguousCreaseIds, Image(1, 1, 1));
  }
  std::vector<IdVertex> silhouettes = id_line_triangles(f.scene, lines, p, IdLineRule::Silhouettes);
  line_triangles.insert(line_triangles.end(), silhouettes.begin(), silhouettes.end());
  draw_triangles(line_triangles, r);
  put_keys(f, r, kIds, kAmbiguousIds);
});

PLUMBAGO_REFERENCE_BOUND(id_image_ids, kIds.name,
                         [](const ReferenceFrame& f) { return ambiguity_bound(f.get(kAmbiguousIds)); });
PLUMBAGO_REFERENCE_BOUND(id_image_crease_ids, kCreaseIds.name,
                         [](const ReferenceFrame& f) { return ambiguity_bound(f.get(kAmbiguousCreaseIds)); });

}  // namespace plumbago::reference

// Sketchy drawing (Nienhaus & Döllner 2004): its parameters, the split of a
// scene into sketchy and ordinary objects, and the enlarged geometry of the `object`
// style. The per-pixel formulas live in reference/sketchy_*.cpp and their GLSL twins
// shaders/sketchy_*.frag.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago {

enum class SketchyStyle { Default, Repeat, Rough, Object };

struct SketchyParams {
  static constexpr const char* stage = "sketchy";
  SketchyStyle style;
  int octaves;
  float noise_scale;
  float edge_a, edge_b, edge_c, edge_d;
  float shade_a, shade_b, shade_c, shade_d;
  float dark_edge;
  int edge_copies;
  float copy_rotation_deg, copy_red, copy_green, copy_blue;
  float enlarge, object_noise_scale;
  int noise3d_size, noise3d_period;
  template <class V>
  void visit(V& v) {
    v.choice(style, "style", SketchyStyle::Default, {"default", "repeat", "rough", "object"},
             "Nienhaus & Döllner 2004, §3.4, §4: default (edges and shade), repeat (edge copies), "
             "rough (uncorrelated noise), object (3D noise on the enlarged geometry)");
    v.integer(octaves, "octaves", 4, 1, 8, "octaves of the turbulence T (Nienhaus & Döllner 2004, §3.2)");
    v.real(noise_scale, "noise_scale", 512, 8, 65536,
           "window pixels per tile of the noise texture: (s,t) = p / noise_scale");
    v.real(edge_a, "edge_a", 6, -64, 64,
           "M_e = [[a, b], [c, d]] turns (u, v) into the edge offset, pixels (paper Fig. 4)");
    v.real(edge_b, "edge_b", 0, -64, 64, "M_e, b");
    v.real(edge_c, "edge_c", 0, -64, 64, "M_e, c");
    v.real(edge_d, "edge_d", 6, -64, 64, "M_e, d");
    v.real(shade_a, "shade_a", 10, -64, 64, "M_s = [[a, b], [c, d]] turns (u, v) into the shade offset, pixels");
    v.real(shade_b, "shade_b", 3, -64, 64, "M_s, b");
    v.real(shade_c, "shade_c", -3, -64, 64, "M_s, c");
    v.real(shade_d, "shade_d", 10, -64, 64, "M_s, d");
    v.real(dark_edge, "dark_edge", 0.1, 0.0, 1.0,
           "an edge sample is drawn (and sets the depth sprite) where its contour darkness exceeds this");
    v.integer(edge_copies, "edge_copies", 2, 1, 8, "repeat style: how many times the edges are drawn");
    v.real(copy_rotation_deg, "copy_rotation_deg", 90, -180, 180,
           "repeat style: copy k uses M_e turned by k x this angle");
    v.real(copy_red, "copy_red", 0.25, 0.0, 1.0, "repeat style: red of the last copy's ink (the first copy is black)");
    v.real(copy_green, "copy_green", 0.35, 0.0, 1.0, "repeat style: green of the last copy's ink");
    v.real(copy_blue, "copy_blue", 0.6, 0.0, 1.0, "repeat style: blue of the last copy's ink");
    v.real(enlarge, "enlarge", 0.02, 0.0, 0.2,
           "object style: vertices pushed out along their normals by this x bbox diagonal (paper §4.2)");
    v.real(object_noise_scale, "object_noise_scale", 0.5, 0.01, 100,
           "object style: bbox diagonals per tile of the 3D noise texture");
    v.integer(noise3d_size, "noise3d_size", 64, 4, 256, "object style: texels per side of the 3D Perlin noise texture");
    v.integer(noise3d_period, "noise3d_period", 4, 1, 64, "object style: Perlin lattice cells across the 3D texture");
  }
};

// The objects drawn by the sketchy pipeline (style sketchy) and the others, each as a
// scene of its own with the same camera, lights and parameters.
Scene sketchy_objects(const Scene& scene);
Scene ordinary_objects(const Scene& scene);

// The unlit color of each object of `scene` (the shade map's, Nienhaus & Döllner 2004, §3.1).
std::vector<glm::vec3> object_colors(const Scene& scene);

// The `object` style's geometry (paper §4.2): each vertex moved by `distance` along its
// normal, in object space.
Mesh enlarged_mesh(const Mesh& mesh, float distance);
// Every object of `sketchy` enlarged by sketchy.enlarge x its bbox diagonal.
Scene enlarged_scene(const Scene& sketchy);
// Where the 3D noise is read (paper §4.3): the enlarged object-space position over the
// enlarged mesh's bbox diagonal, one per vertex.
std::vector<glm::vec3> noise_coordinates(const Mesh& enlarged);

// The farthest the composite reads from its pixel (Nienhaus & Döllner 2004, §3.2): |M (u, v)| <= ||M||_F |(u, v)|
// with |u|, |v| <= 1.5 (T < 2), 0.5 for the rough style's white noise; the largest of M_s
// and M_e, whose turned copies keep the norm.
float sketch_reach(const SketchyParams& p);

// Where the GPU runs the composite: covered_rect (common/scene/scene.hpp) grown by sketch_reach,
// the edge filter and its bilinear read, and a pixel to spare. Outside it both samples
// are exterior and the fragment would be discarded.
PixelRect composite_rect(const Scene& sketchy, int width, int height);

// M_e and M_s of Nienhaus & Döllner 2004, §3.2, acting on the column vector (u, v): [[a, b], [c, d]].
glm::mat2 edge_matrix(const SketchyParams& p);
glm::mat2 shade_matrix(const SketchyParams& p);
// Repeat style (Nienhaus & Döllner 2004, §3.4, §4), edge copy k: M_e turned by k x copy_rotation_deg; its ink,
// black for the first copy and the copy color for the last; and where its turbulence is
// read: (s, t) shifted by k x (0.37, 0.61) of a noise tile, so that copies differ.
glm::mat2 copy_matrix(const SketchyParams& p, int k);
glm::vec3 copy_ink(const SketchyParams& p, int k);
glm::vec2 copy_noise_shift(int k);

// What the uncertainty reads (Nienhaus & Döllner 2004, §3.2; §3.4, §4), made once per scene ("sketchy_noise"),
// only what sketchy.style needs.
struct SketchyNoise {
  Image perlin;                  // default, repeat: noise.size^2 tileable Perlin in [-1, 1]
  Image white;                   // rough: noise.size^2, 2 ch uniform in [0, 1)
  std::vector<Image> perlin_3d;  // object: noise3d_size^3 tileable Perlin in [-1, 1]
};
SketchyNoise make_sketchy_noise(const ParamSet& params, uint32_t seed);

}  // namespace plumbago

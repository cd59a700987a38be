// Surfaces with known curvature, meshed regularly (a grid with one diagonal) or
// irregularly (vertices jittered by up to 0.15 of a cell along each grid direction,
// which keeps every triangle unflipped, and each quad's diagonal picked at random, so
// valences run from 4 to 8), or strongly irregularly (jittered by up to 0.45 of a cell:
// a spread of 0.9 of a grid step, issue 19; about 1% of the triangles fold over), for
// the curvature accuracy tests. Every vertex lies exactly on the surface (up to float rounding) and
// triangles are counter-clockwise seen from outside. Sign convention as curvature.hpp:
// k > 0 where the surface bends away from its normal.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "common/mesh/mesh.hpp"

namespace plumbago::testing {

struct SurfaceTruth {
  glm::dvec3 normal;
  double k_min, k_max;
  glm::dvec3 d_min, d_max;
};

enum class Meshing { Regular, Irregular, Strong };

struct AnalyticSurface {
  std::string name;  // e.g. "torus/irregular", "torus/strong"
  Mesh mesh;
  std::function<SurfaceTruth(const glm::dvec3&)> truth;  // at a point of the surface
};

// `edge` is the target edge length; irregular meshes take their jitter from
// Rng(seed, name).
AnalyticSurface analytic_sphere(double radius, double edge, Meshing meshing, uint32_t seed = 1);
AnalyticSurface analytic_ellipsoid(glm::dvec3 semi_axes, double edge, Meshing meshing, uint32_t seed = 1);
// Axis z, open at both ends, z in [0, height].
AnalyticSurface analytic_cylinder(double radius, double height, double edge, Meshing meshing, uint32_t seed = 1);
// Around the z axis: major radius R (to the tube's center), tube radius r.
AnalyticSurface analytic_torus(double R, double r, double edge, Meshing meshing, uint32_t seed = 1);
// The hyperbolic paraboloid z = s (x^2 - y^2) over [-1, 1]^2, normal towards +z.
AnalyticSurface analytic_saddle(double s, double edge, Meshing meshing, uint32_t seed = 1);

// The surface of the cube [-1, 1]^3, `cells` x `cells` squares per face (flat, with
// sharp edges).
Mesh subdivided_cube(int cells);

// Schwarz's lantern: `rings` + 1 circles of `around` vertices on a cylinder (radius,
// height, open ends), every other circle turned by half a step. Its area and normals do
// not converge to the cylinder's as it is refined with rings >> around^2.
Mesh schwarz_lantern(double radius, double height, int around, int rings);

// Principal curvatures and directions of the level set F = 0 at a point, from the
// gradient and Hessian of F there (normal = grad / |grad|).
SurfaceTruth implicit_surface_truth(const glm::dvec3& gradient, const glm::dmat3& hessian);

}  // namespace plumbago::testing

// Mobile hatching (common/strokes/mobile_hatching.hpp, Kalnins et al. 2002, §6.3): a group
// drawn on an upright sphere travels along its parallel by the angle the view orbits, its
// hatches' surface points with it; its extent follows its peak's width; its alpha fades as l
// approaches T; a mesh without (u, v) gets one on the patch under the group (refused where
// that is no disk); both backends agree on the snowman's mobile trees along
// their camera path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "common/mesh/procedural.hpp"
#include "common/scene/animation.hpp"
#include "common/strokes/hatching.hpp"
#include "common/strokes/mobile_hatching.hpp"
#include "common/strokes/strokes.hpp"
#include "parity/parity.hpp"
#include "reference/strokes/decal.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// One sample of l(u) along a parallel: the bound on where a maximum is placed (the parabola
// through the samples refines it; the bound does not count on that).
constexpr double kSample = 1.0 / kMobileSamples;

// A sphere with its poles on the world's up axis (its parallels are its u-lines: the
// procedural sphere's u is the angle about its own z), a mobile group of four short
// hatches drawn on its right side, structured or free.
Scene sphere_with_mobile_group(const std::string& mesh = "sphere", bool free = false, float long_x = 1,
                               glm::vec3 eye = {0, 1, 4}, bool own_uvs = true) {
  Mesh m = make_procedural(mesh);
  if (!own_uvs) m.uvs.clear();
  Scene s = testing::one_stroke_object(std::move(m), eye);
  s.objects[0].transform = glm::mat4(glm::vec4(long_x, 0, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 1, 0, 0),
                                     glm::vec4(0, 0, 0, 1));  // z up, x stretched by long_x
  StrokeFile f;
  f.source = "mobile hatches";
  f.camera = s.camera, f.width = s.width, f.height = s.height;
  for (int i = 0; i < 4; ++i) {
    DrawnStroke h;
    h.role = StrokeRole::Hatching, h.group = 0, h.mobile = true, h.free = free;
    h.points = {{{190.0 + 5 * i, 100}, 1.0}, {{193.0 + 5 * i, 140}, 1.0}};
    h.style = load_stroke_style("pencil");
    f.strokes.push_back(h);
  }
  s.stroke_files = {f};
  return s;
}

// `s` with its eye turned by `degrees` about the up axis through the target.
Scene orbited(Scene s, double degrees) {
  glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0, 1, 0));
  s.camera.eye = glm::vec3(turn * glm::dvec4(glm::dvec3(s.camera.eye), 1.0));
  return s;
}

// A u difference taken the short way round the period 1.
double around(double du) { return du - std::round(du); }

// The angle of a world point about the up axis, in turns.
double turns_about_up(glm::dvec3 p) { return std::atan2(p.x, p.z) / (2 * std::numbers::pi); }

class MobileGroups : public ::testing::TestWithParam<bool> {};  // free or structured

TEST_P(MobileGroups, TravelAlongTheirULineByTheAngleTheViewOrbits) {
  Scene s = sphere_with_mobile_group("sphere", GetParam());
  DecalSurface surface = reference::project_decals_by_rays(s);
  ASSERT_EQ(surface.size(), GetParam() ? 4u : 3u * (1u << kMaxHatchLevel) + 1u) << "free: as drawn; structured: "
                                                                                   "with the hatches between";
  MobileHatching mobile(s, surface);
  ASSERT_TRUE(mobile.moves(0));
  std::vector<double> shifts;
  for (double degrees : {0.0, 20.0, 40.0, -30.0}) {
    Scene view = orbited(s, degrees);
    std::vector<MobileHatching::Placement> placed = mobile.place(view, 0.5, 0.1);
    ASSERT_EQ(placed.size(), 1u);
    ASSERT_EQ(placed[0].u.size(), 1u) << degrees << " degrees: one maximum of l on a sphere";
    const double du = around(placed[0].u[0] - placed[0].c.x);
    std::printf("[mobile] orbit %+.0f deg: u moves %+.5f (%+.2f deg), l %.4f\n", degrees, du, 360 * du, placed[0].l[0]);
    EXPECT_NEAR(std::abs(du), std::abs(degrees) / 360, kSample) << degrees;
    EXPECT_GT(placed[0].l[0], 0.99) << "a sphere turns its normal with the view";
    shifts.push_back(du);
    // Its hatches' surface points move with it: by the same angle about the up axis.
    for (const MobileHatching::Copy& copy : mobile.copies(surface, 0, placed))
      for (size_t k = 0; k < copy.decal.points.size(); ++k) {
        if (copy.decal.points[k].object == kMissed || surface[0].points[k].object == kMissed) continue;
        double moved = turns_about_up(decal_point_world(s, copy.decal.points[k])) -
                       turns_about_up(decal_point_world(s, surface[0].points[k]));
        ASSERT_NEAR(std::abs(around(moved)), std::abs(degrees) / 360, kSample) << degrees << " point " << k;
      }
  }
  EXPECT_GT(shifts[1] * shifts[2], 0) << "one way round";
  EXPECT_LT(shifts[2] * shifts[3], 0) << "the other way when the view orbits back";
}

INSTANTIATE_TEST_SUITE_P(Kinds, MobileGroups, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Free" : "Structured"; });

// "Each group's extent is governed by the width of the peak": on a sphere the peak keeps its
// width as the view orbits; on an ellipsoid (x stretched 2.5 times) the group drawn where the
// surface faces the eye is carried toward the pointed end as the view turns, where the normal
// turns faster with u (about a / b = 2.5 times against b / a on the flank), and narrows.
TEST(MobileHatching, ACopysExtentFollowsItsPeaksWidth) {
  const double width_samples = 2 * kMobileSamples / 6.0;  // l = cos(angle) >= 1/2 within 60 degrees each side
  Scene sphere = sphere_with_mobile_group();
  DecalSurface on_sphere = reference::project_decals_by_rays(sphere);
  MobileHatching round(sphere, on_sphere);
  for (double degrees : {0.0, 30.0, 70.0})
    EXPECT_NEAR(round.place(orbited(sphere, degrees), 0.5, 0.1)[0].scale.at(0), 1.0, 2.0 / width_samples) << degrees;
  Scene ellipsoid = sphere_with_mobile_group("sphere", false, 2.5f, {0, 1.5f, 7});
  DecalSurface on_ellipsoid = reference::project_decals_by_rays(ellipsoid);
  MobileHatching mobile(ellipsoid, on_ellipsoid);
  std::vector<MobileHatching::Placement> p = mobile.place(orbited(ellipsoid, 70), 0.5, 0.1);
  ASSERT_FALSE(p[0].u.empty());
  std::printf("[mobile] ellipsoid orbited 70 degrees: peak %.3f x the drawn one\n", p[0].scale[0]);
  EXPECT_LT(p[0].scale[0], 0.9) << "nearer the pointed end, a narrower peak";
}

TEST(MobileHatching, FadesAsTheLightingApproachesTheThreshold) {
  Scene s = orbited(sphere_with_mobile_group(), 25);
  DecalSurface surface = reference::project_decals_by_rays(s);
  MobileHatching mobile(s, surface);
  const double l = mobile.place(s, 0.5, 0.1)[0].l.at(0);
  EXPECT_EQ(mobile.place(s, 0.5, 0.1)[0].alpha.at(0), 1.0);
  EXPECT_NEAR(mobile.place(s, l - 0.05, 0.1)[0].alpha.at(0), 0.5, 1e-9);
  EXPECT_TRUE(mobile.place(s, l + 1e-6, 0.1)[0].u.empty()) << "omitted below the threshold";
  // window_lines draws each copy with the fade's alpha.
  s.params.set("hatching.mobile_fade", 0.1);
  s.params.set("hatching.mobile_threshold", double(float(l - 0.05)));
  const SurfaceStrokes strokes = surface_strokes(s, surface);
  WindowLines lines = window_lines(s, s.params.get<StrokesParams>(), LineObjects::Strokes, nullptr, &strokes);
  size_t hatches = 0;
  for (const WindowPath& p : lines.paths) {
    if (p.kind != LineKind::Hatching) continue;
    ++hatches;
    EXPECT_NEAR(p.alpha_scale, (l - double(float(l - 0.05))) / 0.1, 1e-6);
  }
  EXPECT_GE(hatches, 4u);
}

// A mesh without (u, v) of its own gets one on the disk-like patch under the group (CGAL's
// LSCM, u along the drawing camera's right): on the sphere that is nearly its parallel near
// the equator, and the group follows the orbit as on the sphere's own (u, v).
TEST(MobileHatching, AMeshWithoutAParameterizationGetsOneUnderTheGroup) {
  Scene s = sphere_with_mobile_group("sphere", false, 1, {0, 1, 4}, false);
  DecalSurface surface = reference::project_decals_by_rays(s);
  MobileHatching mobile(s, surface);
  for (double degrees : {0.0, 20.0, -30.0}) {
    std::vector<MobileHatching::Placement> placed = mobile.place(orbited(s, degrees), 0.5, 0.1);
    ASSERT_EQ(placed[0].u.size(), 1u) << degrees;
    std::vector<MobileHatching::Copy> copies = mobile.copies(surface, 0, placed);
    double moved = 0, points = 0;
    for (size_t k = 0; k < surface[0].points.size(); ++k) {
      if (copies[0].decal.points[k].object == kMissed || surface[0].points[k].object == kMissed) continue;
      moved += around(turns_about_up(decal_point_world(s, copies[0].decal.points[k])) -
                      turns_about_up(decal_point_world(s, surface[0].points[k])));
      ++points;
    }
    ASSERT_GT(points, 0) << degrees;
    std::printf("[mobile, LSCM patch] orbit %+.0f deg: the hatch moves %+.2f deg about the up axis\n", degrees,
                360 * moved / points);
    EXPECT_NEAR(std::abs(360 * moved / points), std::abs(degrees), 3.0) << "a straight line of a conformal map";
  }
}

// A patch that is no disk however small (the group spans two pieces of the mesh, so two
// borders) is refused, naming the file, the group and the object; so is a group mixing
// mobile and stationary strokes.
TEST(MobileHatching, AGroupWithoutADiskUnderItIsRefused) {
  Scene s = sphere_with_mobile_group("sphere", false, 1, {0, 1, 4}, false);
  DecalSurface surface = reference::project_decals_by_rays(s);
  Mesh two = *s.objects[0].mesh;  // the sphere and a copy of it beside it
  const auto n = uint32_t(two.positions.size()), faces = uint32_t(two.triangles.size());
  for (uint32_t v = 0; v < n; ++v) two.positions.push_back(two.positions[v] + glm::vec3(3, 0, 0));
  for (uint32_t f = 0; f < faces; ++f) two.triangles.push_back(two.triangles[f] + glm::uvec3(n));
  compute_normals(two);
  s.objects[0].mesh = std::make_shared<const Mesh>(std::move(two));
  for (ProjectedDecal& d : surface)  // every other point on the copy
    for (size_t k = 0; k < d.points.size(); k += 2)
      if (d.points[k].object != kMissed) d.points[k].face += faces;
  try {
    MobileHatching mobile(s, surface);
    FAIL() << "no disk under the group";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("mobile hatches: hatching group 0: object 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no disk-like patch"), std::string::npos) << e.what();
  }
  s.stroke_files[0].strokes[1].mobile = false;
  EXPECT_THROW(hatching_groups(s), SceneError) << "a group's strokes all mobile or all stationary";
}

// A (u, v) of one u (every face flat in the chart) has no u-line: refused, not divided by.
TEST(MobileHatching, ADegenerateChartIsRefused) {
  Scene s = sphere_with_mobile_group();
  DecalSurface surface = reference::project_decals_by_rays(s);
  Mesh flat = *s.objects[0].mesh;
  for (glm::vec2& uv : flat.uvs) uv.x = 0.25f;
  s.objects[0].mesh = std::make_shared<const Mesh>(std::move(flat));
  EXPECT_THROW(MobileHatching(s, surface), SceneError);
}

// The snowman's trees with their cones stripped of (u, v): each group travels on an LSCM patch
// of a coarse cone, where l(u) ripples from sample to sample (the smoothing's samples cross
// faces). Seen from where they were drawn each group places one copy, as on the cones' own
// (u, v) (near where it was drawn: the ripples move the peak a few samples); at the orbit's
// end at most one (a patch does not reach round the cone, so its peak may have left it).
TEST(MobileHatching, RipplesOfLOnACoarsePatchPlaceNoCopies) {
  Scene path = testing::cones_without_uvs(load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/snowman_mobile.json"));
  DecalSurface surface = reference::project_decals_by_rays(path);
  MobileHatching mobile(path, surface);
  const HatchingParams p = path.params.get<HatchingParams>();
  const std::vector<HatchGroup> groups = hatching_groups(path);
  for (int frame : {0, path.animation->frames - 1}) {
    size_t moving = 0;
    const auto placed = mobile.place(scene_at_frame(path, frame), p.mobile_threshold, p.mobile_fade);
    for (size_t k = 0; k < placed.size(); ++k) {
      const MobileHatching::Placement& g = placed[k];
      if (!groups[k].mobile) continue;
      ++moving;
      std::printf("[snowman, patch charts, frame %d] a mobile group: %zu copies, the first at u %+.4f from c\n", frame,
                  g.u.size(), g.u.empty() ? 0.0 : g.u[0] - g.c.x);
      EXPECT_LE(g.u.size(), 1u) << frame;
      if (frame == 0) {
        EXPECT_EQ(g.u.size(), 1u);
      }
    }
    EXPECT_EQ(moving, 4u) << "the trees' four groups";
  }
}

class MobileHatchingStrokes : public testing::GlTest {};

// A free mobile group on the sphere, the view orbited 30 degrees: both backends place it
// (each from its own projection) where the ID image, visibility and stroke raster agree.
TEST_F(MobileHatchingStrokes, AFreeGroupAgreesOnBothBackends) {
  Scene s = orbited(sphere_with_mobile_group("sphere", true), 30);
  for (const StageParity& r : run_parity(s, {"id_image", "visibility", "stroke"})) {
    std::printf("[free mobile group] %s  [%s]\n", format_diff(r.name, r.diff).c_str(), r.note.c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

// The snowman's trees carry two layers of mobile hatching (Fig. 8): along its orbit they move
// on the cones, and the ID image, visibility and stroke raster agree on both backends.
TEST_F(MobileHatchingStrokes, TheSnowmansTreesAgreeAlongTheOrbit) {
  Scene path = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/snowman_mobile.json");
  DecalSurface surface = reference::project_decals_by_rays(path);
  MobileHatching mobile(path, surface);
  const HatchingParams p = path.params.get<HatchingParams>();
  size_t moving = 0;
  for (size_t d = 0; d < surface.size(); ++d) moving += mobile.moves(d);
  EXPECT_GT(moving, 40u) << "the trees' four groups";
  for (int frame : {0, path.animation->frames - 1}) {
    Scene scene = scene_at_frame(path, frame);
    for (const MobileHatching::Placement& g : mobile.place(scene, p.mobile_threshold, p.mobile_fade))
      for (size_t m = 0; m < g.u.size(); ++m)
        std::printf("[snowman frame %d] a mobile group at u %+.4f from where drawn, l %.3f\n", frame,
                    around(g.u[m] - g.c.x), g.l[m]);
    for (const StageParity& r : run_parity(scene, {"id_image", "visibility", "stroke"})) {
      std::printf("[snowman frame %d] %s  [%s]\n", frame, format_diff(r.name, r.diff).c_str(), r.note.c_str());
      EXPECT_TRUE(r.pass) << frame << " " << r.name << ": " << r.note;
    }
  }
}

}  // namespace
}  // namespace plumbago

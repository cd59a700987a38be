// Scenes far from the world's origin (Scene::origin): both backends render relative to the
// objects' center, so translating a whole scene (objects and camera) by 1e3, 1e6 or 1e7
// changes neither its image nor its parity. Before, an offset of 1e6 made the G-buffers'
// depth and normals differ on 99.7% of the pixels.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "common/mesh/procedural.hpp"
#include "common/scene/scene.hpp"
#include "common/util/image_compare.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/far_mesh_files.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string point(double x, double y, double z, double offset) {
  std::ostringstream s;
  s.precision(17);
  s << '[' << x + offset << ", " << y + offset << ", " << z + offset << ']';
  return s.str();
}

// A CAD part (pencil, every effect) and a torus drawn with strokes, the whole scene moved
// by `offset` along each axis: the objects' transforms and the camera.
Scene moved_scene(double offset) {
  std::string t = number(offset);
  std::string torus_at = number(offset + 1.6);
  return parse_scene(R"({"objects": [
      {"mesh": {"procedural": "cad"}, "transform": [1,0,0,0, 0,1,0,0, 0,0,1,0, )" +
                         t + ", " + t + ", " + t + R"(, 1]},
      {"mesh": {"procedural": "torus"}, "style": "strokes",
       "transform": [0.5,0,0,0, 0,0.5,0,0, 0,0,0.5,0, )" +
                         torus_at + ", " + t + ", " + t + R"(, 1]}],
    "effects": ["contours", "interior", "crosshatch", "paper", "basecoat"],
    "camera": {"eye": )" +
                         point(2.5, 2.0, 4.0, offset) + R"(, "target": )" + point(0.6, 0, 0, offset) + R"(,
               "up": [0, 1, 0], "fov_deg": 40},
    "resolution": [240, 180]})",
                     "moved by " + t, ".");
}

TEST(SceneOrigin, IsTheObjectsCenterAndKeepsRelativeCoordinatesExact) {
  Scene at_zero = moved_scene(0), far = moved_scene(1e7);
  EXPECT_NEAR(far.origin.x - at_zero.origin.x, 1e7, 1e-6);
  EXPECT_NEAR(far.origin.z - at_zero.origin.z, 1e7, 1e-6);
  for (size_t i = 0; i < far.objects.size(); ++i)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(far.objects[i].transform[c][r], at_zero.objects[i].transform[c][r], 1e-6);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(far.camera.eye[k], at_zero.camera.eye[k], 1e-6);
    EXPECT_NEAR(far.camera.target[k], at_zero.camera.target[k], 1e-6);
  }
  EXPECT_NEAR(far.camera.near, at_zero.camera.near, 1e-6);
}

class FarFromOrigin : public testing::GlTest {};

// Every stage's parity (as in the other parity tests, with their tolerances), and the GPU
// image against the same scene at the origin.
TEST_F(FarFromOrigin, SameImageAndParityAt1e3_1e6_1e7) {
  Image at_zero = gpu::Renderer(moved_scene(0)).render().color;
  for (double offset : {1e3, 1e6, 1e7}) {
    Scene scene = moved_scene(offset);
    ImageDiff d = compare_images(gpu::Renderer(scene).render().color, at_zero, 2.0 / 255);
    std::printf("[origin %g] GPU image vs at the origin: %s\n", offset, format_diff("image", d).c_str());
    EXPECT_LT(d.over_tolerance, 1e-3) << offset;
    auto results = run_parity(scene);
    EXPECT_GE(results.size(), 10u);
    for (const StageParity& r : results) {
      std::printf("[origin %g] %s\n", offset, format_diff(r.name, r.diff).c_str());
      EXPECT_TRUE(r.pass) << offset << ": " << r.name;
    }
  }
}

// A mesh whose file coordinates sit at 1e6 (a cube with corners on float's 1/16 grid
// there, so the file loses nothing): the image is the same cube's at the origin.
TEST_F(FarFromOrigin, MeshFileCoordinatesAt1e6) {
  testing::TempDir tmp;
  auto cube_obj = [](double c) {
    std::ostringstream obj;
    obj.precision(17);
    for (int v = 0; v < 8; ++v)
      obj << "v " << c + (v & 1 ? 0.5 : -0.5) << ' ' << c + (v & 2 ? 0.5 : -0.5) << ' ' << c + (v & 4 ? 0.5 : -0.5)
          << '\n';
    obj << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    return obj.str();
  };
  tmp.write("near.obj", cube_obj(0));
  tmp.write("far.obj", cube_obj(1e6));
  auto scene = [&](const char* file) {
    return parse_scene(std::string(R"({"mesh": ")") + file + R"(", "effects": ["contours", "interior"],
        "resolution": [160, 120]})",
                       file, tmp.dir());
  };
  ImageDiff d = compare_images(gpu::Renderer(scene("far.obj")).render().color,
                               gpu::Renderer(scene("near.obj")).render().color, 2.0 / 255);
  std::printf("[origin 1e6 mesh] %s\n", format_diff("image", d).c_str());
  EXPECT_EQ(d.over_tolerance, 0.0);
  for (const StageParity& r : run_parity(scene("far.obj"), {"gbuffer"})) EXPECT_TRUE(r.pass) << r.name;
}

// The issue's case (32): a sphere whose file sits at 1e6 or 1e7 read as a box, on every
// format, when the file was read (or welded) in float before it was centered. Now each
// format is read in double, centered, then welded on a grid relative to the sphere's size:
// the same pixels as the file at 0, on both backends, for a pencil object (camera framed
// automatically) and a stroke object (camera given, moved with the file).
TEST_F(FarFromOrigin, SphereFilesOfEveryFormatAt1e6And1e7RenderAsAt0) {
  testing::TempDir tmp;
  const Mesh sphere = make_procedural("sphere");
  // The strokes object with an explicit camera at the file's offset, the pencil one framed
  // automatically.
  auto scene = [&](const std::string& file, const char* style, double offset) {
    const bool strokes = std::string(style) == "strokes";
    const std::string camera = R"("camera": {"eye": )" + point(0.3, 0.2, 3.5, offset) + R"(, "target": )" +
                               point(0, 0, 0, offset) + R"(, "up": [0, 1, 0], "fov_deg": 40},)";
    return parse_scene(R"({"objects": [{"mesh": ")" + file + R"(", "style": ")" + style + R"("}],
        "effects": [)" + (strokes ? R"("basecoat")" : R"("contours", "interior")") +
                           "], " + (strokes ? camera : "") + R"( "resolution": [96, 72]})",
                       file, tmp.dir());
  };
  for (const std::string& format : testing::text_mesh_formats())
    for (const char* style : {"pencil", "strokes"}) {
      if (std::string(style) == "strokes" && format != "obj") continue;  // the readers are the pencil case's
      const std::string at_zero = tmp.write("sphere_0." + format, testing::mesh_text_at(sphere, format, 0));
      const Scene zero = scene(at_zero, style, 0);
      const Image gpu_zero = gpu::Renderer(zero).render().color, ref_zero = reference::render(zero).color;
      for (double offset : {1e6, 1e7}) {
        const std::string far =
            tmp.write("sphere_" + number(offset) + "." + format, testing::mesh_text_at(sphere, format, offset));
        const Scene s = scene(far, style, offset);
        EXPECT_EQ(s.objects[0].mesh->positions.size(), zero.objects[0].mesh->positions.size()) << far;
        EXPECT_EQ(s.objects[0].mesh->triangles.size(), zero.objects[0].mesh->triangles.size()) << far;
        ImageDiff g = compare_images(gpu::Renderer(s).render().color, gpu_zero, 0.0);
        ImageDiff r = compare_images(reference::render(s).color, ref_zero, 0.0);
        std::printf("[far %s %s %g] GPU: %s; reference: %s\n", format.c_str(), style, offset,
                    format_diff("image", g).c_str(), format_diff("image", r).c_str());
        EXPECT_EQ(g.max_abs, 0.0) << far;
        EXPECT_EQ(r.max_abs, 0.0) << far;
      }
    }
}

}  // namespace
}  // namespace plumbago

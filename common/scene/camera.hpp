// The pinhole camera of docs/conventions.md: right-handed view space looking down -Z, vertical field
// of view, pixel centers at (i + 0.5, j + 0.5) from the bottom-left corner.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace plumbago {

struct Camera {
  glm::vec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  float fov_deg = 40;
  float near = 0.1f, far = 100;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;  // OpenGL clip space, depth in [-1, 1]
  // Unit world-space viewing direction (target - eye).
  glm::vec3 forward() const;
};

// Primary-ray directions of one camera and image size (docs/conventions.md), the camera basis
// computed once.
class PrimaryRays {
 public:
  PrimaryRays(const Camera& camera, int width, int height);
  // Unit world-space direction through window point (px, py); pixel centers sit at
  // integer + 0.5, from the bottom-left corner.
  glm::vec3 direction(float px, float py) const;

 private:
  glm::mat3 camera_to_world_;
  float tan_half_, aspect_;
  int width_, height_;
};

// What float buffers can render (docs/bad-input.md); scenes and --size are checked against
// these when read.
// |x|, |y|, |z| of any world-space point (the eye and every vertex): the ray-triangle test
// and the face normals multiply up to four differences of coordinates, each at most
// 2 sqrt(3) 1e9, and (3.5e9)^4 = 1.4e38 stays under float's 3.4e38.
constexpr double kMaxCoordinate = 1e9;
// Direction vectors (up, light and view directions) are normalized in float: their length
// must lie in [1e-18, 1e18], so that its square is a normal float.
constexpr double kMinDirectionLength = 1e-18, kMaxDirectionLength = 1e18;
// The narrower field of view (vertical, or horizontal at the image's aspect), in degrees.
// Measured: the backends' images agree down to 1e-5 degrees and differ at 1e-6, where
// neighbouring pixels' rays are no longer apart in float; the bound leaves a factor 100.
constexpr double kMinFovDeg = 1e-3;
// far / near: the GPU's float depth test resolves a relative depth of about
// 2^-24 far / near. Measured (torus, far 10): the backends' images agree at 5e6 and differ
// on 31% of the pixels at 1e7; the bound leaves a factor 5.
constexpr double kMaxFarOverNear = 1e6;
// (far - near) / far: eye-space depth, a float of the size of far, has about 8000 steps
// between the planes at 1e-3. Measured (fitted planes, a telephoto camera): the backends'
// images differ at 1.25e-4 and agree at 2.5e-4.
constexpr double kMinDepthExtent = 1e-3;
// Sine of the angle between up and the viewing direction: below it the image's roll is
// ill-defined.
constexpr double kMinUpSine = 1e-3;

// Why a camera cannot be rendered: the camera key at fault ("eye", "near", ...) and what.
struct CameraFault {
  std::string key, what;
};
// The first fault of `c` for an image of `aspect` = width / height; none when it renders.
// `c` is relative to `origin` (Scene::origin): the world-space bounds apply to c + origin.
std::optional<CameraFault> camera_fault(const Camera& c, double aspect, glm::dvec3 origin = glm::dvec3(0.0));
// "1e+18", "(1, 2, 3)": numbers as the messages about cameras and scenes print them.
std::string format_number(double v);
std::string format_point(glm::dvec3 p);

// A camera fitted to a bounding sphere: looks at its center from `direction`, with the
// sphere filling the view and near/far planes bracketing it.
Camera fit_camera(glm::vec3 center, float radius, glm::vec3 direction, float fov_deg);
// Sets the near and far planes to bracket a bounding sphere seen from the camera.
void fit_planes(Camera& c, glm::vec3 center, float radius);

}  // namespace plumbago

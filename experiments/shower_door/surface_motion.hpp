// Where the surface seen at each pixel of one frame was in the previous frame: the true
// motion of the surface under a camera orbit, from the G-buffers' ids and barycentrics.
// Used to measure the shower-door effect (Nienhaus & Döllner 2004, §4 and §4.3) in
// experiments/shower_door/README.md.
#pragma once

#include <vector>

#include "common/scene/gbuffer.hpp"

namespace plumbago::shower_door {

// `c` with its eye turned about c.target, around the axis c.up, by `degrees` (right-handed).
Camera orbit(const Camera& c, float degrees);

// The world-space point each covered pixel sees, from its triangle id and barycentrics
// over `objects` (world_geometry of the G-buffer's scene). 4 ch: xyz, w = 1 where covered,
// all 0 on the background. The orbit moves only the camera, so a world point is also a
// fixed object-space point.
Image surface_points(const std::vector<WorldObject>& objects, const GBuffer& g);

// Window coordinates (pixel centers at i + 0.5, docs/conventions.md) of world point `x` seen by `c`
// in a width x height image; .z = linear view depth.
glm::vec3 project(const Camera& c, int width, int height, glm::vec3 x);

struct MotionParams {
  float footprints = 3.0f;     // visibility: the previous frame sees points within this many pixel sizes of x
  float min_motion_px = 1.0f;  // pixels whose surface moved less than this are left out
};

// For each pixel p of the next frame: p', where its surface point x was in the previous
// frame. 3 ch: p'.x, p'.y, valid. Valid when p is covered, the four pixel centers around
// p' (a bilinear read's) lie inside the image and the previous frame's surface points
// there are all within `footprints` x (one pixel's size at x's depth) of x (x was
// visible, and not at a silhouette or occlusion edge, where a read would mix in another
// surface), and |p' - p| >= min_motion_px.
Image surface_motion(const Camera& prev, const Image& prev_points, const Image& next_points,
                     const MotionParams& params = {});

}  // namespace plumbago::shower_door

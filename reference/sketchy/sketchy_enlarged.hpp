// The `object` style's geometry buffer (Nienhaus & Döllner §4.2-4.3), CPU
// reference: the enlarged sketchy objects traced, each pixel holding the 3D noise
// coordinate of the surface it sees. The twin of gpu/sketchy/sketchy_enlarged.cpp.
#pragma once

#include "common/scene/scene.hpp"
#include "common/util/image.hpp"

namespace plumbago::reference {

// 4 ch: noise coordinate (common/sketchy/sketchy.hpp noise_coordinates, interpolated with the
// hit's barycentrics), alpha = coverage; 0 where no enlarged object is hit.
Image enlarged_noise_coordinates(const Scene& enlarged, int width, int height);

}  // namespace plumbago::reference

// The machine's own limits at a scene's size (`plumbago bench --limits`): the cheapest pass
// of each kind, timed like the frame's passes. A pass read as a multiple of its probe carries
// across machines where its time does not: llvmpipe on two 2-core machines differs by 3x,
// and an H100 has 8 raster units against an RTX 3060's 48.
#pragma once

#include <string>
#include <vector>

#include "common/scene/scene.hpp"

namespace plumbago::gpu {

enum class Probe {
  Fullscreen,  // a full-screen fragment pass writing a constant into one 32-bit target
  Fetch3x3,    // the same, summing the 3x3 texels around its pixel
  Compute,     // the compute twins of the two above, one invocation a pixel
  Compute3x3,
  Raster,    // the scene's triangles into one 32-bit target, depth-tested, a trivial shader
  Readback,  // one 8-bit RGBA target of the window's size read back to the CPU
};
inline constexpr Probe kProbes[] = {Probe::Fullscreen, Probe::Fetch3x3, Probe::Compute,
                                    Probe::Compute3x3, Probe::Raster,   Probe::Readback};
const char* probe_name(Probe probe);

struct ProbeTime {
  Probe probe;
  double ms;  // the median of the repeats
};

// One probe at the scene's window size: the median of `repeats` runs. Needs the GL context.
double measure_probe(Probe probe, const Scene& scene, int repeats);
// Every probe (kProbes), each `repeats` times.
std::vector<ProbeTime> measure_limits(const Scene& scene, int repeats = 9);

}  // namespace plumbago::gpu

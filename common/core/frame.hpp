// What a backend returns for one frame: the image, what ran and what each pass cost, and
// (on request) every intermediate buffer by name.
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/core/handle.hpp"
#include "common/util/image.hpp"

namespace plumbago {

struct WindowLines;  // common/strokes/strokes.hpp
struct Visibility;   // common/strokes/visibility.hpp

struct PassTime {
  std::string name;
  double ms;
};

struct Frame {
  Image color;                           // RGB, row 0 = bottom
  std::vector<PassTime> ran;             // every pass that ran, in order
  std::map<std::string, Image> buffers;  // intermediate buffers when asked for
  // With the buffers, a strokes frame's lines in the window as its ID image and visibility
  // took them (common/strokes/strokes.hpp), and what its visibility found: the first round's
  // sample count and flags, the visible runs (the GPU's without their polylines, which it
  // makes on the GPU). None without strokes.
  std::shared_ptr<const WindowLines> lines;
  std::shared_ptr<const Visibility> visibility;
  // What the frame drew, by name: the visible strokes per line kind ("strokes.crease", ...),
  // the paths and samples, the hatching groups' scale and level (common/strokes/stroke.hpp
  // stroke_counts), the silhouette segments and chains (common/strokes/silhouette_chains.hpp
  // silhouette_counts); empty without strokes.
  std::map<std::string, double> counts;
  // A GPU frame (Renderer::render_frame): the CPU time of the thread that drives GL while
  // the frame ran (the driver's work in that thread included, llvmpipe's raster and compute
  // threads not), and the bytes it read back from GPU memory.
  double host_ms = 0;
  size_t readback_bytes = 0;
};

// A copy of a frame's data for Frame::lines and Frame::visibility; none where it has none.
template <class T>
std::shared_ptr<const T> kept(const T* value) {
  return value ? std::make_shared<const T>(*value) : nullptr;
}

// What a reference frame of a camera path hands the next one: its stages' CPU data (a
// stage reads what it made itself the frame before: FrameData::before), and the path frame it
// came from. A GPU renderer keeps its own on the GPU, across its frames.
struct Carry {
  int frame = -1;  // none
  DataTable data;
  // The data, where the frame `frame` follows the one it came from; else null.
  const DataTable* before(int next) const { return frame >= 0 && frame + 1 == next ? &data : nullptr; }
};

struct FrameOptions {
  bool keep_buffers = false;  // fill Frame::buffers (for --dump-stages and compare)
  // The reference: the frame reads the carry where it follows the frame it came from, then
  // holds this frame's (PathFrames keeps one along a path). Null: none.
  Carry* carry = nullptr;
};

// The middle value of timings (the upper one of an even count); `ms` must not be empty.
inline double median(std::vector<double> ms) {
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// CPU time of the calling thread since construction (not time spent waiting).
class ThreadClock {
 public:
  ThreadClock() : start_(now()) {}
  double ms() const { return now() - start_; }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
  }
  double start_;
};

// The G-buffer channels as named images (ids as floats), for dumps and comparisons.
struct GBuffer;
void add_gbuffer_buffers(const GBuffer& g, std::map<std::string, Image>& out, const std::string& prefix = "gbuffer");

}  // namespace plumbago

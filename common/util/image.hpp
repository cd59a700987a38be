// Images shared by both backends. Row 0 is the BOTTOM row (OpenGL window convention,
// docs/conventions.md); files are flipped on write so they look right in a viewer.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace plumbago {

class OutputFile;
class OutputFiles;

// A window rectangle of pixels [x0, x1) x [y0, y1), rows from the bottom.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

template <class T>
struct ImageT {
  int width = 0, height = 0, channels = 0;
  std::vector<T> data;  // row-major from the bottom row, channels interleaved

  ImageT() = default;
  ImageT(int w, int h, int c, T fill = T{}) : width(w), height(h), channels(c), data(size_t(w) * h * c, fill) {}

  T& at(int x, int y, int c = 0) { return data[(size_t(y) * width + x) * channels + c]; }
  const T& at(int x, int y, int c = 0) const { return data[(size_t(y) * width + x) * channels + c]; }
  T* pixel(int x, int y) { return &data[(size_t(y) * width + x) * channels]; }
  const T* pixel(int x, int y) const { return &data[(size_t(y) * width + x) * channels]; }
  size_t pixels() const { return size_t(width) * height; }
  bool empty() const { return data.empty(); }
};

using Image = ImageT<float>;
using ImageU32 = ImageT<uint32_t>;

// Writes PNG (8-bit, clamped to [0,1]) or EXR (float), chosen by extension, through
// OpenImageIO. Writes to a temporary name and renames when complete, so a failure leaves
// no partial file. Throws std::runtime_error naming the path.
void write_image(const Image& img, const std::string& path);
// The same into `file`'s temporary name (common/util/output_file.hpp); the caller commits.
void write_image(const Image& img, OutputFile& file);
// The bytes of `img` as a PNG of it holds them: top row first, each value clamped to [0,1]
// and rounded to 8 bits by OpenImageIO's conversion, the one write_image uses.
std::vector<uint8_t> png_bytes(const Image& img);
// Refuses a path whose extension is neither .png nor .exr, naming it.
void check_image_extension(const std::string& path);
// Image files to write: each path with the function that makes its image when its turn
// comes (so that only one is held at a time).
using ImageFiles = std::vector<std::pair<std::string, std::function<Image()>>>;
// Writes them among `out`'s files (which the caller commits), every path checked before
// the first is written.
void write_images(const ImageFiles& images, OutputFiles& out);
Image read_image(const std::string& path);  // float, bottom row first

// A table of `count` records kept as an image (a stage's per-sample or per-face output):
// one texel per record, record i at (i % kTableRow, i / kTableRow); a single row of
// `count` when fewer, 1 x 1 when none.
constexpr int kTableRow = 1024;
Image table_image(size_t count, int channels);
std::pair<int, int> table_size(size_t count);  // (width, height)

// Any NaN or Inf value?
bool has_non_finite(const Image& img);

}  // namespace plumbago

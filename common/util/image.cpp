#include "common/util/image.hpp"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "common/util/output_file.hpp"

namespace plumbago {

namespace {

// OpenImageIO stores the top row first; ours is the bottom row first.
Image flipped(const Image& img) {
  Image out(img.width, img.height, img.channels);
  size_t row = size_t(img.width) * img.channels;
  for (int y = 0; y < img.height; ++y)
    std::copy_n(&img.data[size_t(y) * row], row, &out.data[size_t(img.height - 1 - y) * row]);
  return out;
}

// The date written into a file's header: OpenImageIO stamps the time of writing when
// none is given (EXR capDate), so that two identical runs would give different bytes.
// SOURCE_DATE_EPOCH (reproducible-builds.org), when set, gives the date; else it is empty.
std::string header_date() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return {};
  char* end = nullptr;
  std::time_t t = std::time_t(std::strtoll(epoch, &end, 10));
  std::tm utc{};
  if (*end != '\0' || !gmtime_r(&t, &utc))
    throw std::runtime_error("SOURCE_DATE_EPOCH: '" + std::string(epoch) + "' is not a time in seconds");
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &utc);
  return text;
}

}  // namespace

void check_image_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".exr" && ext != ".png")
    throw std::runtime_error(path + ": unsupported image extension '" + ext + "' (use .png or .exr)");
}

std::vector<uint8_t> png_bytes(const Image& img) {
  Image top_first = flipped(img);
  std::vector<uint8_t> out(top_first.data.size());
  if (!OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, top_first.data.data(), OIIO::TypeDesc::UINT8, out.data(),
                                  int(out.size())))
    throw std::runtime_error("cannot convert an image to 8 bits");
  return out;
}

void write_image(const Image& img, OutputFile& file) {
  const std::string& path = file.path();
  check_image_extension(path);
  bool is_float = std::filesystem::path(path).extension() == ".exr";
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw std::runtime_error(path + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(img.width, img.height, img.channels, is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("DateTime", header_date());
  bool written = false;
  if (out->open(file.temporary_path(), spec)) {
    written = is_float ? out->write_image(OIIO::TypeDesc::FLOAT, flipped(img).data.data())
                       : out->write_image(OIIO::TypeDesc::UINT8, png_bytes(img).data());
    written = out->close() && written;
  }
  if (!written) throw std::runtime_error(path + ": " + out->geterror());
}

void write_images(const ImageFiles& images, OutputFiles& out) {
  std::vector<OutputFile*> files;
  for (const auto& entry : images) {
    check_image_extension(entry.first);
    files.push_back(&out.add(entry.first));
  }
  for (size_t i = 0; i < images.size(); ++i) write_image(images[i].second(), *files[i]);
}

void write_image(const Image& img, const std::string& path) {
  check_image_extension(path);
  OutputFile file(path);
  write_image(img, file);
  file.commit();
}

Image read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error(path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image img(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.data.data()))
    throw std::runtime_error(path + ": " + in->geterror());
  return flipped(img);
}

bool has_non_finite(const Image& img) {
  for (float v : img.data)
    if (!std::isfinite(v)) return true;
  return false;
}

std::pair<int, int> table_size(size_t count) {
  int rows = std::max(1, int((count + kTableRow - 1) / kTableRow));
  return {count < size_t(kTableRow) ? std::max(1, int(count)) : kTableRow, rows};
}

Image table_image(size_t count, int channels) {
  auto [width, height] = table_size(count);
  return Image(width, height, channels);
}

}  // namespace plumbago

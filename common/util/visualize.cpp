#include "common/util/visualize.hpp"

#include <algorithm>
#include <filesystem>

namespace plumbago {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Image as_rgb(const Image& img) {
  if (img.channels != 2) return img;
  Image out(img.width, img.height, 3);
  for (size_t i = 0; i < img.pixels(); ++i) {
    out.data[i * 3] = img.data[i * 2];
    out.data[i * 3 + 1] = img.data[i * 2 + 1];
  }
  return out;
}

}  // namespace

Image viewable(const std::string& name, const Image& img) {
  Image out = as_rgb(img);
  if (ends_with(name, "normal")) {
    for (float& v : out.data) v = v * 0.5f + 0.5f;
  } else if (ends_with(name, "ids")) {
    float top = *std::max_element(out.data.begin(), out.data.end());
    for (float& v : out.data) v = top > 0 ? v / top : 0;
  }
  return out;
}

void dump_buffers(const std::map<std::string, Image>& buffers, const std::string& dir, const std::string& prefix,
                  OutputFiles& out) {
  out.folder(dir);
  ImageFiles files;
  for (const auto& entry : buffers) {  // not a structured binding: clang 14 cannot capture one
    std::string base = (std::filesystem::path(dir) / (prefix + entry.first)).string();
    files.emplace_back(base + ".png", [&entry] { return viewable(entry.first, entry.second); });
    files.emplace_back(base + ".exr", [&entry] { return as_rgb(entry.second); });
  }
  write_images(files, out);
}

}  // namespace plumbago

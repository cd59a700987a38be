// Images: files round-trip with the bottom row first, and a failed write leaves nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/util/image.hpp"
#include "common/util/image_compare.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

Image ramp() {
  Image img(5, 3, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = float(x + 5 * y + c) / 20.0f;
  return img;
}

TEST(ImageFiles, ExrRoundTripsExactlyAndPngToEightBits) {
  testing::TempDir tmp;
  Image img = ramp();
  write_image(img, tmp.path("a.exr"));
  write_image(img, tmp.path("a.png"));
  EXPECT_EQ(read_image(tmp.path("a.exr")).data, img.data);
  EXPECT_LE(compare_images(read_image(tmp.path("a.png")), img, 0.5 / 255 + 1e-6).max_abs, 0.5 / 255 + 1e-6);
}

TEST(ImageFiles, RefusedWritesLeaveNoFile) {
  testing::TempDir tmp;
  EXPECT_THROW(write_image(ramp(), tmp.path("no/such/folder/a.png")), std::runtime_error);
  EXPECT_THROW(write_image(ramp(), tmp.path("a.bmp")), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_empty(tmp.dir()));
}

TEST(ImageCompare, ReportsMaxRmseAndShareOverTolerance) {
  Image a(2, 2, 1, 0.0f), b(2, 2, 1, 0.0f);
  b.at(1, 1) = 0.5f;
  ImageDiff d = compare_images(a, b, 0.1);
  EXPECT_DOUBLE_EQ(d.max_abs, 0.5);
  EXPECT_DOUBLE_EQ(d.rmse, 0.25);
  EXPECT_DOUBLE_EQ(d.over_tolerance, 0.25);
  Image mask(2, 2, 1, 1.0f);
  mask.at(1, 1) = 0;
  EXPECT_DOUBLE_EQ(compare_images(a, b, 0.1, &mask).over_tolerance, 0.0);
  EXPECT_THROW(compare_images(a, Image(3, 2, 1), 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace plumbago

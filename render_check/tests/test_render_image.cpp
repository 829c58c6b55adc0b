// Image metrics, composition, the heat image and PNG output (image.hpp). Expected metric values
// are computed here from the definitions written in image.hpp, on small images built by hand.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <rotorcert/render/image.hpp>

// stb_image reads the PNG files back: a decoder independent of the writer's code path.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace {

using namespace rotorcert::render;

/// A fresh empty directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("rotorcert_image_" + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

Image read_png(const std::filesystem::path& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) {
    ADD_FAILURE() << "stb_image cannot read " << path << ": " << stbi_failure_reason();
    return {};
  }
  Image image;
  image.width = w;
  image.height = h;
  image.rgba.assign(data, data + std::size_t{4} * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  stbi_image_free(data);
  return image;
}

TEST(RenderImage, OnePixelOffByTen) {
  const Image a = Image::filled(4, 4, {10, 20, 30, 255});
  Image b = a;
  b.set_pixel(2, 1, {20, 20, 30, 255});  // red +10
  const ImageDiff d = compare(a, b, 5);
  EXPECT_EQ(d.max_channel_diff, 10);
  EXPECT_EQ(d.differing_pixels, 1u);
  EXPECT_DOUBLE_EQ(d.share_differing, 1.0 / 16.0);
  EXPECT_EQ(d.over_threshold_pixels, 1u);  // 10 > 5
  // mse = sum of squared RGB differences / (3 N) = 10^2 / (16 * 3).
  const double mse = 100.0 / (16.0 * 3.0);
  EXPECT_DOUBLE_EQ(d.mse, mse);
  EXPECT_NEAR(d.psnr_db, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-12);
  ASSERT_TRUE(d.differing_box.has_value());
  EXPECT_EQ(*d.differing_box, (PixelBox{2, 1, 2, 1}));
  // The threshold is strict: a difference equal to it is not over it.
  EXPECT_EQ(compare(a, b, 10).over_threshold_pixels, 0u);
  EXPECT_EQ(compare(a, b, 9).over_threshold_pixels, 1u);
  // Symmetric.
  const ImageDiff r = compare(b, a, 5);
  EXPECT_EQ(r.max_channel_diff, d.max_channel_diff);
  EXPECT_EQ(r.psnr_db, d.psnr_db);
}

TEST(RenderImage, IdenticalImages) {
  const Image a = Image::filled(3, 2, {1, 2, 3, 4});
  const ImageDiff d = compare(a, a);
  EXPECT_EQ(d.max_channel_diff, 0);
  EXPECT_EQ(d.differing_pixels, 0u);
  EXPECT_EQ(d.share_differing, 0.0);
  EXPECT_EQ(d.mse, 0.0);
  EXPECT_EQ(d.psnr_db, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(d.differing_box.has_value());
  // Zero pixels: nothing differs, PSNR infinite.
  const ImageDiff e = compare(Image::filled(0, 5, {}), Image::filled(0, 5, {}));
  EXPECT_EQ(e.share_differing, 0.0);
  EXPECT_EQ(e.psnr_db, std::numeric_limits<double>::infinity());
}

TEST(RenderImage, AlphaCountsAsDifferenceButNotForPsnr) {
  const Image a = Image::filled(2, 2, {0, 0, 0, 255});
  Image b = a;
  b.set_pixel(0, 1, {0, 0, 0, 0});
  const ImageDiff d = compare(a, b);
  EXPECT_EQ(d.max_channel_diff, 255);
  EXPECT_EQ(d.differing_pixels, 1u);
  EXPECT_DOUBLE_EQ(d.share_differing, 0.25);
  EXPECT_EQ(d.mse, 0.0);
  EXPECT_EQ(d.psnr_db, std::numeric_limits<double>::infinity());
  EXPECT_EQ(*d.differing_box, (PixelBox{0, 1, 0, 1}));
}

TEST(RenderImage, SeveralDifferencesAndTheirBox) {
  const Image a = Image::filled(4, 4, {100, 100, 100, 255});
  Image b = a;
  b.set_pixel(0, 3, {0, 0, 0, 255});        // -100 in r, g, b: bottom-left
  b.set_pixel(3, 0, {100, 100, 101, 255});  // +1 in blue: top-right
  const ImageDiff d = compare(a, b, 1);
  EXPECT_EQ(d.max_channel_diff, 100);
  EXPECT_EQ(d.differing_pixels, 2u);
  EXPECT_EQ(d.over_threshold_pixels, 1u);
  EXPECT_DOUBLE_EQ(d.share_over_threshold, 1.0 / 16.0);
  const double mse = (3.0 * 100.0 * 100.0 + 1.0) / (3.0 * 16.0);
  EXPECT_DOUBLE_EQ(d.mse, mse);
  EXPECT_NEAR(d.psnr_db, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-12);
  EXPECT_EQ(*d.differing_box, (PixelBox{0, 0, 3, 3}));
}

TEST(RenderImage, CompareRejectsMismatchedInputs) {
  const Image a = Image::filled(4, 4, {});
  EXPECT_THROW(compare(a, Image::filled(4, 3, {})), ImageError);
  EXPECT_THROW(compare(a, Image::filled(3, 4, {})), ImageError);
  Image broken = a;
  broken.rgba.pop_back();
  EXPECT_FALSE(broken.consistent());
  EXPECT_THROW(compare(a, broken), ImageError);
  EXPECT_THROW(compare(a, a, -1), ImageError);
  EXPECT_THROW(compare(a, a, 256), ImageError);
  EXPECT_THROW(Image::filled(-1, 2, {}), ImageError);
}

TEST(RenderImage, PixelLayoutIsRowMajorTopFirst) {
  Image image = Image::filled(3, 2, {0, 0, 0, 0});
  image.set_pixel(2, 1, {1, 2, 3, 4});
  // Pixel (x, y) starts at byte 4 (y width + x) = 4 * 5 = 20.
  EXPECT_EQ(image.rgba[20], 1);
  EXPECT_EQ(image.rgba[23], 4);
  EXPECT_EQ(image.pixel(2, 1), (Rgba8{1, 2, 3, 4}));
  EXPECT_THROW((void)image.pixel(3, 0), std::out_of_range);  // inside the buffer, outside the row
  EXPECT_THROW(image.set_pixel(0, -1, {}), std::out_of_range);
}

TEST(RenderImage, SideBySide) {
  const Rgba8 red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255};
  const Image row = side_by_side({Image::filled(2, 2, red), Image::filled(3, 1, green)}, 1, blue);
  ASSERT_EQ(row.width, 2 + 1 + 3);
  ASSERT_EQ(row.height, 2);
  ASSERT_TRUE(row.consistent());
  for (int y = 0; y < 2; ++y) {
    EXPECT_EQ(row.pixel(0, y), red);
    EXPECT_EQ(row.pixel(1, y), red);
    EXPECT_EQ(row.pixel(2, y), blue);  // the gap
  }
  for (int x = 3; x < 6; ++x) {
    EXPECT_EQ(row.pixel(x, 0), green);  // top-aligned
    EXPECT_EQ(row.pixel(x, 1), blue);   // below the shorter image
  }
  EXPECT_EQ(side_by_side({}, 4, blue).width, 0);
  EXPECT_EQ(side_by_side({Image::filled(2, 3, red)}, 5, blue), Image::filled(2, 3, red));
  EXPECT_THROW(side_by_side({Image::filled(2, 2, red)}, -1, blue), ImageError);
}

TEST(RenderImage, DiffHeat) {
  const Image a = Image::filled(4, 1, {100, 100, 100, 255});
  Image b = a;
  b.set_pixel(1, 0, {101, 100, 100, 255});  // d = 1
  b.set_pixel(2, 0, {100, 116, 100, 255});  // d = 16
  b.set_pixel(3, 0, {100, 100, 0, 255});    // d = 100
  const double gain = 8.0;
  const Image heat = diff_heat(a, b, gain);
  ASSERT_EQ(heat.width, 4);
  // The ramp of image.hpp: t = min(1, gain d / 255), r = 3t, g = 3t - 1, b = 3t - 2, clamped to [0, 1].
  const auto expected = [&](int d) {
    const double t = std::min(1.0, gain * d / 255.0);
    const auto byte = [](double v) { return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0))); };
    return Rgba8{byte(3 * t), byte(3 * t - 1), byte(3 * t - 2), 255};
  };
  EXPECT_EQ(heat.pixel(0, 0), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(heat.pixel(1, 0), expected(1));
  EXPECT_EQ(heat.pixel(1, 0), (Rgba8{24, 0, 0, 255}));  // 255 * 3 * 8 / 255 = 24: one level shows
  EXPECT_EQ(heat.pixel(2, 0), expected(16));
  EXPECT_EQ(heat.pixel(3, 0), (Rgba8{255, 255, 255, 255}));
  EXPECT_THROW(diff_heat(a, Image::filled(3, 1, {}), gain), ImageError);
  EXPECT_THROW(diff_heat(a, b, 0.0), ImageError);
}

/// Every byte value in every channel, alpha included (PNG keeps straight alpha, even 0).
Image test_pattern(int w, int h, int seed) {
  Image image = Image::filled(w, h, {});
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>((i * 37 + static_cast<std::size_t>(seed)) % 256);
  return image;
}

TEST(RenderImage, PngRoundTrip) {
  const TempDir dir;
  const Image image = test_pattern(17, 9, 0);
  const auto file = dir.path() / "frame.png";
  write_png(file, image);
  EXPECT_EQ(read_png(file), image);
  // Replacing an existing file: the new pixels, and no temporary left behind.
  const Image other = test_pattern(5, 23, 11);
  write_png(file, other);
  EXPECT_EQ(read_png(file), other);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.png"});
}

TEST(RenderImage, PngWriteFailuresLeaveNothing) {
  const TempDir dir;
  EXPECT_THROW(write_png(dir.path() / "missing" / "frame.png", test_pattern(2, 2, 0)), ImageError);
  EXPECT_THROW(write_png(dir.path() / "empty.png", Image::filled(0, 3, {})), ImageError);
  Image broken = test_pattern(2, 2, 0);
  broken.rgba.resize(3);
  EXPECT_THROW(write_png(dir.path() / "broken.png", broken), ImageError);
  // Renaming onto a directory fails after the temporary was written: it must be removed.
  std::filesystem::create_directory(dir.path() / "taken.png");
  std::filesystem::create_directory(dir.path() / "taken.png" / "x");
  EXPECT_THROW(write_png(dir.path() / "taken.png", test_pattern(2, 2, 0)), ImageError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.png"});
}

}  // namespace

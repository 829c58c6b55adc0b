// RGBA8 images of the render check: PNG output, composition of frames into a row (Figure 1), a
// difference heat image, and the image metrics that compare one implementation's frame with the
// reference's frame.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

namespace rotorcert::render {

/// One pixel or colour: [r, g, b, a], 0..255, not premultiplied.
using Rgba8 = std::array<std::uint8_t, 4>;

/// An image of width x height pixels. Layout of `rgba`: rows top to bottom, pixels left to right
/// within a row, 4 bytes per pixel in the order r, g, b, a; so pixel (x, y) (y = 0: top row) starts
/// at byte 4 * (y * width + x) and rgba.size() == 4 * width * height.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  /// An image filled with `fill`; ImageError when a dimension is negative or the size overflows.
  static Image filled(int width, int height, Rgba8 fill);

  /// Pixel (x, y); std::out_of_range outside the image.
  Rgba8 pixel(int x, int y) const;
  void set_pixel(int x, int y, Rgba8 value);
  /// Dimensions non-negative and rgba.size() == 4 * width * height.
  bool consistent() const;

  friend bool operator==(const Image&, const Image&) = default;
};

/// A file that cannot be written, or an image whose dimensions do not match its data.
class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `image` as an 8-bit RGBA PNG (stb_image_write) to `path`, atomically: the bytes go to a
/// temporary file in the same directory which is then renamed onto `path`, so a reader never sees
/// a half-written file and an existing file is replaced whole or not at all. ImageError when the
/// image is inconsistent or empty, or the file cannot be written (the temporary is removed).
void write_png(const std::filesystem::path& path, const Image& image);

/// The images left to right, top-aligned, `gap` pixels of `background` between neighbours and
/// below shorter images. Width: sum of widths + gap * (n - 1); height: the largest height. No
/// images: an empty (0 x 0) image. ImageError when an image is inconsistent or gap < 0.
Image side_by_side(const std::vector<Image>& images, int gap, Rgba8 background);

/// A heat image of |a - b| for reports. Per pixel, d = the largest |a_c - b_c| over the four
/// channels and t = min(1, gain * d / 255); the colour runs black (t = 0) -> red (t = 1/3) ->
/// yellow (2/3) -> white (1): r = 255 * min(1, 3t), g = 255 * clamp(3t - 1, 0, 1),
/// b = 255 * clamp(3t - 2, 0, 1), each rounded to nearest; alpha 255. Identical pixels are black, so
/// with the default gain a difference of one level is already visible (24, 0, 0).
/// ImageError when the images are inconsistent, differ in size, or gain <= 0.
Image diff_heat(const Image& a, const Image& b, double gain = 8.0);

/// Inclusive pixel rectangle: x_min <= x <= x_max, y_min <= y <= y_max (y = 0: top row).
struct PixelBox {
  int x_min = 0;
  int y_min = 0;
  int x_max = 0;
  int y_max = 0;
  friend bool operator==(const PixelBox&, const PixelBox&) = default;
};

/// How two images of the same size differ. With N = width * height pixels and, per pixel p and
/// channel c, d(p, c) = |a(p, c) - b(p, c)|:
///   max_channel_diff       = max over p and the four channels of d(p, c)            (0..255)
///   differing_pixels       = #{p : d(p, c) > 0 for some channel c}
///   over_threshold_pixels  = #{p : d(p, c) > threshold for some channel c}
///   share_differing        = differing_pixels / N,  share_over_threshold = over_threshold_pixels / N
///   mse                    = sum over p and c in {r, g, b} of d(p, c)^2 / (3 N)     (alpha ignored)
///   psnr_db                = 10 log10(255^2 / mse), +infinity when mse = 0
///   differing_box          = the smallest PixelBox holding every differing pixel; none if none.
/// Alpha counts for the pixel counts and the maximum (a differing alpha is a difference) but not
/// for PSNR, which is the usual measure over colour. N = 0 gives zero shares and infinite PSNR.
struct ImageDiff {
  int max_channel_diff = 0;
  std::size_t differing_pixels = 0;
  std::size_t over_threshold_pixels = 0;
  int threshold = 0;
  double share_differing = 0.0;
  double share_over_threshold = 0.0;
  double mse = 0.0;
  double psnr_db = 0.0;
  std::optional<PixelBox> differing_box;
};

/// The metrics above; `threshold` in 0..255 (ImageError otherwise), and ImageError when the images
/// are inconsistent or differ in size.
ImageDiff compare(const Image& a, const Image& b, int threshold = 0);

}  // namespace rotorcert::render

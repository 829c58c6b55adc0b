#include <rotorcert/render/image.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <limits>
#include <string>
#include <system_error>

#include <unistd.h>

#include <stb_image_write.h>

namespace rotorcert::render {

namespace {

std::size_t byte_count(int width, int height) {
  return std::size_t{4} * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

void require_consistent(const Image& image, const char* what) {
  if (!image.consistent())
    throw ImageError(std::string(what) + ": image of " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " pixels holds " + std::to_string(image.rgba.size()) +
                     " bytes");
}

void require_same_size(const Image& a, const Image& b, const char* what) {
  require_consistent(a, what);
  require_consistent(b, what);
  if (a.width != b.width || a.height != b.height)
    throw ImageError(std::string(what) + ": images of different sizes (" + std::to_string(a.width) + " x " +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + " x " +
                     std::to_string(b.height) + ")");
}

std::uint8_t unit_to_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
}

/// stb_image_write's output callback: append to a byte vector.
void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  const auto* bytes = static_cast<const unsigned char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

Image Image::filled(int width, int height, Rgba8 fill) {
  if (width < 0 || height < 0)
    throw ImageError("image size " + std::to_string(width) + " x " + std::to_string(height) + " is negative");
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(byte_count(width, height));
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) std::copy(fill.begin(), fill.end(), image.rgba.begin() + static_cast<std::ptrdiff_t>(i));
  return image;
}

namespace {
void require_inside(const Image& image, int x, int y) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height)
    throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside a " +
                            std::to_string(image.width) + " x " + std::to_string(image.height) + " image");
}
}  // namespace

Rgba8 Image::pixel(int x, int y) const {
  require_inside(*this, x, y);
  const std::size_t at = byte_count(width, y) + std::size_t{4} * static_cast<std::size_t>(x);
  return {rgba.at(at), rgba.at(at + 1), rgba.at(at + 2), rgba.at(at + 3)};
}

void Image::set_pixel(int x, int y, Rgba8 value) {
  require_inside(*this, x, y);
  const std::size_t at = byte_count(width, y) + std::size_t{4} * static_cast<std::size_t>(x);
  for (std::size_t c = 0; c < 4; ++c) rgba.at(at + c) = value[c];
}

bool Image::consistent() const { return width >= 0 && height >= 0 && rgba.size() == byte_count(width, height); }

void write_png(const std::filesystem::path& path, const Image& image) {
  require_consistent(image, "write_png");
  if (image.width == 0 || image.height == 0) throw ImageError("write_png: " + path.string() + ": empty image");
  std::vector<unsigned char> png;
  if (stbi_write_png_to_func(append_bytes, &png, image.width, image.height, 4, image.rgba.data(), 4 * image.width) == 0)
    throw ImageError("write_png: " + path.string() + ": PNG encoding failed");

  // The temporary's name is unique per process and call, so concurrent writers of the same path
  // never share a temporary; the last rename wins, and each result is a whole file.
  static std::atomic<unsigned long> counter{0};
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::filesystem::path tmp =
      dir / ("." + path.filename().string() + "." + std::to_string(::getpid()) + "." + std::to_string(counter++) + ".tmp");
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (out) out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (out) out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(tmp, ignored);
      throw ImageError("write_png: cannot write " + tmp.string());
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw ImageError("write_png: cannot rename " + tmp.string() + " to " + path.string() + ": " + ec.message());
  }
}

Image side_by_side(const std::vector<Image>& images, int gap, Rgba8 background) {
  if (gap < 0) throw ImageError("side_by_side: negative gap " + std::to_string(gap));
  if (images.empty()) return {};
  int width = 0, height = 0;
  for (const Image& image : images) {
    require_consistent(image, "side_by_side");
    width += image.width;
    height = std::max(height, image.height);
  }
  width += gap * static_cast<int>(images.size() - 1);
  Image out = Image::filled(width, height, background);
  int x0 = 0;
  for (const Image& image : images) {
    const std::size_t row_bytes = std::size_t{4} * static_cast<std::size_t>(image.width);
    for (int y = 0; y < image.height; ++y) {
      const auto src = image.rgba.begin() + static_cast<std::ptrdiff_t>(byte_count(image.width, y));
      const auto dst = out.rgba.begin() + static_cast<std::ptrdiff_t>(byte_count(width, y) + std::size_t{4} * static_cast<std::size_t>(x0));
      std::copy(src, src + static_cast<std::ptrdiff_t>(row_bytes), dst);
    }
    x0 += image.width + gap;
  }
  return out;
}

Image diff_heat(const Image& a, const Image& b, double gain) {
  require_same_size(a, b, "diff_heat");
  if (!(gain > 0.0) || !std::isfinite(gain)) throw ImageError("diff_heat: gain must be positive and finite");
  Image out = Image::filled(a.width, a.height, {0, 0, 0, 255});
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int d = 0;
    for (std::size_t c = 0; c < 4; ++c) d = std::max(d, std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]}));
    const double t = std::min(1.0, gain * d / 255.0);
    out.rgba[i] = unit_to_byte(3.0 * t);
    out.rgba[i + 1] = unit_to_byte(3.0 * t - 1.0);
    out.rgba[i + 2] = unit_to_byte(3.0 * t - 2.0);
  }
  return out;
}

ImageDiff compare(const Image& a, const Image& b, int threshold) {
  require_same_size(a, b, "compare");
  if (threshold < 0 || threshold > 255) throw ImageError("compare: threshold " + std::to_string(threshold) + " outside 0..255");
  ImageDiff r;
  r.threshold = threshold;
  double squares = 0.0;  // exact: at most 3 * 255^2 * N, far below 2^53 for any image that fits in memory
  PixelBox box{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), -1, -1};
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t at = byte_count(a.width, y) + std::size_t{4} * static_cast<std::size_t>(x);
      int d_max = 0;
      for (std::size_t c = 0; c < 4; ++c) {
        const int d = std::abs(int{a.rgba[at + c]} - int{b.rgba[at + c]});
        d_max = std::max(d_max, d);
        if (c < 3) squares += static_cast<double>(d) * d;
      }
      r.max_channel_diff = std::max(r.max_channel_diff, d_max);
      if (d_max > 0) {
        ++r.differing_pixels;
        box = {std::min(box.x_min, x), std::min(box.y_min, y), std::max(box.x_max, x), std::max(box.y_max, y)};
      }
      if (d_max > threshold) ++r.over_threshold_pixels;
    }
  }
  const double n = static_cast<double>(a.width) * a.height;
  if (n > 0) {
    r.share_differing = static_cast<double>(r.differing_pixels) / n;
    r.share_over_threshold = static_cast<double>(r.over_threshold_pixels) / n;
    r.mse = squares / (3.0 * n);
  }
  r.psnr_db = r.mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / r.mse);
  if (r.differing_pixels > 0) r.differing_box = box;
  return r;
}

}  // namespace rotorcert::render

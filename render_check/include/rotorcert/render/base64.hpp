// Base64 (RFC 4648, standard alphabet, with padding): the data: URIs of written glTF buffers
// and of the PNG figures embedded in HTML pages.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace rotorcert::render {

std::string base64(std::span<const std::uint8_t> bytes);

inline std::string base64(std::string_view bytes) {
  return base64(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

}  // namespace rotorcert::render

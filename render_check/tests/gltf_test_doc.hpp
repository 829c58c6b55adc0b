// Small glTF documents built inside the tests: one buffer (base64 data: URI) holding every
// accessor tightly packed, so that each test states exactly the data it loads.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/render/base64.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotorcert::render::test {


enum : int { kUByte = 5121, kUShort = 5123, kUInt = 5125, kFloat = 5126 };

struct Doc {
  nlohmann::json j = {{"asset", {{"version", "2.0"}}}, {"bufferViews", nlohmann::json::array()},
                      {"accessors", nlohmann::json::array()}};
  std::vector<std::uint8_t> bin;

  /// Appends raw bytes as a new buffer view (4-byte aligned) and an accessor over it.
  int add_raw(const void* data, std::size_t bytes, std::size_t count, int ctype, const char* type, bool normalized = false) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t off = bin.size();
    bin.resize(off + bytes);
    if (bytes > 0) std::memcpy(bin.data() + off, data, bytes);
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", off}, {"byteLength", bytes}});
    nlohmann::json a = {{"bufferView", j["bufferViews"].size() - 1}, {"componentType", ctype}, {"count", count}, {"type", type}};
    if (normalized) a["normalized"] = true;
    j["accessors"].push_back(a);
    return static_cast<int>(j["accessors"].size() - 1);
  }
  int add_floats(const std::vector<float>& v, const char* type, std::size_t width) {
    return add_raw(v.data(), v.size() * 4, v.size() / width, kFloat, type);
  }
  template <class T>
  int add_ints(const std::vector<T>& v, int ctype, const char* type, std::size_t width, bool normalized = false) {
    return add_raw(v.data(), v.size() * sizeof(T), v.size() / width, ctype, type, normalized);
  }

  std::string str() const {
    nlohmann::json out = j;
    if (!bin.empty())
      out["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
    return out.dump();
  }
  Scene load(const GltfLimits& limits = {}, const std::string& name = "doc.gltf") const {
    const std::string s = str();
    return load_gltf_memory(reinterpret_cast<const std::uint8_t*>(s.data()), s.size(), limits, name);
  }
};

/// One channel animating node `node`: times and values (3 or 4 wide; CUBICSPLINE: a, v, b triplets).
inline void add_channel(Doc& d, int node, const char* path, const char* interp, const std::vector<float>& times,
                        const std::vector<float>& values) {
  const std::size_t w = std::string(path) == "rotation" ? 4 : 3;
  const int in = d.add_floats(times, "SCALAR", 1);
  const int out = d.add_floats(values, w == 4 ? "VEC4" : "VEC3", w);
  if (!d.j.contains("animations")) d.j["animations"] = {{{"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}}};
  auto& a = d.j["animations"][0];
  a["samplers"].push_back({{"input", in}, {"output", out}, {"interpolation", interp}});
  a["channels"].push_back({{"sampler", a["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

/// A valid skinned, animated document: joints node 0 (root) -> node 1, a mesh on node 2 with one
/// triangle skinned to both, and a LINEAR rotation channel on node 1 (two keyframes).
inline Doc skinned_doc() {
  Doc d;
  const int pos = d.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  const int idx = d.add_ints(std::vector<std::uint16_t>{0, 1, 2}, kUShort, "SCALAR", 1);
  const int jnt = d.add_ints(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0}, kUByte, "VEC4", 4);
  const int wgt = d.add_floats({0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4", 4);
  std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};
  const int ibm_acc = d.add_floats(ibm, "MAT4", 16);
  d.j["nodes"] = {{{"name", "root"}, {"children", {1}}}, {{"name", "tip"}, {"translation", {0, 1, 0}}}, {{"mesh", 0}, {"skin", 0}}};
  d.j["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}, {"JOINTS_0", jnt}, {"WEIGHTS_0", wgt}}}, {"indices", idx}}}}}};
  d.j["skins"] = {{{"joints", {0, 1}}, {"inverseBindMatrices", ibm_acc}}};
  add_channel(d, 1, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, 1, 0});
  return d;
}

/// The strict bar of an eps tolerance class of spec/clauses.json, as an absolute tolerance for
/// values of magnitude `scale` in a format with machine epsilon `eps`.
inline double class_tolerance(const char* cls, double eps, double scale = 1.0) {
  return rotorcert::testing::eps_class_bars(cls).strict * eps * scale;
}
constexpr double kEps64 = 0x1p-52;  // binary64 (NUM-1)
constexpr double kEps32 = 0x1p-23;  // binary32: the precision of glTF FLOAT data

inline std::filesystem::path shared_dir() { return std::filesystem::path(ROTORCERT_SHARED_DIR) / "data"; }

}  // namespace rotorcert::render::test

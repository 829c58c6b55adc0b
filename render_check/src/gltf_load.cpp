// glTF loading: tinygltf parses; everything after that is checked here before it is read
// (GLTF-1 and GLTF-3 of spec/SPEC.md).
#include <rotorcert/render/gltf_load.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <rotorcert/render/capsule.hpp>
#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

std::size_t Scene::vertex_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.positions.size();
  return n;
}

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

namespace {

// glTF-Validator's thresholds (8-bit quantisation error): a rotation is unit when |1 - |q|| is at
// most this, a set of weights sums to one when |1 - sum| is at most kWeightSumThreshold.
constexpr double kUnitQuatThreshold = 0.00769;
constexpr double kWeightSumThreshold = 0.0039216;
constexpr std::size_t kKeptWarnings = 64;

/// The loading context: file name for messages, limits, the parsed model, warnings.
struct Ctx {
  std::string name;
  GltfLimits limits;
  tinygltf::Model model;
  Scene scene;

  [[noreturn]] void fail(const std::string& what) const { throw GltfError(name + ": " + what); }
  void warn(const std::string& what) {
    ++scene.warning_count;
    if (scene.warnings.size() < kKeptWarnings) scene.warnings.push_back(name + ": " + what);
  }
};

// ---------------------------------------------------------------------------------------------
// Before tinygltf: size and nesting limits, GLB container, images removed.

/// Depth of JSON nesting, scanned without parsing (tinygltf's extras parser and nlohmann's dump
/// recurse once per level, so a deep document would exhaust the stack).
std::size_t json_depth(const char* s, std::size_t n) {
  std::size_t depth = 0, max_depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < n; ++i) {
    const char c = s[i];
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      max_depth = std::max(max_depth, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return max_depth;
}

/// The JSON text with "images" removed: images are never decoded (so a missing or broken one is
/// not an error), and tinygltf's image path indexes a buffer without checking the view.
std::string prepare_json(Ctx& ctx, const char* text, std::size_t size) {
  if (json_depth(text, size) > ctx.limits.max_json_depth)
    ctx.fail("JSON nesting deeper than " + std::to_string(ctx.limits.max_json_depth) + " levels");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text, text + size);
  } catch (const nlohmann::json::exception& e) {
    ctx.fail(std::string("invalid JSON: ") + e.what());
  }
  if (!doc.is_object()) ctx.fail("the JSON document is not an object");
  if (doc.contains("images")) {
    if (doc["images"].is_array() && !doc["images"].empty())
      ctx.warn(std::to_string(doc["images"].size()) + " image(s) not loaded (not needed)");
    doc.erase("images");
  }
  // Invalid UTF-8 cannot reach here (the parser rejects it); replace keeps dump() from throwing.
  return doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::uint32_t read_u32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

/// GLB: header and chunks checked here (tinygltf 2.7's own check lets the BIN chunk end 8 bytes
/// past the data), then rebuilt with the prepared JSON.
std::vector<std::uint8_t> prepare_glb(Ctx& ctx, const std::uint8_t* data, std::size_t size) {
  if (size < 20) ctx.fail("GLB shorter than its 20-byte header");
  const std::uint32_t version = read_u32(data + 4), length = read_u32(data + 8);
  if (version != 2) ctx.fail("GLB version " + std::to_string(version) + " (2 expected)");
  if (length > size || length < 20) ctx.fail("GLB length " + std::to_string(length) + " does not match the " + std::to_string(size) + " bytes given");
  const std::uint64_t json_len = read_u32(data + 12);
  if (read_u32(data + 16) != 0x4E4F534Au) ctx.fail("GLB first chunk is not JSON");
  if (20 + json_len > length) ctx.fail("GLB JSON chunk (" + std::to_string(json_len) + " bytes) runs past the end");
  const std::uint8_t* bin = nullptr;
  std::uint64_t bin_len = 0;
  const std::uint64_t bin_at = 20 + json_len;
  if (bin_at < length) {
    if (json_len % 4 != 0) ctx.fail("GLB JSON chunk length is not a multiple of 4");
    if (bin_at + 8 > length) ctx.fail("GLB second chunk header runs past the end");
    bin_len = read_u32(data + bin_at);
    if (read_u32(data + bin_at + 4) != 0x004E4942u) ctx.fail("GLB second chunk is not BIN");
    if (bin_at + 8 + bin_len > length) ctx.fail("GLB BIN chunk (" + std::to_string(bin_len) + " bytes) runs past the end");
    if (bin_len < 4 || bin_len % 4 != 0) ctx.fail("GLB BIN chunk length " + std::to_string(bin_len) + " is not a positive multiple of 4");
    bin = data + bin_at + 8;
  }
  std::string json = prepare_json(ctx, reinterpret_cast<const char*>(data + 20), static_cast<std::size_t>(json_len));
  while (json.size() % 4 != 0) json.push_back(' ');
  std::vector<std::uint8_t> out;
  const std::uint64_t total = 12 + 8 + json.size() + (bin ? 8 + bin_len : 0);
  if (total > std::numeric_limits<std::uint32_t>::max()) ctx.fail("GLB larger than 4 GiB");
  out.reserve(static_cast<std::size_t>(total));
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(total));
  put_u32(out, static_cast<std::uint32_t>(json.size()));
  put_u32(out, 0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  if (bin) {
    put_u32(out, static_cast<std::uint32_t>(bin_len));
    put_u32(out, 0x004E4942u);
    out.insert(out.end(), bin, bin + bin_len);
  }
  return out;
}

// tinygltf file-system callbacks: external buffers only from the glTF file's own directory, as
// regular files within the size limit; none at all when loading from memory.
struct FsPolicy {
  bool allow = false;
  std::filesystem::path base;
  std::size_t max_bytes = 0;
};

bool inside_base(const FsPolicy& p, const std::string& path) {
  if (!p.allow) return false;
  std::error_code ec;
  const auto canon = std::filesystem::weakly_canonical(path, ec);
  if (ec) return false;
  const auto rel = canon.lexically_relative(p.base);
  return !rel.empty() && *rel.begin() != "..";
}

bool fs_exists(const std::string& path, void* user) {
  const auto& p = *static_cast<FsPolicy*>(user);
  std::error_code ec;
  return inside_base(p, path) && std::filesystem::is_regular_file(path, ec);
}

std::string fs_expand(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool fs_read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto& p = *static_cast<FsPolicy*>(user);
  if (!p.allow) {
    *err = "external files are not read when loading from memory";
    return false;
  }
  std::error_code ec;
  if (!inside_base(p, path) || !std::filesystem::is_regular_file(path, ec)) {
    *err = "not a regular file in the glTF file's directory";
    return false;
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > p.max_bytes) {
    *err = "larger than the limit of " + std::to_string(p.max_bytes) + " bytes";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    *err = "read error";
    return false;
  }
  return true;
}

bool fs_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "writing is not supported";
  return false;
}

bool no_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;  // images are not used (and are removed before parsing)
}

void parse(Ctx& ctx, const std::uint8_t* data, std::size_t size, FsPolicy policy) {
  if (size > ctx.limits.max_file_bytes)
    ctx.fail("file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(ctx.limits.max_file_bytes));
  if (size > std::numeric_limits<unsigned int>::max()) ctx.fail("file larger than 4 GiB");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(no_image, nullptr);
  loader.SetFsCallbacks(tinygltf::FsCallbacks{fs_exists, fs_expand, fs_read, fs_write, &policy});
  std::string err, warn;
  bool ok = false;
  const std::string base = policy.allow ? policy.base.string() : std::string();
  if (size >= 4 && std::memcmp(data, "glTF", 4) == 0) {
    const auto glb = prepare_glb(ctx, data, size);
    ok = loader.LoadBinaryFromMemory(&ctx.model, &err, &warn, glb.data(), static_cast<unsigned int>(glb.size()), base);
  } else {
    const std::string json = prepare_json(ctx, reinterpret_cast<const char*>(data), size);
    ok = loader.LoadASCIIFromString(&ctx.model, &err, &warn, json.data(), static_cast<unsigned int>(json.size()), base);
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    for (char& c : err)
      if (c == '\n') c = ';';
    ctx.fail("glTF parse error: " + (err.empty() ? std::string("unknown") : err));
  }
}

// ---------------------------------------------------------------------------------------------
// Accessors.

std::size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // DOUBLE (5130) and anything else: not a glTF 2.0 component type
  }
}

const char* component_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    default: return "an invalid component type";
  }
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an invalid type";
  }
}

std::size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

/// A checked window on an accessor's bytes: element e, component c lies at
/// base + e * stride + c * csize, and every such byte is inside the buffer (or `zeros`).
struct View {
  std::string label;  // "accessor 3 (animation 0 sampler 2 output)"
  const std::uint8_t* base = nullptr;
  std::size_t stride = 0, count = 0, ncomp = 0, csize = 0;
  int ctype = 0;
  bool normalized = false;
  bool zeros = false;  // no bufferView: every element is zero (glTF 2.0, 3.6.2.3)

  /// Component c of element e as a number, normalised integers mapped as glTF 3.11 defines.
  double get(std::size_t e, std::size_t c) const {
    if (zeros) return 0.0;
    const std::uint8_t* p = base + e * stride + c * csize;
    switch (ctype) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<std::int8_t>(p[0]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
      }
      default: {  // UNSIGNED_INT
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
    }
  }
  /// Integer component (indices, joints): exact for every integer component type.
  std::uint64_t get_uint(std::size_t e, std::size_t c) const { return static_cast<std::uint64_t>(get(e, c)); }
};

/// What a use of an accessor requires (glTF 2.0, 3.7.2.1 and 3.11).
struct Want {
  std::vector<int> types;                // accepted accessor types (SCALAR, VEC3, ...)
  std::vector<int> float_or_normalized;  // integer types accepted only with normalized: true
  std::vector<int> plain;                // types accepted only with normalized: false (FLOAT here)
};

View view_accessor(Ctx& ctx, int index, const std::string& use, const Want& want) {
  const auto& m = ctx.model;
  std::string label = "accessor " + std::to_string(index) + " (" + use + ")";
  if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size())
    ctx.fail(use + ": accessor index " + std::to_string(index) + " out of range (" + std::to_string(m.accessors.size()) + " accessors)");
  const auto& a = m.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) ctx.fail(label + ": sparse accessors are not supported");
  View v;
  v.label = label;
  v.ctype = a.componentType;
  v.normalized = a.normalized;
  v.count = a.count;
  v.ncomp = component_count(a.type);
  v.csize = component_size(a.componentType);
  if (v.ncomp == 0) ctx.fail(label + ": invalid type");
  if (v.csize == 0) ctx.fail(label + ": component type " + std::to_string(a.componentType) + " is not a glTF 2.0 component type");
  if (std::find(want.types.begin(), want.types.end(), a.type) == want.types.end())
    ctx.fail(label + ": type " + type_name(a.type) + " is not allowed here");
  const bool is_plain = std::find(want.plain.begin(), want.plain.end(), a.componentType) != want.plain.end();
  const bool is_norm = std::find(want.float_or_normalized.begin(), want.float_or_normalized.end(), a.componentType) !=
                       want.float_or_normalized.end();
  if (is_norm && !a.normalized)
    ctx.fail(label + ": component type " + component_name(a.componentType) + " must be normalized here");
  if (!is_plain && !is_norm)
    ctx.fail(label + ": component type " + component_name(a.componentType) + " is not allowed here");
  if (is_plain && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
    ctx.fail(label + ": a FLOAT accessor cannot be normalized");
  if (a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3) {
    if (v.csize < 4) ctx.fail(label + ": padded matrix columns are not supported");
  }
  const std::size_t elem = v.ncomp * v.csize;
  if (a.bufferView < 0) {
    v.zeros = true;
    return v;
  }
  if (static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size())
    ctx.fail(label + ": buffer view " + std::to_string(a.bufferView) + " out of range (" + std::to_string(m.bufferViews.size()) + " buffer views)");
  const auto& bv = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string bvl = "buffer view " + std::to_string(a.bufferView);
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= m.buffers.size())
    ctx.fail(label + ": " + bvl + " names buffer " + std::to_string(bv.buffer) + ", out of range (" + std::to_string(m.buffers.size()) + " buffers)");
  const auto& buf = m.buffers[static_cast<std::size_t>(bv.buffer)];
  if (bv.byteOffset > buf.data.size() || bv.byteLength > buf.data.size() - bv.byteOffset)
    ctx.fail(bvl + ": bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) + " exceed buffer " +
             std::to_string(bv.buffer) + " (" + std::to_string(buf.data.size()) + " bytes)");
  v.stride = bv.byteStride != 0 ? bv.byteStride : elem;
  if (v.stride < elem)
    ctx.fail(label + ": " + bvl + " byteStride " + std::to_string(bv.byteStride) + " is smaller than the element (" + std::to_string(elem) + " bytes)");
  if (v.count > 0) {
    // offset + stride * (count - 1) + elem <= byteLength, without overflow.
    const std::size_t len = bv.byteLength;
    bool fits = a.byteOffset <= len && elem <= len - a.byteOffset;
    if (fits) {
      const std::size_t room = len - a.byteOffset - elem;
      fits = (v.count - 1) <= room / v.stride;
    }
    if (!fits)
      ctx.fail(label + ": count " + std::to_string(v.count) + " at offset " + std::to_string(a.byteOffset) + " exceeds " + bvl + " (" +
               std::to_string(len) + " bytes)");
  }
  v.base = buf.data.data() + bv.byteOffset + a.byteOffset;
  return v;
}

const std::vector<int> kFloat{TINYGLTF_COMPONENT_TYPE_FLOAT};

std::string num(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

const char* nonfinite_name(double x) { return std::isnan(x) ? "NaN" : "infinite"; }

/// Unit-length rule of GLTF-3 for a rotation q: zero, NaN or infinite -> error; |1 - |q|| above
/// the threshold -> normalised with a warning; otherwise kept exactly as stored.
void check_rotation(Ctx& ctx, double* q, const std::string& what) {
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(q[i])) ctx.fail(what + " rotation is " + nonfinite_name(q[i]));
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n == 0.0) ctx.fail(what + " rotation is zero");
  if (std::abs(1.0 - n) > kUnitQuatThreshold) {
    for (int i = 0; i < 4; ++i) q[i] /= n;
    ctx.warn(what + " rotation has length " + num(n) + ", normalised");
  }
}

// ---------------------------------------------------------------------------------------------
// Skeleton.

void build_skeleton(Ctx& ctx, std::vector<std::size_t>& joint_of_node) {
  const auto& nodes = ctx.model.nodes;
  const std::size_t n = nodes.size();
  if (n > ctx.limits.max_joints)
    ctx.fail(std::to_string(n) + " nodes exceed the limit of " + std::to_string(ctx.limits.max_joints) + " joints");
  std::vector<long> parent(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    for (int c : nodes[i].children) {
      if (c < 0 || static_cast<std::size_t>(c) >= n)
        ctx.fail("node " + std::to_string(i) + ": child " + std::to_string(c) + " out of range (" + std::to_string(n) + " nodes)");
      const auto cu = static_cast<std::size_t>(c);
      if (cu == i) ctx.fail("node " + std::to_string(i) + " is its own child (cyclic hierarchy)");
      if (parent[cu] >= 0)
        ctx.fail("node " + std::to_string(c) + " has two parents (nodes " + std::to_string(parent[cu]) + " and " + std::to_string(i) + ")");
      parent[cu] = static_cast<long>(i);
    }
  // Preorder from the roots: parents come before children; a node never reached is on a cycle.
  std::vector<std::size_t> order;
  order.reserve(n);
  std::vector<std::size_t> stack;
  for (std::size_t r = 0; r < n; ++r) {
    if (parent[r] >= 0) continue;
    stack.push_back(r);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      order.push_back(i);
      const auto& ch = nodes[i].children;
      for (auto it = ch.rbegin(); it != ch.rend(); ++it) stack.push_back(static_cast<std::size_t>(*it));
    }
  }
  if (order.size() != n) {
    std::vector<bool> seen(n, false);
    for (auto i : order) seen[i] = true;
    const auto it = std::find(seen.begin(), seen.end(), false);
    ctx.fail("node hierarchy has a cycle through node " + std::to_string(it - seen.begin()));
  }
  joint_of_node.assign(n, 0);
  for (std::size_t j = 0; j < n; ++j) joint_of_node[order[j]] = j;
  auto& joints = ctx.scene.skeleton.joints;
  joints.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = order[j];
    const auto& nd = nodes[i];
    Joint& jt = joints[j];
    const std::string label = "node " + std::to_string(i);
    jt.name = nd.name.empty() ? label : nd.name;
    jt.node = i;
    jt.parent = parent[i] < 0 ? -1 : static_cast<int>(joint_of_node[static_cast<std::size_t>(parent[i])]);
    jt.inverse_bind = identity_matrix();
    const bool has_trs = !nd.translation.empty() || !nd.rotation.empty() || !nd.scale.empty();
    if (!nd.matrix.empty()) {
      if (nd.matrix.size() != 16) ctx.fail(label + ": matrix has " + std::to_string(nd.matrix.size()) + " numbers (16 expected)");
      if (has_trs) ctx.fail(label + ": both matrix and translation/rotation/scale are given");
      Mat4 m{};
      for (std::size_t k = 0; k < 16; ++k) {
        if (!std::isfinite(nd.matrix[k])) ctx.fail(label + ": matrix element " + std::to_string(k) + " is " + nonfinite_name(nd.matrix[k]));
        m[k] = nd.matrix[k];
      }
      jt.matrix = m;
      continue;
    }
    auto vec3 = [&](const std::vector<double>& v, Vec3& out, const char* what) {
      if (v.empty()) return;
      if (v.size() != 3) ctx.fail(label + ": " + what + " has " + std::to_string(v.size()) + " numbers (3 expected)");
      for (std::size_t k = 0; k < 3; ++k) {
        if (!std::isfinite(v[k])) ctx.fail(label + ": " + what + " is " + nonfinite_name(v[k]));
        out[k] = v[k];
      }
    };
    vec3(nd.translation, jt.rest.translation, "translation");
    vec3(nd.scale, jt.rest.scale, "scale");
    if (!nd.rotation.empty()) {
      if (nd.rotation.size() != 4) ctx.fail(label + ": rotation has " + std::to_string(nd.rotation.size()) + " numbers (4 expected)");
      for (std::size_t k = 0; k < 4; ++k) jt.rest.rotation[k] = nd.rotation[k];
      check_rotation(ctx, jt.rest.rotation.data(), label);
    }
  }
}

/// Inverse bind matrices and the skin joint list of every skin; returns, per skin, the skeleton
/// index of each of its joints (what JOINTS_0 values index).
std::vector<std::vector<std::size_t>> read_skins(Ctx& ctx, const std::vector<std::size_t>& joint_of_node) {
  auto& sk = ctx.scene.skeleton;
  const std::size_t n = ctx.model.nodes.size();
  std::vector<std::vector<std::size_t>> skins;
  std::vector<bool> ibm_set(sk.joints.size(), false);
  for (std::size_t s = 0; s < ctx.model.skins.size(); ++s) {
    const auto& skin = ctx.model.skins[s];
    const std::string label = "skin " + std::to_string(s);
    if (skin.joints.empty()) ctx.fail(label + ": no joints");
    if (skin.skeleton >= 0 && static_cast<std::size_t>(skin.skeleton) >= n)
      ctx.fail(label + ": skeleton node " + std::to_string(skin.skeleton) + " out of range (" + std::to_string(n) + " nodes)");
    std::vector<std::size_t> js;
    std::vector<bool> in_skin(sk.joints.size(), false);
    for (std::size_t k = 0; k < skin.joints.size(); ++k) {
      const int node = skin.joints[k];
      if (node < 0 || static_cast<std::size_t>(node) >= n)
        ctx.fail(label + ": joint " + std::to_string(k) + " is node " + std::to_string(node) + ", out of range (" + std::to_string(n) + " nodes)");
      const std::size_t j = joint_of_node[static_cast<std::size_t>(node)];
      if (in_skin[j]) ctx.fail(label + ": node " + std::to_string(node) + " is listed twice");
      in_skin[j] = true;
      js.push_back(j);
    }
    std::vector<Mat4> ibm(js.size(), identity_matrix());
    if (skin.inverseBindMatrices >= 0) {
      const View v = view_accessor(ctx, skin.inverseBindMatrices, label + " inverse bind matrices", {{TINYGLTF_TYPE_MAT4}, {}, kFloat});
      if (v.count < js.size())
        ctx.fail(label + ": " + std::to_string(v.count) + " inverse bind matrices for " + std::to_string(js.size()) + " joints");
      for (std::size_t k = 0; k < js.size(); ++k)
        for (std::size_t e = 0; e < 16; ++e) {
          const double x = v.get(k, e);
          if (!std::isfinite(x)) ctx.fail(label + ": inverse bind matrix " + std::to_string(k) + " element " + std::to_string(e) + " is " + nonfinite_name(x));
          ibm[k][e] = x;
        }
    }
    for (std::size_t k = 0; k < js.size(); ++k) {
      Joint& jt = sk.joints[js[k]];
      if (!inverse(ibm[k])) ctx.fail(label + ": inverse bind matrix " + std::to_string(k) + " is singular");
      if (ibm_set[js[k]]) {
        if (jt.inverse_bind != ibm[k])
          ctx.fail(label + ": node " + std::to_string(jt.node) + " has another inverse bind matrix in an earlier skin");
      } else {
        ibm_set[js[k]] = true;
        jt.inverse_bind = ibm[k];
        jt.skinned = true;
        sk.skin_joints.push_back(js[k]);
      }
    }
    skins.push_back(std::move(js));
  }
  return skins;
}

// ---------------------------------------------------------------------------------------------
// Meshes.

void compute_normals(SkinnedMesh& m) {
  m.normals.assign(m.positions.size(), Vec3{0.0, 0.0, 0.0});
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const auto &a = m.positions[m.indices[t]], &b = m.positions[m.indices[t + 1]], &c = m.positions[m.indices[t + 2]];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 f{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};  // area-weighted
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) m.normals[m.indices[t + static_cast<std::size_t>(k)]][static_cast<std::size_t>(d)] += f[static_cast<std::size_t>(d)];
  }
  for (auto& nrm : m.normals) {
    const double l = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (l > 0.0 && std::isfinite(l)) {
      for (auto& x : nrm) x /= l;
    } else {
      nrm = {0.0, 0.0, 1.0};  // an isolated or degenerate vertex: any unit normal
    }
  }
}

int attribute(const tinygltf::Primitive& p, const char* name) {
  const auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

void read_primitive(Ctx& ctx, std::size_t node, std::size_t mesh_index, std::size_t prim_index,
                    const std::vector<std::size_t>* skin, std::size_t node_joint, std::size_t& vertex_total,
                    std::size_t& triangle_total) {
  const auto& prim = ctx.model.meshes[mesh_index].primitives[prim_index];
  const std::string label = "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(prim_index);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == 3) {
    ctx.warn(label + ": points/lines primitive skipped");
    return;
  }
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
    ctx.fail(label + ": invalid mode " + std::to_string(mode));
  const int pos_index = attribute(prim, "POSITION");
  if (pos_index < 0) ctx.fail(label + ": no POSITION attribute");
  const View pos = view_accessor(ctx, pos_index, label + " POSITION", {{TINYGLTF_TYPE_VEC3}, {}, kFloat});
  const std::size_t nv = pos.count;
  if (nv > ctx.limits.max_vertices || vertex_total + nv > ctx.limits.max_vertices)
    ctx.fail(label + ": " + std::to_string(vertex_total + nv) + " vertices exceed the limit of " + std::to_string(ctx.limits.max_vertices));
  vertex_total += nv;

  SkinnedMesh m;
  m.name = ctx.model.meshes[mesh_index].name.empty() ? "mesh " + std::to_string(mesh_index) : ctx.model.meshes[mesh_index].name;
  if (ctx.model.meshes[mesh_index].primitives.size() > 1) m.name += " primitive " + std::to_string(prim_index);
  m.node = node;
  m.positions.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
    for (std::size_t c = 0; c < 3; ++c) {
      const double x = pos.get(v, c);
      if (!std::isfinite(x)) ctx.fail(label + ": POSITION " + std::to_string(v) + " is " + nonfinite_name(x));
      m.positions[v][c] = x;
    }

  // Triangles.
  std::vector<std::uint32_t> raw;
  if (prim.indices >= 0) {
    const View ix = view_accessor(ctx, prim.indices, label + " indices", {{TINYGLTF_TYPE_SCALAR}, {},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}});
    if (ix.count / 3 > ctx.limits.max_triangles) ctx.fail(label + ": " + std::to_string(ix.count) + " indices exceed the triangle limit");
    raw.resize(ix.count);
    for (std::size_t k = 0; k < ix.count; ++k) {
      const std::uint64_t i = ix.get_uint(k, 0);
      if (i >= nv) ctx.fail(label + ": index " + std::to_string(k) + " is " + std::to_string(i) + ", not below the vertex count " + std::to_string(nv));
      raw[k] = static_cast<std::uint32_t>(i);
    }
  } else {
    if (nv > std::numeric_limits<std::uint32_t>::max()) ctx.fail(label + ": too many vertices");
    raw.resize(nv);
    for (std::size_t k = 0; k < nv; ++k) raw[k] = static_cast<std::uint32_t>(k);
  }
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (raw.size() % 3 != 0) ctx.fail(label + ": " + std::to_string(raw.size()) + " indices is not a multiple of 3");
    m.indices = std::move(raw);
  } else {
    for (std::size_t k = 2; k < raw.size(); ++k) {
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN) m.indices.insert(m.indices.end(), {raw[0], raw[k - 1], raw[k]});
      else if (k % 2 == 0) m.indices.insert(m.indices.end(), {raw[k - 2], raw[k - 1], raw[k]});
      else m.indices.insert(m.indices.end(), {raw[k - 1], raw[k - 2], raw[k]});  // keep the winding
    }
  }
  triangle_total += m.triangle_count();
  if (triangle_total > ctx.limits.max_triangles)
    ctx.fail(label + ": " + std::to_string(triangle_total) + " triangles exceed the limit of " + std::to_string(ctx.limits.max_triangles));

  // Normals.
  const int nrm_index = attribute(prim, "NORMAL");
  if (nrm_index >= 0) {
    const View nrm = view_accessor(ctx, nrm_index, label + " NORMAL", {{TINYGLTF_TYPE_VEC3}, {}, kFloat});
    if (nrm.count != nv) ctx.fail(label + ": NORMAL count " + std::to_string(nrm.count) + " differs from POSITION count " + std::to_string(nv));
    m.normals.resize(nv);
    for (std::size_t v = 0; v < nv; ++v)
      for (std::size_t c = 0; c < 3; ++c) {
        const double x = nrm.get(v, c);
        if (!std::isfinite(x)) ctx.fail(label + ": NORMAL " + std::to_string(v) + " is " + nonfinite_name(x));
        m.normals[v][c] = x;
      }
  } else {
    compute_normals(m);
  }

  // Joints and weights.
  m.joints.assign(nv, {0, 0, 0, 0});
  m.weights.assign(nv, {0.0, 0.0, 0.0, 0.0});
  if (skin != nullptr) {
    if (attribute(prim, "JOINTS_1") >= 0 || attribute(prim, "WEIGHTS_1") >= 0)
      ctx.fail(label + ": more than 4 joint influences per vertex (JOINTS_1/WEIGHTS_1) are not supported");
    const int j_index = attribute(prim, "JOINTS_0"), w_index = attribute(prim, "WEIGHTS_0");
    if (j_index < 0 || w_index < 0) ctx.fail(label + ": skinned mesh without JOINTS_0 and WEIGHTS_0");
    const View jv = view_accessor(ctx, j_index, label + " JOINTS_0", {{TINYGLTF_TYPE_VEC4}, {},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}});
    const View wv = view_accessor(ctx, w_index, label + " WEIGHTS_0", {{TINYGLTF_TYPE_VEC4},
        {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, kFloat});
    if (jv.count != nv || wv.count != nv)
      ctx.fail(label + ": JOINTS_0/WEIGHTS_0 counts " + std::to_string(jv.count) + "/" + std::to_string(wv.count) + " differ from POSITION count " + std::to_string(nv));
    for (std::size_t v = 0; v < nv; ++v) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 4; ++k) {
        const std::uint64_t j = jv.get_uint(v, k);
        if (j >= skin->size())
          ctx.fail(label + ": vertex " + std::to_string(v) + " joint index " + std::to_string(j) + " out of range (" + std::to_string(skin->size()) + " joints in the skin)");
        m.joints[v][k] = static_cast<std::uint32_t>((*skin)[j]);
        const double w = wv.get(v, k);
        if (!std::isfinite(w)) ctx.fail(label + ": vertex " + std::to_string(v) + " weight " + std::to_string(k) + " is " + nonfinite_name(w));
        if (w < 0.0) ctx.fail(label + ": vertex " + std::to_string(v) + " weight " + std::to_string(k) + " is negative (" + num(w) + ")");
        m.weights[v][k] = w;
        sum += w;
      }
      if (sum == 0.0) ctx.fail(label + ": vertex " + std::to_string(v) + " weights sum to 0");
      if (std::abs(sum - 1.0) > kWeightSumThreshold) {
        for (auto& w : m.weights[v]) w /= sum;
        ctx.warn(label + ": vertex " + std::to_string(v) + " weights sum to " + num(sum) + ", renormalised");
      }
    }
  } else {
    // Rigidly bound to its node: skinning matrix = global * inverse bind, so bind space is the
    // node's space mapped by the inverse of the inverse bind (the identity for non-skin nodes).
    const Joint& jt = ctx.scene.skeleton.joints[node_joint];
    if (jt.skinned) {
      const Mat4 bind = *inverse(jt.inverse_bind);  // checked invertible in read_skins
      Mat4 nt{};  // normals: inverse transpose of bind = transpose of inverse_bind
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) nt[static_cast<std::size_t>(4 * c + r)] = jt.inverse_bind[static_cast<std::size_t>(4 * r + c)];
      for (auto& p : m.positions) p = transform_point(bind, p);
      for (auto& q : m.normals) {
        q = transform_vector(nt, q);
        const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        if (l > 0.0) for (auto& x : q) x /= l;
      }
    }
    for (std::size_t v = 0; v < nv; ++v) {
      m.joints[v] = {static_cast<std::uint32_t>(node_joint), 0, 0, 0};
      m.weights[v] = {1.0, 0.0, 0.0, 0.0};
    }
  }
  ctx.scene.meshes.push_back(std::move(m));
}

void read_meshes(Ctx& ctx, const std::vector<std::size_t>& joint_of_node, const std::vector<std::vector<std::size_t>>& skins) {
  std::size_t vertices = 0, triangles = 0;
  const auto& model = ctx.model;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const auto& nd = model.nodes[i];
    if (nd.mesh < 0) {
      if (nd.skin >= 0) ctx.fail("node " + std::to_string(i) + ": skin without mesh");
      continue;
    }
    if (static_cast<std::size_t>(nd.mesh) >= model.meshes.size())
      ctx.fail("node " + std::to_string(i) + ": mesh " + std::to_string(nd.mesh) + " out of range (" + std::to_string(model.meshes.size()) + " meshes)");
    const std::vector<std::size_t>* skin = nullptr;
    if (nd.skin >= 0) {
      if (static_cast<std::size_t>(nd.skin) >= skins.size())
        ctx.fail("node " + std::to_string(i) + ": skin " + std::to_string(nd.skin) + " out of range (" + std::to_string(skins.size()) + " skins)");
      skin = &skins[static_cast<std::size_t>(nd.skin)];
    }
    const auto mesh = static_cast<std::size_t>(nd.mesh);
    for (std::size_t p = 0; p < model.meshes[mesh].primitives.size(); ++p)
      read_primitive(ctx, i, mesh, p, skin, joint_of_node[i], vertices, triangles);
  }
}

// ---------------------------------------------------------------------------------------------
// Animations.

void read_animations(Ctx& ctx, const std::vector<std::size_t>& joint_of_node) {
  const auto& model = ctx.model;
  std::size_t keyframes = 0;
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const auto& anim = model.animations[a];
    const std::string alabel = "animation " + std::to_string(a);
    Clip clip;
    clip.name = anim.name.empty() ? alabel : anim.name;
    bool any = false;
    std::map<std::pair<std::size_t, int>, std::size_t> targeted;  // (joint, path) -> channel
    for (std::size_t c = 0; c < anim.channels.size(); ++c) {
      const auto& ch = anim.channels[c];
      const std::string clabel = alabel + " channel " + std::to_string(c);
      if (ch.sampler < 0 || static_cast<std::size_t>(ch.sampler) >= anim.samplers.size())
        ctx.fail(clabel + ": sampler " + std::to_string(ch.sampler) + " out of range (" + std::to_string(anim.samplers.size()) + " samplers)");
      if (ch.target_node < 0) {
        ctx.warn(clabel + ": no target node, ignored");
        continue;
      }
      if (static_cast<std::size_t>(ch.target_node) >= model.nodes.size())
        ctx.fail(clabel + ": target node " + std::to_string(ch.target_node) + " out of range (" + std::to_string(model.nodes.size()) + " nodes)");
      Channel out;
      if (ch.target_path == "translation") out.path = ChannelPath::translation;
      else if (ch.target_path == "rotation") out.path = ChannelPath::rotation;
      else if (ch.target_path == "scale") out.path = ChannelPath::scale;
      else if (ch.target_path == "weights") {
        ctx.warn(clabel + ": morph target weights are not supported, ignored");
        continue;
      } else {
        ctx.fail(clabel + ": invalid target path \"" + ch.target_path + "\"");
      }
      out.joint = joint_of_node[static_cast<std::size_t>(ch.target_node)];
      if (ctx.scene.skeleton.joints[out.joint].matrix)
        ctx.fail(clabel + ": targets node " + std::to_string(ch.target_node) + ", which has a matrix (animated nodes must use TRS)");
      const auto key = std::make_pair(out.joint, static_cast<int>(out.path));
      if (const auto it = targeted.find(key); it != targeted.end())
        ctx.fail(clabel + ": channel " + std::to_string(it->second) + " already targets node " + std::to_string(ch.target_node) + " " + ch.target_path);
      targeted[key] = c;

      const auto& smp = anim.samplers[static_cast<std::size_t>(ch.sampler)];
      const std::string slabel = alabel + " sampler " + std::to_string(ch.sampler);
      if (smp.interpolation == "STEP") out.interpolation = Interpolation::step;
      else if (smp.interpolation == "LINEAR" || smp.interpolation.empty()) out.interpolation = Interpolation::linear;
      else if (smp.interpolation == "CUBICSPLINE") out.interpolation = Interpolation::cubicspline;
      else ctx.fail(slabel + ": invalid interpolation \"" + smp.interpolation + "\"");

      const View in = view_accessor(ctx, smp.input, slabel + " input", {{TINYGLTF_TYPE_SCALAR}, {}, kFloat});
      if (in.count == 0) ctx.fail(slabel + ": no keyframes");
      if (in.count > ctx.limits.max_keyframes || keyframes + in.count > ctx.limits.max_keyframes)
        ctx.fail(slabel + ": " + std::to_string(keyframes + in.count) + " keyframes exceed the limit of " + std::to_string(ctx.limits.max_keyframes));
      keyframes += in.count;
      const bool rot = out.path == ChannelPath::rotation;
      const Want want = rot ? Want{{TINYGLTF_TYPE_VEC4},
                                   {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                    TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                   kFloat}
                            : Want{{TINYGLTF_TYPE_VEC3}, {}, kFloat};
      const View ov = view_accessor(ctx, smp.output, slabel + " output", want);
      const std::size_t per = out.interpolation == Interpolation::cubicspline ? 3 : 1;
      if (ov.count / per != in.count || ov.count % per != 0)
        ctx.fail(slabel + ": output count " + std::to_string(ov.count) + " does not match " + std::to_string(in.count) + " keyframes" +
                 (per == 3 ? " (CUBICSPLINE needs 3 per keyframe)" : ""));

      out.times.resize(in.count);
      for (std::size_t k = 0; k < in.count; ++k) {
        const double t = in.get(k, 0);
        if (!std::isfinite(t)) ctx.fail(slabel + ": keyframe " + std::to_string(k) + " time is " + nonfinite_name(t));
        if (k > 0 && t < out.times[k - 1])
          ctx.fail(slabel + ": keyframe times decrease at keyframe " + std::to_string(k) + " (" + num(t) + " after " + num(out.times[k - 1]) + ")");
        out.times[k] = t;
      }
      const std::size_t w = out.width();
      out.values.resize(ov.count * w);
      for (std::size_t e = 0; e < ov.count; ++e) {
        const std::size_t k = e / per;
        const bool is_value = per == 1 || e % 3 == 1;
        const std::string what = "keyframe " + std::to_string(k) + (is_value ? "" : e % 3 == 0 ? " in-tangent" : " out-tangent");
        for (std::size_t i = 0; i < w; ++i) {
          const double x = ov.get(e, i);
          if (!std::isfinite(x)) ctx.fail(slabel + ": " + what + " " + ch.target_path + " is " + nonfinite_name(x));
          out.values[e * w + i] = x;
        }
        if (rot && is_value) check_rotation(ctx, &out.values[e * w], slabel + ": " + what);
      }
      if (!any || out.times.front() < clip.start) clip.start = out.times.front();
      if (!any || out.times.back() > clip.end) clip.end = out.times.back();
      any = true;
      clip.channels.push_back(std::move(out));
    }
    ctx.scene.clips.push_back(std::move(clip));
  }
}

Scene load(Ctx& ctx, const std::uint8_t* data, std::size_t size, FsPolicy policy) {
  if (data == nullptr || size == 0) ctx.fail("empty input");
  parse(ctx, data, size, std::move(policy));
  std::vector<std::size_t> joint_of_node;
  build_skeleton(ctx, joint_of_node);
  const auto skins = read_skins(ctx, joint_of_node);
  read_meshes(ctx, joint_of_node, skins);
  read_animations(ctx, joint_of_node);
  if (ctx.scene.meshes.empty() && ctx.model.meshes.empty() && !ctx.scene.skeleton.joints.empty()) {
    // Skeleton only (GLTF-4): without a skin, bind pose = rest pose and every joint is skinned.
    auto& sk = ctx.scene.skeleton;
    if (sk.skin_joints.empty()) {
      std::vector<Mat4> global(sk.joints.size());
      for (std::size_t j = 0; j < sk.joints.size(); ++j) {
        Joint& jt = sk.joints[j];
        const Mat4 local = jt.matrix ? *jt.matrix : trs_matrix(jt.rest);
        global[j] = jt.parent < 0 ? local : multiply(global[static_cast<std::size_t>(jt.parent)], local);
        const auto inv = inverse(global[j]);
        if (!inv) ctx.fail("node " + std::to_string(jt.node) + ": rest transform is singular, no bind pose");
        jt.inverse_bind = *inv;
        jt.skinned = true;
        sk.skin_joints.push_back(j);
      }
    }
    ctx.scene.meshes.push_back(make_capsule_skin(sk));
    ctx.scene.meshes.back().name = "capsules";
    ctx.scene.generated_skin = true;
  }
  ctx.scene.name = ctx.name;
  return std::move(ctx.scene);
}

}  // namespace

Scene load_gltf_memory(const std::uint8_t* data, std::size_t size, const GltfLimits& limits, const std::string& name) {
  Ctx ctx;
  ctx.name = name;
  ctx.limits = limits;
  return load(ctx, data, size, FsPolicy{});
}

Scene load_gltf_file(const std::filesystem::path& file, const GltfLimits& limits) {
  Ctx ctx;
  ctx.name = file.filename().string();
  ctx.limits = limits;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) ctx.fail("not a readable file (" + file.string() + ")");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) ctx.fail("cannot read the size of " + file.string());
  if (size > limits.max_file_bytes)
    ctx.fail("file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(limits.max_file_bytes));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(file, std::ios::binary);
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    ctx.fail("read error on " + file.string());
  FsPolicy policy;
  policy.allow = true;
  policy.base = std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec).parent_path(), ec);
  policy.max_bytes = limits.max_file_bytes;
  return load(ctx, bytes.data(), bytes.size(), std::move(policy));
}

}  // namespace rotorcert::render

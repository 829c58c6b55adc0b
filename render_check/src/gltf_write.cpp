// glTF 2.0 writer (gltf_write.hpp): JSON through nlohmann::json (std::map objects, so keys are
// sorted and the output is deterministic), one buffer as a base64 data: URI.
#include <rotorcert/render/gltf_write.hpp>

#include <rotorcert/render/base64.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include <nlohmann/json.hpp>

namespace rotorcert::render {

namespace {

using nlohmann::json;

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;


/// The document under construction: JSON plus the one binary buffer every accessor views.
struct Writer {
  json doc = json::object();
  std::vector<std::uint8_t> bin;

  [[noreturn]] static void fail(const std::string& what) { throw GltfWriteError("write_gltf: " + what); }

  /// A new 4-byte aligned buffer view holding `bytes`, and an accessor over all of it.
  int add_accessor(const void* data, std::size_t bytes, std::size_t count, int ctype, const char* type, int target) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t offset = bin.size();
    bin.resize(offset + bytes);
    std::memcpy(bin.data() + offset, data, bytes);
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
    if (target != 0) view["target"] = target;
    doc["bufferViews"].push_back(view);
    doc["accessors"].push_back(
        {{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", ctype}, {"count", count}, {"type", type}});
    return static_cast<int>(doc["accessors"].size() - 1);
  }

  /// FLOAT accessor of `values.size() / width` elements; min/max per component when asked
  /// (glTF requires them on POSITION and on animation inputs).
  int add_floats(const std::vector<double>& values, std::size_t width, const char* type, bool min_max, int target,
                 const std::string& what) {
    if (values.empty()) fail(what + ": no data");
    std::vector<float> f(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      f[i] = static_cast<float>(values[i]);
      if (!std::isfinite(f[i])) fail(what + ": value " + std::to_string(i) + " is not a finite binary32 number");
    }
    const int a = add_accessor(f.data(), f.size() * sizeof(float), f.size() / width, kFloat, type, target);
    if (min_max) {
      std::vector<double> lo(width, std::numeric_limits<double>::infinity()), hi(width, -std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < f.size(); ++i) {
        lo[i % width] = std::min(lo[i % width], static_cast<double>(f[i]));
        hi[i % width] = std::max(hi[i % width], static_cast<double>(f[i]));
      }
      doc["accessors"].back()["min"] = lo;
      doc["accessors"].back()["max"] = hi;
    }
    return a;
  }

  template <class T>
  int add_ints(const std::vector<T>& values, std::size_t width, int ctype, const char* type, int target) {
    return add_accessor(values.data(), values.size() * sizeof(T), values.size() / width, ctype, type, target);
  }
};

bool is_default(const Vec3& v, double d) { return v[0] == d && v[1] == d && v[2] == d; }

json node_json(const Joint& jt) {
  json n = json::object();
  n["name"] = jt.name;
  if (jt.matrix) {
    n["matrix"] = *jt.matrix;
    return n;
  }
  if (!is_default(jt.rest.translation, 0.0)) n["translation"] = jt.rest.translation;
  const Quat& q = jt.rest.rotation;
  if (!(q[0] == 0.0 && q[1] == 0.0 && q[2] == 0.0 && q[3] == 1.0)) n["rotation"] = q;
  if (!is_default(jt.rest.scale, 1.0)) n["scale"] = jt.rest.scale;
  return n;
}

void check_finite(const double* x, std::size_t n, const std::string& what) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) Writer::fail(what + " is not finite");
}

void write_mesh(Writer& w, const Scene& scene, const SkinnedMesh& m, std::size_t mesh_index,
                const std::vector<long>& skin_index) {
  const std::string label = "mesh " + std::to_string(mesh_index) + " (" + m.name + ")";
  const std::size_t nv = m.positions.size();
  if (nv == 0 || m.indices.empty()) w.fail(label + ": no vertices or no triangles");
  if (m.joints.size() != nv || m.weights.size() != nv || (!m.normals.empty() && m.normals.size() != nv))
    w.fail(label + ": per-vertex arrays of different lengths");
  if (m.indices.size() % 3 != 0) w.fail(label + ": index count is not a multiple of 3");
  if (m.node >= scene.skeleton.joints.size()) w.fail(label + ": node " + std::to_string(m.node) + " is not a joint");

  std::vector<double> flat;
  flat.reserve(nv * 3);
  for (const auto& p : m.positions) flat.insert(flat.end(), p.begin(), p.end());
  json attributes = json::object();
  attributes["POSITION"] = w.add_floats(flat, 3, "VEC3", true, kArrayBuffer, label + " POSITION");
  if (!m.normals.empty()) {
    flat.clear();
    for (const auto& p : m.normals) flat.insert(flat.end(), p.begin(), p.end());
    attributes["NORMAL"] = w.add_floats(flat, 3, "VEC3", false, kArrayBuffer, label + " NORMAL");
  }
  // JOINTS_0 holds skin indices; an influence of weight 0 may name any joint (written as 0).
  std::vector<std::uint32_t> joints;
  joints.reserve(nv * 4);
  flat.clear();
  for (std::size_t v = 0; v < nv; ++v)
    for (std::size_t k = 0; k < 4; ++k) {
      const std::uint32_t j = m.joints[v][k];
      const double wt = m.weights[v][k];
      long s = j < skin_index.size() ? skin_index[j] : -1;
      if (s < 0) {
        if (wt != 0.0) w.fail(label + ": vertex " + std::to_string(v) + " is weighted to joint " + std::to_string(j) + ", which is not in the skin");
        s = 0;
      }
      joints.push_back(static_cast<std::uint32_t>(s));
      flat.push_back(wt);
    }
  if (scene.skeleton.skin_joints.size() <= 256) {
    const std::vector<std::uint8_t> j8(joints.begin(), joints.end());
    attributes["JOINTS_0"] = w.add_ints(j8, 4, kUnsignedByte, "VEC4", kArrayBuffer);
  } else {
    const std::vector<std::uint16_t> j16(joints.begin(), joints.end());
    attributes["JOINTS_0"] = w.add_ints(j16, 4, kUnsignedShort, "VEC4", kArrayBuffer);
  }
  attributes["WEIGHTS_0"] = w.add_floats(flat, 4, "VEC4", false, kArrayBuffer, label + " WEIGHTS_0");

  for (auto i : m.indices)
    if (i >= nv) w.fail(label + ": index " + std::to_string(i) + " is not below the vertex count");
  int indices;
  if (nv <= 65536) {
    const std::vector<std::uint16_t> i16(m.indices.begin(), m.indices.end());
    indices = w.add_ints(i16, 1, kUnsignedShort, "SCALAR", kElementArrayBuffer);
  } else {
    indices = w.add_ints(m.indices, 1, kUnsignedInt, "SCALAR", kElementArrayBuffer);
  }
  json prim = {{"attributes", attributes}, {"indices", indices}, {"mode", 4}};
  w.doc["meshes"].push_back({{"name", m.name}, {"primitives", json::array({prim})}});
}

void write_clip(Writer& w, const Scene& scene, const Clip& clip, std::size_t clip_index) {
  json anim = {{"name", clip.name}, {"channels", json::array()}, {"samplers", json::array()}};
  for (std::size_t c = 0; c < clip.channels.size(); ++c) {
    const Channel& ch = clip.channels[c];
    const std::string label = "clip " + std::to_string(clip_index) + " (" + clip.name + ") channel " + std::to_string(c);
    if (ch.joint >= scene.skeleton.joints.size()) w.fail(label + ": joint " + std::to_string(ch.joint) + " out of range");
    if (scene.skeleton.joints[ch.joint].matrix) w.fail(label + ": animates a joint given by a matrix");
    const std::size_t per = ch.interpolation == Interpolation::cubicspline ? 3 : 1;
    if (ch.times.empty() || ch.values.size() != ch.times.size() * per * ch.width())
      w.fail(label + ": " + std::to_string(ch.values.size()) + " values for " + std::to_string(ch.times.size()) + " keyframes");
    const int input = w.add_floats(ch.times, 1, "SCALAR", true, 0, label + " times");
    const bool rot = ch.path == ChannelPath::rotation;
    const int output = w.add_floats(ch.values, ch.width(), rot ? "VEC4" : "VEC3", false, 0, label + " values");
    const char* interp = ch.interpolation == Interpolation::step ? "STEP"
                         : ch.interpolation == Interpolation::linear ? "LINEAR" : "CUBICSPLINE";
    const char* path = rot ? "rotation" : ch.path == ChannelPath::translation ? "translation" : "scale";
    anim["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interp}});
    anim["channels"].push_back({{"sampler", c}, {"target", {{"node", ch.joint}, {"path", path}}}});
  }
  w.doc["animations"].push_back(anim);
}

}  // namespace

std::string write_gltf(const Scene& scene) {
  Writer w;
  w.doc["asset"] = {{"version", "2.0"}, {"generator", "rotorcert write_gltf"}};
  w.doc["bufferViews"] = json::array();
  w.doc["accessors"] = json::array();

  // Nodes: joint j is node j; children in ascending index.
  const auto& joints = scene.skeleton.joints;
  json nodes = json::array();
  json roots = json::array();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& jt = joints[j];
    check_finite(jt.rest.translation.data(), 3, "joint " + std::to_string(j) + " translation");
    check_finite(jt.rest.rotation.data(), 4, "joint " + std::to_string(j) + " rotation");
    check_finite(jt.rest.scale.data(), 3, "joint " + std::to_string(j) + " scale");
    if (jt.matrix) check_finite(jt.matrix->data(), 16, "joint " + std::to_string(j) + " matrix");
    nodes.push_back(node_json(jt));
    if (jt.parent < 0) {
      roots.push_back(j);
    } else {
      if (static_cast<std::size_t>(jt.parent) >= j)
        Writer::fail("joint " + std::to_string(j) + ": parent " + std::to_string(jt.parent) + " does not precede it");
      nodes[static_cast<std::size_t>(jt.parent)]["children"].push_back(j);
    }
  }

  // The skin.
  std::vector<long> skin_index(joints.size(), -1);
  const auto& sj = scene.skeleton.skin_joints;
  if (!sj.empty()) {
    std::vector<double> ibm;
    ibm.reserve(sj.size() * 16);
    for (std::size_t k = 0; k < sj.size(); ++k) {
      if (sj[k] >= joints.size() || skin_index[sj[k]] >= 0)
        Writer::fail("skin joint " + std::to_string(k) + " is out of range or listed twice");
      skin_index[sj[k]] = static_cast<long>(k);
      ibm.insert(ibm.end(), joints[sj[k]].inverse_bind.begin(), joints[sj[k]].inverse_bind.end());
    }
    const int acc = w.add_floats(ibm, 16, "MAT4", false, 0, "inverse bind matrices");
    w.doc["skins"] = json::array({{{"joints", sj}, {"inverseBindMatrices", acc}}});
  } else if (!scene.meshes.empty()) {
    Writer::fail("meshes without skin joints");
  }

  if (!scene.meshes.empty()) w.doc["meshes"] = json::array();
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const SkinnedMesh& m = scene.meshes[i];
    write_mesh(w, scene, m, i, skin_index);
    json& node = nodes[m.node];
    if (node.contains("mesh")) Writer::fail("two meshes on node " + std::to_string(m.node));
    node["mesh"] = i;
    node["skin"] = 0;
  }

  if (!scene.clips.empty()) w.doc["animations"] = json::array();
  for (std::size_t i = 0; i < scene.clips.size(); ++i) write_clip(w, scene, scene.clips[i], i);

  w.doc["nodes"] = nodes;
  w.doc["scenes"] = json::array({{{"name", scene.name}, {"nodes", roots}}});
  w.doc["scene"] = 0;
  if (!w.bin.empty()) {
    while (w.bin.size() % 4 != 0) w.bin.push_back(0);
    w.doc["buffers"] = json::array({{{"byteLength", w.bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(w.bin)}}});
  } else {
    w.doc.erase("bufferViews");
    w.doc.erase("accessors");
  }
  return w.doc.dump();
}

void write_gltf_file(const Scene& scene, const std::filesystem::path& file) {
  const std::string text = write_gltf(scene);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw GltfWriteError("write_gltf_file: cannot open " + file.string());
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw GltfWriteError("write_gltf_file: cannot write " + file.string());
}

}  // namespace rotorcert::render

// The built-in characters (character.hpp, CHAR-1 of spec/SPEC.md): skeletons from joint positions,
// skins from closed tubes along the bones, clips from rotations about world-space axes.
#include <rotorcert/render/character.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Clips: 2 s at 30 frames per second.
constexpr int kFramesPerSecond = 30;
constexpr int kFrames = 2 * kFramesPerSecond;  // keyframes 0..kFrames
constexpr double kClipSeconds = 2.0;

/// Accessor data are binary32 in glTF: rounding here makes the in-memory scene equal to what the
/// loader reads back. Through a volatile float because gcc 12.2's SLP vectorizer (-O2) drops the
/// double -> float -> double round trip when it is applied to neighbouring array elements.
double f32(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

// ---------------------------------------------------------------------------------------------
// Vector and quaternion arithmetic in binary64 (quaternions [x, y, z, w] as in types.hpp).

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 mul(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalize(const Vec3& a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

Quat qmul(const Quat& a, const Quat& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
          a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
          a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
Quat qconj(const Quat& q) { return {-q[0], -q[1], -q[2], q[3]}; }
Quat qnormalize(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}
Vec3 qrotate(const Quat& q, const Vec3& v) {
  const Quat r = qmul(qmul(q, Quat{v[0], v[1], v[2], 0.0}), qconj(q));
  return {r[0], r[1], r[2]};
}
/// Rotation by `angle` radians about the unit vector `axis` (right-handed).
Quat axis_angle(const Vec3& axis, double angle) {
  const double s = std::sin(angle / 2);
  return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(angle / 2)};
}
/// The shortest rotation taking unit vector a onto unit vector b (opposite vectors: half a turn
/// about an axis perpendicular to a, chosen deterministically).
Quat from_to(const Vec3& a, const Vec3& b) {
  const double d = dot(a, b);
  if (d < -1.0 + 1e-12) {
    Vec3 axis = cross(a, Vec3{0.0, 0.0, 1.0});
    if (dot(axis, axis) < 1e-12) axis = cross(a, Vec3{1.0, 0.0, 0.0});
    return axis_angle(normalize(axis), kPi);
  }
  const Vec3 c = cross(a, b);
  return qnormalize({c[0], c[1], c[2], 1.0 + d});
}

double smoothstep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

// ---------------------------------------------------------------------------------------------
// Skeleton.

/// A joint in world rest coordinates: origin `head`, bone towards `tail`.
struct JointDef {
  std::string name;
  std::string parent;  // empty: root
  Vec3 head;
  Vec3 tail;
};

/// A character under construction: the scene plus each joint's world rest position and rotation
/// (rotation taking local +Y onto the bone), which the tubes and the clips are built from.
struct Rig {
  Scene scene;
  std::vector<Vec3> head;
  std::vector<Vec3> tail;
  std::vector<Quat> global_rotation;
  std::map<std::string, std::size_t> index;

  std::size_t joint(const std::string& name) const {
    const auto it = index.find(name);
    if (it == index.end()) throw std::logic_error("make_character: no joint " + name);
    return it->second;
  }
  /// The local rotation of joint j when the rotation R (about world axes, as if the parent were
  /// at rest) is applied to it relative to its parent: conj(G_parent) * R * G_j. With R the
  /// identity this is the rest rotation.
  Quat posed(std::size_t j, const Quat& r) const {
    const int p = scene.skeleton.joints[j].parent;
    const Quat g = qmul(r, global_rotation[j]);
    return qnormalize(p < 0 ? g : qmul(qconj(global_rotation[static_cast<std::size_t>(p)]), g));
  }
};

/// Skeleton from joint definitions, renumbered in depth-first preorder (children in definition
/// order), followed by the mesh node "body"; inverse bind matrices from the rest pose.
Rig build_rig(const std::string& name, const std::vector<JointDef>& defs) {
  Rig rig;
  rig.scene.name = name;
  const std::size_t n = defs.size();
  std::map<std::string, std::size_t> def_index;
  for (std::size_t i = 0; i < n; ++i) def_index[defs[i].name] = i;
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < n; ++i) {
    if (defs[i].parent.empty()) roots.push_back(i);
    else children[def_index.at(defs[i].parent)].push_back(i);
  }
  std::vector<std::size_t> order, stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    order.push_back(i);
    for (auto it = children[i].rbegin(); it != children[i].rend(); ++it) stack.push_back(*it);
  }
  auto& sk = rig.scene.skeleton;
  for (std::size_t j = 0; j < n; ++j) {
    const JointDef& d = defs[order[j]];
    rig.index[d.name] = j;
    const Quat g = from_to(Vec3{0.0, 1.0, 0.0}, normalize(sub(d.tail, d.head)));
    Joint jt;
    jt.name = d.name;
    jt.node = j;
    jt.skinned = true;
    if (d.parent.empty()) {
      jt.parent = -1;
      jt.rest.translation = d.head;
      jt.rest.rotation = g;
    } else {
      const std::size_t p = rig.index.at(d.parent);
      jt.parent = static_cast<int>(p);
      const Quat gp_inv = qconj(rig.global_rotation[p]);
      jt.rest.translation = qrotate(gp_inv, sub(d.head, rig.head[p]));
      jt.rest.rotation = qnormalize(qmul(gp_inv, g));
    }
    sk.joints.push_back(jt);
    sk.skin_joints.push_back(j);
    rig.head.push_back(d.head);
    rig.tail.push_back(d.tail);
    rig.global_rotation.push_back(g);
  }
  const auto global = global_matrices(sk, rest_pose(sk));
  for (std::size_t j = 0; j < n; ++j) {
    const auto inv = inverse(global[j]);
    if (!inv) throw std::logic_error("make_character: singular rest pose");
    for (std::size_t e = 0; e < 16; ++e) sk.joints[j].inverse_bind[e] = f32((*inv)[e]);
  }
  Joint body;
  body.name = "body";
  body.node = n;
  body.inverse_bind = identity_matrix();
  sk.joints.push_back(body);
  SkinnedMesh mesh;
  mesh.name = "body";
  mesh.node = n;
  rig.scene.meshes.push_back(mesh);
  return rig;
}

// ---------------------------------------------------------------------------------------------
// Skin.

/// Influences of one vertex: at most four distinct joints, weights multiples of 2^-16 summing to
/// exactly 1 (so the sum is exact in binary32 and binary64 alike), largest first.
void set_weights(SkinnedMesh& m, std::vector<std::pair<std::size_t, double>> w) {
  std::map<std::size_t, double> merged;
  for (const auto& [j, x] : w)
    if (x > 0.0) merged[j] += x;
  std::vector<std::pair<std::size_t, double>> v(merged.begin(), merged.end());
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.second != b.second ? a.second > b.second : a.first < b.first; });
  std::vector<std::pair<std::size_t, double>> q;
  double rest = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    const double x = std::round(v[i].second * 65536.0) / 65536.0;
    if (x > 0.0) {
      q.push_back({v[i].first, x});
      rest += x;
    }
  }
  q.insert(q.begin(), {v.at(0).first, 1.0 - rest});
  if (q.size() > 4) throw std::logic_error("make_character: more than 4 influences");
  std::array<std::uint32_t, 4> joints{0, 0, 0, 0};
  std::array<double, 4> weights{0.0, 0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < q.size(); ++k) {
    joints[k] = static_cast<std::uint32_t>(q[k].first);
    weights[k] = q[k].second;
  }
  m.joints.push_back(joints);
  m.weights.push_back(weights);
}

/// Area-weighted vertex normals of the triangles from `first_index` on (one closed part), rounded
/// to binary32.
void set_normals(SkinnedMesh& m, std::size_t first_vertex, std::size_t first_index) {
  std::vector<Vec3> acc(m.positions.size() - first_vertex, Vec3{0.0, 0.0, 0.0});
  for (std::size_t t = first_index; t + 2 < m.indices.size(); t += 3) {
    const Vec3& a = m.positions[m.indices[t]];
    const Vec3 f = cross(sub(m.positions[m.indices[t + 1]], a), sub(m.positions[m.indices[t + 2]], a));
    for (std::size_t k = 0; k < 3; ++k) {
      Vec3& n = acc[m.indices[t + k] - first_vertex];
      n = add(n, f);
    }
  }
  for (const Vec3& n : acc) {
    const Vec3 u = normalize(n);
    m.normals.push_back({f32(u[0]), f32(u[1]), f32(u[2])});
  }
}

/// A closed tube along the straight segment start -> end: elliptical cross-sections (radius ra
/// along the part of `up` perpendicular to the axis, rb along axis x up) following a radius
/// profile, closed by half-ellipsoid caps. Along the axis the tube is cut into segments, each
/// moved by one joint; at each cut the weight passes from one joint to the next over a smoothstep
/// ramp of half-width h around the cut (the weight of segment k is t_k - t_{k+1}, t_k the ramp
/// at cut k, t_0 = 1, t_n = 0: non-negative when the ramps' starts and ends are both in order,
/// and summing to 1).
struct Tube {
  Vec3 start, end, up;
  std::vector<std::array<double, 3>> profile;        // (fraction of the length, ra, rb), fractions 0 .. 1
  std::vector<std::pair<std::size_t, double>> cuts;  // (joint, start distance along the axis); first at 0
  std::vector<double> half_width;                    // per cut k >= 1; empty: blend * shorter neighbour
  double blend = 0.35;
  unsigned around = 16;
  double spacing = 0.02;
  unsigned cap_rings = 3;
};

std::array<double, 2> radius_at(const Tube& t, double f) {
  const auto& p = t.profile;
  if (f <= p.front()[0]) return {p.front()[1], p.front()[2]};
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    if (f <= p[i + 1][0]) {
      const double s = smoothstep((f - p[i][0]) / (p[i + 1][0] - p[i][0]));
      return {p[i][1] + s * (p[i + 1][1] - p[i][1]), p[i][2] + s * (p[i + 1][2] - p[i][2])};
    }
  return {p.back()[1], p.back()[2]};
}

std::vector<std::pair<std::size_t, double>> tube_weights(const Tube& t, double length, double s) {
  const std::size_t n = t.cuts.size();
  auto cut_len = [&](std::size_t k) { return (k + 1 < n ? t.cuts[k + 1].second : length) - t.cuts[k].second; };
  auto half = [&](std::size_t k) { return t.half_width.empty() ? t.blend * std::min(cut_len(k - 1), cut_len(k)) : t.half_width[k - 1]; };
  auto ramp = [&](std::size_t k) {
    if (k == 0) return 1.0;
    if (k == n) return 0.0;
    const double h = half(k);
    return smoothstep((s - t.cuts[k].second + h) / (2.0 * h));
  };
  for (std::size_t k = 1; k + 1 < n; ++k) {  // ramps in order: the weights are then non-negative
    const double a = t.cuts[k].second, b = t.cuts[k + 1].second;
    if (a - half(k) > b - half(k + 1) || a + half(k) > b + half(k + 1))
      throw std::logic_error("make_character: tube ramps out of order");
  }
  std::vector<std::pair<std::size_t, double>> w;
  for (std::size_t k = 0; k < n; ++k) w.push_back({t.cuts[k].first, ramp(k) - ramp(k + 1)});
  return w;
}

void add_tube(SkinnedMesh& m, const Tube& t) {
  const Vec3 axis0 = sub(t.end, t.start);
  const double length = std::sqrt(dot(axis0, axis0));
  const Vec3 a = mul(axis0, 1.0 / length);
  const Vec3 u = normalize(sub(t.up, mul(a, dot(t.up, a))));
  const Vec3 v = cross(a, u);
  // Rings in increasing axial position x: (x, ra, rb); a pole is a ring of radius 0.
  std::vector<std::array<double, 3>> rings;
  const auto r0 = radius_at(t, 0.0), r1 = radius_at(t, 1.0);
  const double c0 = std::min(r0[0], r0[1]), c1 = std::min(r1[0], r1[1]);
  const unsigned C = t.cap_rings;
  rings.push_back({-c0, 0.0, 0.0});
  for (unsigned j = C; j >= 1; --j) {
    const double al = kPi / 2 * j / (C + 1);
    rings.push_back({-c0 * std::sin(al), r0[0] * std::cos(al), r0[1] * std::cos(al)});
  }
  const auto body = static_cast<unsigned>(std::max(2.0, std::ceil(length / t.spacing) + 1.0));
  for (unsigned i = 0; i < body; ++i) {
    const double f = static_cast<double>(i) / (body - 1);
    const auto r = radius_at(t, f);
    rings.push_back({length * f, r[0], r[1]});
  }
  for (unsigned j = 1; j <= C; ++j) {
    const double al = kPi / 2 * j / (C + 1);
    rings.push_back({length + c1 * std::sin(al), r1[0] * std::cos(al), r1[1] * std::cos(al)});
  }
  rings.push_back({length + c1, 0.0, 0.0});

  const std::size_t first_vertex = m.positions.size(), first_index = m.indices.size();
  std::vector<std::size_t> ring_start;
  for (const auto& r : rings) {
    ring_start.push_back(m.positions.size());
    const bool pole = r[1] == 0.0;
    const unsigned count = pole ? 1 : t.around;
    for (unsigned i = 0; i < count; ++i) {
      const double phi = 2.0 * kPi * i / t.around;
      const Vec3 p = add(add(t.start, mul(a, r[0])), add(mul(u, r[1] * std::cos(phi)), mul(v, r[2] * std::sin(phi))));
      m.positions.push_back({f32(p[0]), f32(p[1]), f32(p[2])});
      set_weights(m, tube_weights(t, length, std::clamp(r[0], 0.0, length)));
    }
  }
  // Triangles facing outwards: with the axis a and the ring direction from u to v, (ring k, i),
  // (ring k, i+1), (ring k+1, i) is counter-clockwise seen from outside.
  const auto S = t.around;
  for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
    const bool pole_a = k == 0, pole_b = k + 2 == rings.size();
    for (unsigned i = 0; i < S; ++i) {
      const unsigned i1 = (i + 1) % S;
      const auto A = [&](unsigned q) { return static_cast<std::uint32_t>(ring_start[k] + (pole_a ? 0 : q)); };
      const auto B = [&](unsigned q) { return static_cast<std::uint32_t>(ring_start[k + 1] + (pole_b ? 0 : q)); };
      if (!pole_a) m.indices.insert(m.indices.end(), {A(i), A(i1), B(i)});
      if (!pole_b) m.indices.insert(m.indices.end(), {A(i1), B(i1), B(i)});
    }
  }
  set_normals(m, first_vertex, first_index);
}

/// A tube along start -> end whose cuts lie where the named joints' origins project onto the
/// axis; the first joint moves the tube from its start.
Tube tube(const Rig& rig, const Vec3& start, const Vec3& end, const Vec3& up, const std::vector<std::string>& joints,
          std::vector<std::array<double, 3>> profile, unsigned around, double spacing) {
  Tube t;
  t.start = start;
  t.end = end;
  t.up = up;
  t.profile = std::move(profile);
  t.around = around;
  t.spacing = spacing;
  const Vec3 a = normalize(sub(end, start));
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const std::size_t j = rig.joint(joints[k]);
    t.cuts.push_back({j, k == 0 ? 0.0 : dot(sub(rig.head[j], start), a)});
  }
  return t;
}

// ---------------------------------------------------------------------------------------------
// Clips.

double key_time(int k) { return f32(static_cast<double>(k) / kFramesPerSecond); }

/// A LINEAR rotation channel of joint j sampled from rotation(t) at every frame; each key is put
/// in the hemisphere of its predecessor, then rounded to binary32.
Channel rotation_channel(std::size_t j, const std::function<Quat(double)>& rotation) {
  Channel ch;
  ch.joint = j;
  ch.path = ChannelPath::rotation;
  ch.interpolation = Interpolation::linear;
  Quat prev{0.0, 0.0, 0.0, 0.0};
  for (int k = 0; k <= kFrames; ++k) {
    const double t = key_time(k);
    Quat q = rotation(t);
    if (k > 0 && q[0] * prev[0] + q[1] * prev[1] + q[2] * prev[2] + q[3] * prev[3] < 0.0)
      for (auto& x : q) x = -x;
    prev = q;
    ch.times.push_back(t);
    for (double x : q) ch.values.push_back(f32(x));
  }
  return ch;
}

Channel translation_channel(std::size_t j, const std::function<Vec3(double)>& translation) {
  Channel ch;
  ch.joint = j;
  ch.path = ChannelPath::translation;
  ch.interpolation = Interpolation::linear;
  for (int k = 0; k <= kFrames; ++k) {
    const double t = key_time(k);
    ch.times.push_back(t);
    for (double x : translation(t)) ch.values.push_back(f32(x));
  }
  return ch;
}

Clip make_clip(const std::string& name, std::vector<Channel> channels) {
  Clip c;
  c.name = name;
  c.channels = std::move(channels);
  c.start = key_time(0);
  c.end = key_time(kFrames);
  return c;
}

/// Eased progress 0 -> 1 over the clip.
double ease(double t) { return smoothstep(t / kClipSeconds); }

/// Joint j turned by ease(t) * angle about the world axis (relative to its parent).
Channel eased_rotation(const Rig& rig, std::size_t j, const Vec3& axis, double angle) {
  return rotation_channel(j, [&rig, j, axis, angle](double t) { return rig.posed(j, axis_angle(axis, ease(t) * angle)); });
}

/// "bend": the elbows bend forwards to 135 degrees. The left forearm points along +X, so forwards
/// (+Z) is a turn about -Y; the right one points along -X: about +Y.
Clip bend_clip(const Rig& rig) {
  return make_clip("bend", {eased_rotation(rig, rig.joint("forearm_L"), {0.0, -1.0, 0.0}, 135.0 * kDeg),
                            eased_rotation(rig, rig.joint("forearm_R"), {0.0, 1.0, 0.0}, 135.0 * kDeg)});
}

/// "twist": the wrists turn half a turn about the forearm axis (elbow -> wrist).
Clip twist_clip(const Rig& rig) {
  std::vector<Channel> ch;
  for (const char* side : {"L", "R"}) {
    const std::size_t hand = rig.joint(std::string("hand_") + side);
    const std::size_t forearm = rig.joint(std::string("forearm_") + side);
    ch.push_back(eased_rotation(rig, hand, normalize(sub(rig.head[hand], rig.head[forearm])), 180.0 * kDeg));
  }
  return make_clip("twist", std::move(ch));
}

/// "walk": one gait cycle of 2 s that loops (every channel is periodic in the clip).
Clip walk_clip(const Rig& rig) {
  const double w = 2.0 * kPi / kClipSeconds;
  std::vector<Channel> ch;
  const Vec3 X{1.0, 0.0, 0.0}, Y{0.0, 1.0, 0.0}, Z{0.0, 0.0, 1.0};
  const std::size_t hips = rig.joint("hips");
  const Vec3 hips_rest = rig.head[hips];
  // The hips bob twice per cycle (once per step): the one translation channel.
  ch.push_back(translation_channel(hips, [hips_rest, w](double t) {
    return Vec3{hips_rest[0], hips_rest[1] - 0.02 * (0.5 - 0.5 * std::cos(2.0 * w * t)), hips_rest[2]};
  }));
  ch.push_back(rotation_channel(hips, [&rig, hips, w](double t) { return rig.posed(hips, axis_angle({0.0, 1.0, 0.0}, 5.0 * kDeg * std::sin(w * t))); }));
  const std::size_t spine = rig.joint("spine");
  ch.push_back(rotation_channel(spine, [&rig, spine, w](double t) { return rig.posed(spine, axis_angle({0.0, 1.0, 0.0}, -8.0 * kDeg * std::sin(w * t))); }));
  for (const char* side : {"L", "R"}) {
    const bool left = side[0] == 'L';
    const double phase = left ? 0.0 : kPi;
    const std::string s = std::string("_") + side;
    // Legs: a leg hangs along -Y; a turn about -X swings it forwards (+Z).
    const std::size_t thigh = rig.joint("thigh" + s), shin = rig.joint("shin" + s), foot = rig.joint("foot" + s);
    ch.push_back(rotation_channel(thigh, [&rig, thigh, w, phase, X](double t) {
      return rig.posed(thigh, axis_angle(mul(X, -1.0), 25.0 * kDeg * std::sin(w * t + phase)));
    }));
    // The knee bends backwards (a turn about +X), most while the leg swings forwards.
    ch.push_back(rotation_channel(shin, [&rig, shin, w, phase, X](double t) {
      return rig.posed(shin, axis_angle(X, (5.0 + 45.0 * (0.5 + 0.5 * std::sin(w * t + phase + kPi / 2))) * kDeg));
    }));
    ch.push_back(rotation_channel(foot, [&rig, foot, w, phase, X](double t) {
      return rig.posed(foot, axis_angle(X, 10.0 * kDeg * std::sin(w * t + phase)));
    }));
    // Arms: lowered 70 degrees from the T-pose (about -Z on the left, +Z on the right), then
    // swung against the leg of the same side; elbows slightly bent forwards.
    const std::size_t upper = rig.joint("upper_arm" + s), fore = rig.joint("forearm" + s);
    const double lower = left ? -70.0 * kDeg : 70.0 * kDeg;
    ch.push_back(rotation_channel(upper, [&rig, upper, w, phase, lower, X, Z](double t) {
      const Quat swing = axis_angle(X, 20.0 * kDeg * std::sin(w * t + phase));
      return rig.posed(upper, qmul(swing, axis_angle(Z, lower)));
    }));
    ch.push_back(rotation_channel(fore, [&rig, fore, w, phase, left, Y](double t) {
      const double bend = (15.0 + 10.0 * std::sin(w * t + phase)) * kDeg;
      return rig.posed(fore, axis_angle(mul(Y, left ? -1.0 : 1.0), bend));
    }));
  }
  return make_clip("walk", std::move(ch));
}

// ---------------------------------------------------------------------------------------------
// The three characters.

Scene simple_character() {
  Rig rig = build_rig("rotorcert_simple", {{"root", "", {0, 0, 0}, {1, 0, 0}},
                                           {"mid", "root", {1, 0, 0}, {2, 0, 0}},
                                           {"tip", "mid", {2, 0, 0}, {3, 0, 0}}});
  SkinnedMesh& m = rig.scene.meshes.front();
  // Columns x = 0, 1, 2 of two vertices (z = +0.5, -0.5): root; root/mid half and half; mid/tip
  // half and half.
  const std::size_t root = rig.joint("root"), mid = rig.joint("mid"), tip = rig.joint("tip");
  const std::vector<std::vector<std::pair<std::size_t, double>>> column = {
      {{root, 1.0}}, {{root, 0.5}, {mid, 0.5}}, {{mid, 0.5}, {tip, 0.5}}};
  for (std::size_t c = 0; c < 3; ++c)
    for (double z : {0.5, -0.5}) {
      m.positions.push_back({static_cast<double>(c), 0.0, z});
      m.normals.push_back({0.0, 1.0, 0.0});
      set_weights(m, column[c]);
    }
  // Vertex 2c is (c, 0, +0.5), 2c+1 is (c, 0, -0.5): counter-clockwise seen from +Y.
  for (std::uint32_t c = 0; c < 2; ++c) {
    const std::uint32_t a0 = 2 * c, b0 = 2 * c + 1, a1 = 2 * c + 2, b1 = 2 * c + 3;
    m.indices.insert(m.indices.end(), {a0, a1, b1, a0, b1, b0});
  }
  rig.scene.clips.push_back(make_clip("bend", {eased_rotation(rig, mid, {0.0, 0.0, 1.0}, 90.0 * kDeg)}));
  rig.scene.clips.push_back(make_clip("twist", {eased_rotation(rig, tip, normalize(sub(rig.head[tip], rig.head[mid])), 180.0 * kDeg)}));
  return std::move(rig.scene);
}

/// Torso joints from the hips to the head (medium: without upper_chest).
std::vector<JointDef> torso_defs(bool full) {
  std::vector<JointDef> d = {{"hips", "", {0, 0.95, 0}, {0, 1.05, 0}},
                             {"spine", "hips", {0, 1.05, 0}, {0, 1.20, 0}},
                             {"chest", "spine", {0, 1.20, 0}, {0, full ? 1.35 : 1.50, 0}}};
  if (full) d.push_back({"upper_chest", "chest", {0, 1.35, 0}, {0, 1.50, 0}});
  d.push_back({"neck", full ? "upper_chest" : "chest", {0, 1.50, 0}, {0, 1.60, 0}});
  d.push_back({"head", "neck", {0, 1.60, 0}, {0, 1.78, 0}});
  return d;
}

/// A finger of two joints along `dir` from `knuckle` (lengths of its two bones).
void finger_defs(std::vector<JointDef>& d, const std::string& name, const std::string& side, const Vec3& knuckle,
                 const Vec3& dir, double l1, double l2) {
  const Vec3 mid = add(knuckle, mul(dir, l1)), tip = add(mid, mul(dir, l2));
  d.push_back({name + "_1_" + side, "hand_" + side, knuckle, mid});
  d.push_back({name + "_2_" + side, name + "_1_" + side, mid, tip});
}

/// An arm along +X (left) or -X (right) at shoulder height 1.45, attached to `parent`; fingers
/// of the full character, or a thumb and a mitten for the medium one.
void arm_defs(std::vector<JointDef>& d, const std::string& side, const std::string& parent, bool full) {
  const double sx = side == "L" ? 1.0 : -1.0;
  auto p = [sx](double x, double y, double z) { return Vec3{sx * x, y, z}; };
  d.push_back({"clavicle_" + side, parent, p(0.03, 1.45, 0), p(0.17, 1.45, 0)});
  d.push_back({"upper_arm_" + side, "clavicle_" + side, p(0.17, 1.45, 0), p(0.45, 1.45, 0)});
  d.push_back({"forearm_" + side, "upper_arm_" + side, p(0.45, 1.45, 0), p(0.70, 1.45, 0)});
  d.push_back({"hand_" + side, "forearm_" + side, p(0.70, 1.45, 0), p(0.79, 1.45, 0)});
  const Vec3 along = p(1, 0, 0);
  const Vec3 thumb_dir = normalize(p(1.0, 0.0, 1.2));
  finger_defs(d, "thumb", side, add(p(0.70, 1.44, 0.02), mul(thumb_dir, 0.03)), thumb_dir, 0.035, 0.035);
  if (full) {
    finger_defs(d, "index", side, p(0.79, 1.45, 0.03), along, 0.045, 0.04);
    finger_defs(d, "middle", side, p(0.79, 1.45, 0.01), along, 0.05, 0.045);
    finger_defs(d, "ring", side, p(0.79, 1.45, -0.01), along, 0.045, 0.04);
    finger_defs(d, "pinky", side, p(0.78, 1.45, -0.03), along, 0.035, 0.03);
  } else {
    finger_defs(d, "fingers", side, p(0.79, 1.45, 0.0), along, 0.045, 0.045);
  }
}

void leg_defs(std::vector<JointDef>& d, const std::string& side) {
  const double sx = side == "L" ? 1.0 : -1.0;
  auto p = [sx](double x, double y, double z) { return Vec3{sx * x, y, z}; };
  d.push_back({"thigh_" + side, "hips", p(0.09, 0.92, 0), p(0.09, 0.50, 0)});
  d.push_back({"shin_" + side, "thigh_" + side, p(0.09, 0.50, 0), p(0.09, 0.08, 0)});
  d.push_back({"foot_" + side, "shin_" + side, p(0.09, 0.08, 0), p(0.09, 0.03, 0.13)});
  d.push_back({"toe_" + side, "foot_" + side, p(0.09, 0.03, 0.13), p(0.09, 0.03, 0.20)});
}

/// Mesh resolution: segments around and ring spacing (m) per kind of part.
struct Resolution {
  unsigned torso, limb, foot, finger;
  double spacing;
};

void torso_tube(Rig& rig, bool full, const Resolution& r) {
  std::vector<std::string> joints = {"hips", "spine", "chest"};
  std::vector<double> half = {0.16, 0.16};
  if (full) {
    joints.push_back("upper_chest");
    half.push_back(0.16);
  }
  joints.insert(joints.end(), {"neck", "head"});
  half.insert(half.end(), {0.06, 0.05});
  // Height y -> fraction of the tube from y = 0.85 to 1.80; radii across (X) and deep (Z).
  auto f = [](double y) { return (y - 0.85) / 0.95; };
  Tube t = tube(rig, {0, 0.85, 0}, {0, 1.80, 0}, {1, 0, 0}, joints,
                {{f(0.85), 0.14, 0.10}, {f(0.95), 0.16, 0.11}, {f(1.10), 0.135, 0.10}, {f(1.30), 0.16, 0.11},
                 {f(1.42), 0.15, 0.10}, {f(1.50), 0.055, 0.055}, {f(1.56), 0.05, 0.05}, {f(1.63), 0.085, 0.095},
                 {f(1.70), 0.09, 0.10}, {f(1.80), 0.07, 0.08}},
                r.torso, r.spacing);
  t.half_width = half;
  t.cap_rings = 5;
  add_tube(rig.scene.meshes.front(), t);
}

void arm_tubes(Rig& rig, const std::string& side, bool full, const Resolution& r) {
  const double sx = side == "L" ? 1.0 : -1.0;
  auto p = [sx](double x, double y, double z) { return Vec3{sx * x, y, z}; };
  SkinnedMesh& m = rig.scene.meshes.front();
  // From the clavicle to the knuckles; the palm is flat (wide along Z, thin along Y).
  auto f = [](double x) { return (x - 0.03) / 0.77; };
  Tube arm = tube(rig, p(0.03, 1.45, 0), p(0.80, 1.45, 0), {0, 0, 1},
                  {"clavicle_" + side, "upper_arm_" + side, "forearm_" + side, "hand_" + side},
                  {{f(0.03), 0.06, 0.06}, {f(0.17), 0.055, 0.055}, {f(0.30), 0.048, 0.048}, {f(0.45), 0.04, 0.04},
                   {f(0.55), 0.042, 0.04}, {f(0.70), 0.03, 0.022}, {f(0.74), 0.042, 0.017}, {f(0.80), 0.04, 0.015}},
                  r.limb, r.spacing);
  add_tube(m, arm);
  auto finger = [&](const std::string& name, double ra, double rb) {
    const std::size_t j1 = rig.joint(name + "_1_" + side), j2 = rig.joint(name + "_2_" + side);
    const Vec3 dir = normalize(sub(rig.head[j2], rig.head[j1]));
    const Vec3 tip = sub(rig.tail[j2], mul(dir, 0.8 * std::min(ra, rb)));  // the cap ends at the bone's tail
    const Vec3 start = sub(rig.head[j1], mul(dir, 0.025));  // inside the palm, moved by the hand
    Tube t = tube(rig, start, tip, {0, 0, 1}, {"hand_" + side, name + "_1_" + side, name + "_2_" + side},
                  {{0.0, ra, rb}, {1.0, ra * 0.8, rb * 0.8}}, r.finger, r.spacing);
    t.cap_rings = 2;
    add_tube(m, t);
  };
  finger("thumb", 0.011, 0.011);
  if (full) {
    for (const char* name : {"index", "middle", "ring", "pinky"}) finger(name, 0.009, 0.009);
  } else {
    finger("fingers", 0.038, 0.012);  // the four fingers as one mitten
  }
}

void leg_tubes(Rig& rig, const std::string& side, const Resolution& r) {
  const double sx = side == "L" ? 1.0 : -1.0;
  auto p = [sx](double x, double y, double z) { return Vec3{sx * x, y, z}; };
  SkinnedMesh& m = rig.scene.meshes.front();
  auto f = [](double y) { return (1.0 - y) / 0.94; };
  Tube leg = tube(rig, p(0.09, 1.0, 0), p(0.09, 0.06, 0), {1, 0, 0},
                  {"hips", "thigh_" + side, "shin_" + side, "foot_" + side},
                  {{f(1.0), 0.08, 0.08}, {f(0.85), 0.08, 0.085}, {f(0.55), 0.055, 0.055}, {f(0.50), 0.05, 0.052},
                   {f(0.38), 0.055, 0.06}, {f(0.12), 0.035, 0.038}, {f(0.06), 0.035, 0.035}},
                  r.limb, r.spacing);
  leg.half_width = {0.04, 0.10, 0.035};
  add_tube(m, leg);
  Tube foot = tube(rig, p(0.09, 0.04, -0.05), p(0.09, 0.03, 0.20), {1, 0, 0}, {"foot_" + side, "toe_" + side},
                   {{0.0, 0.035, 0.035}, {0.5, 0.045, 0.035}, {1.0, 0.04, 0.02}}, r.foot, r.spacing);
  add_tube(m, foot);
}

Scene humanoid(bool full) {
  std::vector<JointDef> d = torso_defs(full);
  const std::string shoulder_parent = full ? "upper_chest" : "chest";
  for (const char* side : {"L", "R"}) arm_defs(d, side, shoulder_parent, full);
  if (full)
    for (const char* side : {"L", "R"}) leg_defs(d, side);
  Rig rig = build_rig(full ? "rotorcert_full" : "rotorcert_medium", d);
  const Resolution r = full ? Resolution{48, 32, 24, 10, 0.014} : Resolution{18, 12, 10, 8, 0.035};
  torso_tube(rig, full, r);
  for (const char* side : {"L", "R"}) arm_tubes(rig, side, full, r);
  if (full)
    for (const char* side : {"L", "R"}) leg_tubes(rig, side, r);
  if (full) rig.scene.clips.push_back(walk_clip(rig));
  rig.scene.clips.push_back(bend_clip(rig));
  rig.scene.clips.push_back(twist_clip(rig));
  return std::move(rig.scene);
}

}  // namespace

const char* to_string(Complexity c) {
  switch (c) {
    case Complexity::simple: return "simple";
    case Complexity::medium: return "medium";
    case Complexity::full: return "full";
  }
  return "full";
}

Scene make_character(Complexity c) {
  switch (c) {
    case Complexity::simple: return simple_character();
    case Complexity::medium: return humanoid(false);
    case Complexity::full: return humanoid(true);
  }
  throw std::invalid_argument("make_character: unknown complexity");
}

}  // namespace rotorcert::render

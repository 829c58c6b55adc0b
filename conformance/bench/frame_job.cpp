// One frame of the render check's pipeline on native arrays (frame_job.hpp).
#include "frame_job.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <type_traits>

#include <rotorcert/impl.hpp>
#include <rotorcert/render/vertex_error.hpp>

#include "bench/vertex_kernels.hpp"

namespace rotorcert::bench {

namespace r = rotorcert::render;

// The scalar-typed half of a FrameJob, behind one virtual call per frame.
struct FrameJob::Pipeline {
  virtual ~Pipeline() = default;
  virtual bool run(double time_a, double time_b, bool skin_vertices, std::string& message) = 0;
  virtual r::SkinOutput output(std::size_t mesh) const = 0;
  std::size_t joints = 0, vertices = 0, levels = 0, channels = 0;
};

namespace {

template <class S>
const impl::Ops<S>& ops_of(const rc_impl& t) {
  if constexpr (std::is_same_v<S, float>) return *t.f32;
  else return *t.f64;
}

/// The ops table of the method's scalar type, or nullptr.
bool has_ops(const rc_impl& t) {
  return (t.scalar == RC_SCALAR_FLOAT32 && t.f32 != nullptr) || (t.scalar == RC_SCALAR_FLOAT64 && t.f64 != nullptr);
}

/// Whether a channel's values are all exactly `v` (a scale channel that scales nothing).
bool all_equal(const r::Channel& ch, double v) {
  return std::all_of(ch.values.begin(), ch.values.end(), [v](double x) { return x == v; });
}

/// The last rotation or translation channel of each joint in a clip (PoseJob applies the
/// channels in order, so a later one wins), in the clip's order.
std::vector<const r::Channel*> effective_channels(const r::Clip& clip, r::ChannelPath path, std::size_t joints) {
  std::map<std::size_t, std::size_t> last;
  for (std::size_t c = 0; c < clip.channels.size(); ++c) {
    const r::Channel& ch = clip.channels[c];
    if (ch.path == path && ch.joint < joints) last[ch.joint] = c;
  }
  std::vector<const r::Channel*> out;
  for (std::size_t c = 0; c < clip.channels.size(); ++c) {
    const r::Channel& ch = clip.channels[c];
    if (ch.path == path && ch.joint < joints && last[ch.joint] == c) out.push_back(&ch);
  }
  return out;
}

// Array layouts of Native (all in the method's scalar S, ABI layouts of impl_abi.h):
//   joints are stored in level order: position i of level L lies in [level_[L], level_[L+1]);
//     pos_[j] maps a skeleton joint to its position, order_[i] back, ppos_[i] is the parent's.
//   slots: the local poses of A and B, 2 per joint. pairs (blend ops with k = 2: blend_qlb,
//     dq_blend): A of joint i at 2i, B at 2i + 1, so the pair is one element of the k = 2 op;
//     blocks (nlerp, dq_sclerp): A of joint i at i, B at n + i.
//   q2_ (4 per slot), t2_ (3 per slot): local rotations and translations of A and B, holding
//     the rest pose where a clip has no channel (run() overwrites only animated slots).
//   keys of a clip: rotation keyframes, key_width_ scalars each (4: quaternion; 8: [q, 0]
//     rotation-only dual quaternion for dq_sclerp), channel c's keys from key0; translation
//     keyframes 3 each.
//   vertices of every mesh one after another: 4 influences each, vjoints_ (level positions),
//     weights_ (w_k / W in S, as SkinJob divides); the vertex loops read them, with the
//     bind-space positions and normals, as the SoA streams_ of vertex_kernels.hpp.
template <class S>
class Native final : public FrameJob::Pipeline {
 public:
  explicit Native(const FrameJob& job)
      : m_(job.method), ops_(ops_of<S>(*job.method.table)), rig_(*job.rig), alpha_(job.alpha) {}

  /// Lays everything out; false with `message` when an op fails while preparing.
  bool prepare(const FrameJob& job, std::string& message) {
    const r::Skeleton& sk = *rig_.skeleton;
    const std::size_t n = sk.joints.size();
    lbs_ = m_.technique == r::Technique::lbs;
    pairs_ = m_.pose_blend() == r::PoseBlend::qlb || m_.pose_blend() == r::PoseBlend::dlb;
    sclerp_keys_ = m_.key_interpolation() == r::KeyInterpolation::sclerp;
    key_width_ = sclerp_keys_ ? 8 : 4;
    n_ = n;
    joints = n;
    levels = rig_.levels.size();

    // Level order.
    pos_.assign(n, 0);
    order_.clear();
    level_.assign(1, 0);
    for (const auto& lv : rig_.levels) {
      for (std::size_t j : lv) {
        pos_[j] = order_.size();
        order_.push_back(j);
      }
      level_.push_back(order_.size());
    }
    ppos_.assign(n, 0);
    std::size_t widest = 0;
    for (std::size_t L = 0; L + 1 < level_.size(); ++L) widest = std::max(widest, level_[L + 1] - level_[L]);
    for (std::size_t i = 0; i < n; ++i) {
      const int p = sk.joints[order_[i]].parent;
      if (p >= 0) ppos_[i] = pos_[static_cast<std::size_t>(p)];
    }

    // Rest pose in both slots of every joint.
    q2_.assign(8 * n, S(0));
    t2_.assign(6 * n, S(0));
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = order_[i];
      const r::Quat q = rig_.matrix_local[j] ? rig_.matrix_local[j]->rotation : sk.joints[j].rest.rotation;
      const r::Vec3 t = rig_.matrix_local[j] ? rig_.matrix_local[j]->translation : sk.joints[j].rest.translation;
      for (std::size_t which = 0; which < 2; ++which) {
        for (std::size_t c = 0; c < 4; ++c) q2_[4 * slot(i, which) + c] = static_cast<S>(q[c]);
        for (std::size_t c = 0; c < 3; ++c) t2_[3 * slot(i, which) + c] = static_cast<S>(t[c]);
      }
    }
    if (pairs_) {
      w2_.resize(2 * n);
      for (std::size_t i = 0; i < n; ++i) {
        w2_[2 * i] = static_cast<S>(1.0 - alpha_);
        w2_[2 * i + 1] = static_cast<S>(alpha_);
      }
    } else {
      alpha_n_.assign(n, static_cast<S>(alpha_));
    }
    plan(clips_[0], *job.clip_a, 0);
    plan(clips_[1], *job.clip_b, 1);
    channels = clips_[0].rot.size() + clips_[1].rot.size();

    // Inverse binds: rotation and translation (K_p = I in a rigid rig, so u = t_b), and the
    // stretch K_b that SkinJob applies.
    bq_.resize(4 * n);
    bt_.resize(3 * n);
    kb_.assign(9 * n, S(0));
    kb_stretched_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const r::JointTransform& ib = rig_.inverse_bind[order_[i]];
      for (std::size_t c = 0; c < 4; ++c) bq_[4 * i + c] = static_cast<S>(ib.rotation[c]);
      for (std::size_t c = 0; c < 3; ++c) bt_[3 * i + c] = static_cast<S>(ib.translation[c]);
      kb_stretched_[i] = ib.stretched ? 1 : 0;
      for (std::size_t c = 0; c < 9; ++c) kb_[9 * i + c] = static_cast<S>(ib.stretch[c]);
    }

    // Vertices.
    std::size_t nv = 0;
    mesh_begin_.assign(1, 0);
    for (const r::SkinnedMesh& mesh : job.scene->meshes) mesh_begin_.push_back(nv += mesh.positions.size());
    vertices = nv;
    vjoints_.resize(4 * nv);
    weights_.resize(4 * nv);
    std::vector<S> pin(3 * nv), nin(3 * nv);
    std::size_t v = 0;
    for (const r::SkinnedMesh& mesh : job.scene->meshes)
      for (std::size_t mv = 0; mv < mesh.positions.size(); ++mv, ++v) {
        S total = 0;
        for (std::size_t k = 0; k < 4; ++k) {
          vjoints_[4 * v + k] = static_cast<std::uint32_t>(pos_[mesh.joints[mv][k]]);
          total += weights_[4 * v + k] = static_cast<S>(mesh.weights[mv][k]);
        }
        for (std::size_t k = 0; k < 4; ++k) weights_[4 * v + k] /= total;
        bind_vertex(v, mesh.positions[mv], &pin[3 * v]);
        bind_vertex(v, mesh.normals[mv], &nin[3 * v]);
      }
    lay_out_vertex_streams(pin, nin);
    // Scratch, sized once: run() allocates nothing.
    std::size_t widest_clip = std::max(clips_[0].rot.size(), clips_[1].rot.size());
    st_.assign(std::max({2 * n, nv, widest_clip, std::size_t{1}}), RC_OK);
    lq_.resize(4 * n);
    lt_.resize(3 * n);
    gq_.resize(4 * n);
    gt_.resize(3 * n);
    r3_.resize(3 * n);
    sq_.resize(4 * n);
    mats_.resize(9 * n);
    palette_.resize(12 * n);
    pq_.resize(8 * std::max(widest, std::size_t{1}));
    if (!lbs_) {
      d2_.resize(16 * n);
      ld_.resize(8 * n);
      gd_.resize(8 * n);
      sd_.resize(8 * n);
      bd_.resize(8 * n);
      // The inverse binds as the method's own dual quaternions (constant for a rigid rig).
      if (!check(message, "dq_from_rotation_translation",
                 ops_.dq_from_rotation_translation(n, bq_.data(), bt_.data(), bd_.data(), st_.data()), n))
        return false;
    }
    return true;
  }

  bool run(double time_a, double time_b, bool skin_vertices, std::string& message) override {
    if (!sample(clips_[0], time_a, message) || !sample(clips_[1], time_b, message)) return false;
    return lbs_ ? run_lbs(skin_vertices, message) : run_dqs(skin_vertices, message);
  }

  r::SkinOutput output(std::size_t mesh) const override {
    r::SkinOutput out;
    const auto& p = streams_.position_out;
    const auto& n = streams_.normal_out;
    for (std::size_t v = mesh_begin_[mesh]; v < mesh_begin_[mesh + 1]; ++v) {
      out.positions.push_back({double(p[0][v]), double(p[1][v]), double(p[2][v])});
      out.normals.push_back({double(n[0][v]), double(n[1][v]), double(n[2][v])});
    }
    return out;
  }

 private:
  struct Track {
    const r::Channel* ch = nullptr;
    std::size_t pos = 0;   // joint's level position
    std::size_t key0 = 0;  // first key in the clip's key array (in keys)
    std::size_t keys = 0;
  };
  struct ClipPlan {
    const r::Clip* clip = nullptr;
    std::size_t which = 0;  // 0: A, 1: B
    std::vector<Track> rot, trans;
    std::vector<S> rot_keys, trans_keys;
    std::vector<S> ka, kb, s, out;  // per-frame arguments of slerp / dq_sclerp
  };

  const r::SkinningMethod m_;  // a copy: the job may move
  const impl::Ops<S>& ops_;
  const r::Rig& rig_;
  const double alpha_;
  bool lbs_ = true, pairs_ = true, sclerp_keys_ = false;
  std::size_t key_width_ = 4, n_ = 0;
  std::vector<std::size_t> pos_, order_, level_, ppos_, mesh_begin_;
  ClipPlan clips_[2];
  std::vector<S> q2_, t2_, w2_, alpha_n_;
  std::vector<S> bq_, bt_, kb_;
  std::vector<std::uint8_t> kb_stretched_;
  std::vector<std::uint32_t> vjoints_;
  std::vector<S> weights_;
  // The vertex loops' SoA streams (vertex_kernels.hpp), padded to a multiple of kVertexPad.
  std::vector<vertices::Offset<S>> voffset_;
  std::vector<S> vweight_, vin_, vout_;
  vertices::Streams<S> streams_;
  std::vector<std::uint8_t> st_;
  // LBS
  std::vector<S> lq_, lt_, gq_, gt_, r3_, sq_, mats_, palette_, pq_;
  // DQS
  std::vector<S> d2_, ld_, gd_, sd_, bd_;

  std::size_t slot(std::size_t i, std::size_t which) const { return pairs_ ? 2 * i + which : which * n_ + i; }

  /// The ABI call's outcome: 0 returned and every status byte OK.
  bool check(std::string& message, const char* op, int rc, std::size_t n) const {
    if (rc != 0) {
      message = m_.name() + ": " + op + " could not run";
      return false;
    }
    std::uint8_t any = 0;
    for (std::size_t i = 0; i < n; ++i) any |= st_[i];
    if (any == RC_OK) return true;
    std::size_t i = 0;
    while (st_[i] == RC_OK) ++i;
    message = m_.name() + ": " + op + " answered DOMAIN_ERROR for element " + std::to_string(i);
    return false;
  }

  void plan(ClipPlan& c, const r::Clip& clip, std::size_t which) {
    c.clip = &clip;
    c.which = which;
    const std::size_t n = n_;
    for (const r::Channel* ch : effective_channels(clip, r::ChannelPath::rotation, n)) {
      Track t{ch, pos_[ch->joint], c.rot_keys.size() / key_width_, std::max<std::size_t>(ch->times.size(), 1)};
      for (std::size_t k = 0; k < t.keys; ++k) {
        const r::Quat q = r::pose_math::key_quat(*ch, k);  // identity for an empty channel, as PoseJob
        for (std::size_t i = 0; i < 4; ++i) c.rot_keys.push_back(static_cast<S>(q[i]));
        if (sclerp_keys_) c.rot_keys.insert(c.rot_keys.end(), 4, S(0));
      }
      c.rot.push_back(t);
    }
    for (const r::Channel* ch : effective_channels(clip, r::ChannelPath::translation, n)) {
      if (ch->times.empty()) continue;
      Track t{ch, pos_[ch->joint], c.trans_keys.size() / 3, ch->times.size()};
      for (std::size_t k = 0; k < t.keys; ++k)
        for (std::size_t i = 0; i < 3; ++i) c.trans_keys.push_back(static_cast<S>(ch->values[3 * k + i]));
      c.trans.push_back(t);
    }
    const std::size_t nc = c.rot.size();
    c.ka.resize(key_width_ * nc);
    c.kb.resize(key_width_ * nc);
    c.s.resize(nc);
    c.out.resize(key_width_ * nc);
  }

  /// Bind-space vertex x as SkinJob's DQS sees it: sum (w_k/W) K_b x over the influences when
  /// one of them is stretched, else x (LBS applies K_b in its matrices and uses x).
  void bind_vertex(std::size_t v, const r::Vec3& x, S* out) const {
    const S xs[3] = {static_cast<S>(x[0]), static_cast<S>(x[1]), static_cast<S>(x[2])};
    bool any = false;
    for (std::size_t k = 0; k < 4; ++k) any = any || kb_stretched_[vjoints_[4 * v + k]];
    if (lbs_ || !any) {
      std::copy(xs, xs + 3, out);
      return;
    }
    S acc[3] = {0, 0, 0};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t i = vjoints_[4 * v + k];
      S y[3] = {xs[0], xs[1], xs[2]};
      if (kb_stretched_[i]) {
        const S* a = &kb_[9 * i];
        y[0] = a[0] * xs[0] + a[3] * xs[1] + a[6] * xs[2];
        y[1] = a[1] * xs[0] + a[4] * xs[1] + a[7] * xs[2];
        y[2] = a[2] * xs[0] + a[5] * xs[1] + a[8] * xs[2];
      }
      for (std::size_t c = 0; c < 3; ++c) acc[c] += weights_[4 * v + k] * y[c];
    }
    std::copy(acc, acc + 3, out);
  }

  /// The vertex loops' streams from the AoS influences and the bind-space positions and
  /// normals (3 per vertex): SoA, padded with vertices of weight (1, 0, 0, 0) on entry 0.
  void lay_out_vertex_streams(const std::vector<S>& pin, const std::vector<S>& nin) {
    const std::size_t nv = vertices, pad = vertices::kVertexPad;
    const std::size_t count = (nv + pad - 1) / pad * pad;
    const std::size_t stride = lbs_ ? 12 : 8;  // palette scalars per joint
    voffset_.assign(4 * count, 0);
    vweight_.assign(4 * count, S(0));
    vin_.assign(6 * count, S(0));
    vout_.assign(6 * count, S(0));
    for (std::size_t v = 0; v < count; ++v) {
      for (std::size_t k = 0; k < 4; ++k) {
        const bool real = v < nv;
        voffset_[k * count + v] = static_cast<vertices::Offset<S>>(real ? stride * vjoints_[4 * v + k] : 0);
        vweight_[k * count + v] = real ? weights_[4 * v + k] : S(k == 0 ? 1 : 0);
      }
      for (std::size_t c = 0; c < 3 && v < nv; ++c) {
        vin_[c * count + v] = pin[3 * v + c];
        vin_[(3 + c) * count + v] = nin[3 * v + c];
      }
    }
    streams_.count = count;
    for (std::size_t k = 0; k < 4; ++k) {
      streams_.offset[k] = &voffset_[k * count];
      streams_.weight[k] = &vweight_[k * count];
    }
    for (std::size_t c = 0; c < 3; ++c) {
      streams_.position[c] = &vin_[c * count];
      streams_.normal[c] = &vin_[(3 + c) * count];
      streams_.position_out[c] = &vout_[c * count];
      streams_.normal_out[c] = &vout_[(3 + c) * count];
    }
  }

  // ---- per frame --------------------------------------------------------------------------

  /// Keys of every rotation channel by one slerp (or dq_sclerp) call, scattered into the clip's
  /// slots; translations lerped by the suite.
  bool sample(ClipPlan& c, double time, std::string& message) {
    const r::Clip& clip = *c.clip;
    const double t = std::clamp(time, clip.start, std::max(clip.start, clip.end));
    const std::size_t w = key_width_, nc = c.rot.size();
    for (std::size_t i = 0; i < nc; ++i) {
      const Track& tr = c.rot[i];
      const r::pose_math::KeyLocation loc = r::pose_math::locate(*tr.ch, t);
      const std::size_t k1 = std::min(loc.k + 1, tr.keys - 1);
      std::memcpy(&c.ka[w * i], &c.rot_keys[w * (tr.key0 + loc.k)], w * sizeof(S));
      std::memcpy(&c.kb[w * i], &c.rot_keys[w * (tr.key0 + k1)], w * sizeof(S));
      c.s[i] = loc.kind == r::pose_math::KeyLocation::linear ? static_cast<S>(loc.s) : S(0);
    }
    if (nc != 0) {
      const int rc = sclerp_keys_ ? ops_.dq_sclerp(nc, c.ka.data(), c.kb.data(), c.s.data(), c.out.data(), st_.data())
                                  : ops_.slerp(nc, c.ka.data(), c.kb.data(), c.s.data(), c.out.data(), st_.data());
      if (!check(message, sclerp_keys_ ? "dq_sclerp" : "slerp", rc, nc)) return false;
      for (std::size_t i = 0; i < nc; ++i)
        std::memcpy(&q2_[4 * slot(c.rot[i].pos, c.which)], &c.out[w * i], 4 * sizeof(S));
    }
    for (const Track& tr : c.trans) {
      const r::pose_math::KeyLocation loc = r::pose_math::locate(*tr.ch, t);
      const std::size_t k1 = std::min(loc.k + 1, tr.keys - 1);
      const S s = loc.kind == r::pose_math::KeyLocation::linear ? static_cast<S>(loc.s) : S(0);
      const S* a = &c.trans_keys[3 * (tr.key0 + loc.k)];
      const S* b = &c.trans_keys[3 * (tr.key0 + k1)];
      S* out = &t2_[3 * slot(tr.pos, c.which)];
      for (std::size_t i = 0; i < 3; ++i) out[i] = (S(1) - s) * a[i] + s * b[i];
    }
    return true;
  }

  bool run_lbs(bool skin_vertices, std::string& message) {
    const std::size_t n = n_;
    // Pose blend of the local rotations; translations lerped.
    const int rc = pairs_ ? ops_.blend_qlb(n, 2, q2_.data(), w2_.data(), lq_.data(), st_.data())
                          : ops_.nlerp(n, q2_.data(), q2_.data() + 4 * n, alpha_n_.data(), lq_.data(), st_.data());
    if (!check(message, pairs_ ? "blend_qlb" : "nlerp", rc, n)) return false;
    const S wb = static_cast<S>(alpha_), wa = static_cast<S>(1.0 - alpha_);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < 3; ++c) lt_[3 * i + c] = wa * t2_[3 * slot(i, 0) + c] + wb * t2_[3 * slot(i, 1) + c];

    // Hierarchy, one call per op per level.
    std::copy(lq_.begin(), lq_.begin() + static_cast<std::ptrdiff_t>(4 * level_[1]), gq_.begin());
    std::copy(lt_.begin(), lt_.begin() + static_cast<std::ptrdiff_t>(3 * level_[1]), gt_.begin());
    for (std::size_t L = 1; L + 1 < level_.size(); ++L) {
      const std::size_t lo = level_[L], m = level_[L + 1] - lo;
      for (std::size_t i = 0; i < m; ++i) std::memcpy(&pq_[4 * i], &gq_[4 * ppos_[lo + i]], 4 * sizeof(S));
      if (!check(message, "compose", ops_.compose(m, pq_.data(), &lq_[4 * lo], &gq_[4 * lo], st_.data()), m) ||
          !check(message, "apply_vector", ops_.apply_vector(m, pq_.data(), &lt_[3 * lo], r3_.data(), st_.data()), m))
        return false;
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t c = 0; c < 3; ++c) gt_[3 * (lo + i) + c] = gt_[3 * ppos_[lo + i] + c] + r3_[3 * i + c];
    }

    // Skinning transforms and their matrices [R K_b | t].
    if (!check(message, "compose", ops_.compose(n, gq_.data(), bq_.data(), sq_.data(), st_.data()), n) ||
        !check(message, "apply_vector", ops_.apply_vector(n, gq_.data(), bt_.data(), r3_.data(), st_.data()), n) ||
        !check(message, "to_matrix", ops_.to_matrix(n, sq_.data(), mats_.data(), st_.data()), n))
      return false;
    for (std::size_t i = 0; i < n; ++i) {
      S* p = &palette_[12 * i];
      const S* rm = &mats_[9 * i];
      if (kb_stretched_[i]) {
        const S* k = &kb_[9 * i];
        for (std::size_t c = 0; c < 3; ++c)
          for (std::size_t row = 0; row < 3; ++row)
            p[3 * c + row] = rm[row] * k[3 * c] + rm[3 + row] * k[3 * c + 1] + rm[6 + row] * k[3 * c + 2];
      } else {
        std::memcpy(p, rm, 9 * sizeof(S));
      }
      for (std::size_t c = 0; c < 3; ++c) p[9 + c] = gt_[3 * i + c] + r3_[3 * i + c];
    }
    if (!skin_vertices) return true;

    // Vertices: the suite's blend of the 4 matrices, the same loop for every method.
    vertices::skin_lbs(streams_, palette_.data());
    return true;
  }

  bool run_dqs(bool skin_vertices, std::string& message) {
    const std::size_t n = n_;
    // Local rigid motions of A and B in one call, then the pose blend.
    if (!check(message, "dq_from_rotation_translation",
               ops_.dq_from_rotation_translation(2 * n, q2_.data(), t2_.data(), d2_.data(), st_.data()), 2 * n))
      return false;
    const int rc = pairs_ ? ops_.dq_blend(n, 2, d2_.data(), w2_.data(), ld_.data(), st_.data())
                          : ops_.dq_sclerp(n, d2_.data(), d2_.data() + 8 * n, alpha_n_.data(), ld_.data(), st_.data());
    if (!check(message, pairs_ ? "dq_blend" : "dq_sclerp", rc, n)) return false;

    // Hierarchy.
    std::copy(ld_.begin(), ld_.begin() + static_cast<std::ptrdiff_t>(8 * level_[1]), gd_.begin());
    for (std::size_t L = 1; L + 1 < level_.size(); ++L) {
      const std::size_t lo = level_[L], m = level_[L + 1] - lo;
      for (std::size_t i = 0; i < m; ++i) std::memcpy(&pq_[8 * i], &gd_[8 * ppos_[lo + i]], 8 * sizeof(S));
      if (!check(message, "dq_compose", ops_.dq_compose(m, pq_.data(), &ld_[8 * lo], &gd_[8 * lo], st_.data()), m))
        return false;
    }
    if (!check(message, "dq_compose", ops_.dq_compose(n, gd_.data(), bd_.data(), sd_.data(), st_.data()), n))
      return false;
    if (!skin_vertices) return true;

    // Vertices: Kavan et al.'s DQS shader (2008, Algorithm 1) over the palette of skinning dual
    // quaternions, the same loop for every method, as the LBS matrix blend is (frame_job.hpp).
    vertices::skin_dqs(streams_, sd_.data());
    return true;
  }

};

}  // namespace

FrameJob::FrameJob() = default;
FrameJob::~FrameJob() = default;
FrameJob::FrameJob(FrameJob&&) noexcept = default;
FrameJob& FrameJob::operator=(FrameJob&&) noexcept = default;

std::string FrameJob::validate() const {
  if (method.table == nullptr || !has_ops(*method.table)) return "no implementation table with ops";
  const std::string missing = r::missing_ops(*method.table, method.technique);
  if (!missing.empty()) return method.name() + ": no " + missing;
  if (method.pose_blend() == r::PoseBlend::none) return method.name() + ": no op to blend two poses";
  if (scene == nullptr || rig == nullptr || clip_a == nullptr || clip_b == nullptr)
    return "scene, rig or clips missing";
  if (rig->skeleton != &scene->skeleton || rig->depth.size() != scene->skeleton.joints.size())
    return "rig prepared for another skeleton";
  if (!(alpha >= 0.0 && alpha <= 1.0)) return "blend weight outside [0, 1]";
  const r::Skeleton& sk = scene->skeleton;
  const std::size_t n = sk.joints.size();
  if (n == 0) return "no joints";
  // Rigid: every joint's local stretch is the identity, so every global one is (pose_job.hpp).
  for (std::size_t j = 0; j < n; ++j) {
    if (rig->matrix_local[j] ? rig->matrix_local[j]->stretched : sk.joints[j].rest.scale != r::Vec3{1.0, 1.0, 1.0})
      return "joint " + sk.joints[j].name + " is scaled or sheared: FrameJob poses rigid rigs only";
  }
  for (const r::Clip* clip : {clip_a, clip_b})
    for (const r::Channel& ch : clip->channels) {
      if (ch.joint >= n) continue;
      if (ch.path == r::ChannelPath::scale && !all_equal(ch, 1.0))
        return "clip " + clip->name + " scales joint " + sk.joints[ch.joint].name + ": FrameJob poses rigid rigs only";
      if (ch.path != r::ChannelPath::scale && ch.interpolation == r::Interpolation::cubicspline)
        return "clip " + clip->name + " has CUBICSPLINE channels: FrameJob interpolates LINEAR and STEP only";
    }
  for (const r::SkinnedMesh& mesh : scene->meshes) {
    const std::size_t nv = mesh.positions.size();
    if (mesh.normals.size() != nv || mesh.joints.size() != nv || mesh.weights.size() != nv)
      return "mesh " + mesh.name + ": arrays differ in length";
    for (std::size_t v = 0; v < nv; ++v) {
      double total = 0;
      for (std::size_t k = 0; k < 4; ++k) {
        if (mesh.joints[v][k] >= n) return "mesh " + mesh.name + ": a joint index is out of range";
        if (!(mesh.weights[v][k] >= 0)) return "mesh " + mesh.name + ": a weight is negative or NaN";
        total += mesh.weights[v][k];
      }
      if (!(total > 0)) return "mesh " + mesh.name + ": a vertex has no weight";
    }
  }
  return {};
}

bool FrameJob::prepare() {
  p_.reset();
  message = validate();
  if (!message.empty()) return false;
  if (method.is_float()) {
    auto p = std::make_unique<Native<float>>(*this);
    if (!p->prepare(*this, message)) return false;
    p_ = std::move(p);
  } else {
    auto p = std::make_unique<Native<double>>(*this);
    if (!p->prepare(*this, message)) return false;
    p_ = std::move(p);
  }
  return true;
}

bool FrameJob::run() {
  if (!p_) {
    message = "not prepared";
    return false;
  }
  return p_->run(time_a, time_b, skin_vertices, message);
}

std::size_t FrameJob::joint_count() const { return p_ ? p_->joints : 0; }
std::size_t FrameJob::vertex_count() const { return p_ ? p_->vertices : 0; }
std::size_t FrameJob::level_count() const { return p_ ? p_->levels : 0; }
std::size_t FrameJob::rotation_channels() const { return p_ ? p_->channels : 0; }

r::SkinOutput FrameJob::output(std::size_t m) const { return p_ ? p_->output(m) : r::SkinOutput{}; }

FrameAgreement compare_with_render_check(FrameJob& job, const std::vector<std::pair<double, double>>& times,
                                         double metres_per_unit) {
  FrameAgreement a;
  const bool skin_vertices = job.skin_vertices;
  job.skin_vertices = true;
  struct Restore {
    FrameJob& j;
    bool v;
    ~Restore() { j.skin_vertices = v; }
  } restore{job, skin_vertices};
  for (const auto& [ta, tb] : times) {
    const std::string when = "t_a = " + std::to_string(ta) + ", t_b = " + std::to_string(tb);
    job.time_a = ta;
    job.time_b = tb;
    if (!job.run()) {
      a.failure = "FrameJob at " + when + ": " + job.message;
      return a;
    }
    std::vector<r::JointTransform> globals, skinning;
    r::PoseJob pose;
    pose.method = job.method;
    pose.rig = job.rig;
    pose.request.a = {job.clip_a, ta};
    pose.request.b = r::PoseSample{job.clip_b, tb};
    pose.request.alpha = job.alpha;
    pose.globals = &globals;
    pose.skinning = &skinning;
    if (!pose.run()) {
      a.failure = "PoseJob at " + when + ": " + pose.message;
      return a;
    }
    for (std::size_t m = 0; m < job.scene->meshes.size(); ++m) {
      r::SkinOutput expected;
      r::SkinJob skin;
      skin.method = job.method;
      skin.mesh = &job.scene->meshes[m];
      skin.skinning = &skinning;
      skin.output = &expected;
      if (!skin.run()) {
        a.failure = "SkinJob at " + when + ": " + skin.message;
        return a;
      }
      const r::VertexError e = r::vertex_error(job.output(m), expected, metres_per_unit);
      if (e.max_mm > a.max_mm || a.worst.empty())
        a.worst = "mesh " + std::to_string(m) + " vertex " + std::to_string(e.worst_vertex) + " at " + when;
      a.max_mm = std::max(a.max_mm, e.max_mm);
      a.max_normal_rad = std::max(a.max_normal_rad, e.max_normal_rad);
    }
  }
  return a;
}

}  // namespace rotorcert::bench

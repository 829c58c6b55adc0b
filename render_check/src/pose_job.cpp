// Posing a skeleton with one implementation (pose_job.hpp).
#include <rotorcert/render/pose_job.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

Mat3 identity3() { return {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}; }

namespace pose_math {

KeyLocation locate(const Channel& ch, double t) {
  // The same decisions, in the same order, as sample_channel (sample.cpp).
  KeyLocation r;
  const std::size_t n = ch.times.size();
  if (n == 0) return r;
  if (!(t > ch.times.front())) return r;  // before the first (and NaN)
  if (t >= ch.times.back()) {
    r.k = n - 1;
    return r;
  }
  r.k = static_cast<std::size_t>(std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin()) - 1;
  if (t == ch.times[r.k] || ch.interpolation == Interpolation::step) return r;
  r.td = ch.times[r.k + 1] - ch.times[r.k];
  r.s = (t - ch.times[r.k]) / r.td;
  r.kind = ch.interpolation == Interpolation::cubicspline ? KeyLocation::cubic : KeyLocation::linear;
  return r;
}

Quat key_quat(const Channel& ch, std::size_t k) {
  if (k >= ch.times.size()) return {0.0, 0.0, 0.0, 1.0};
  const std::size_t e = ch.interpolation == Interpolation::cubicspline ? 3 * k + 1 : k;
  const double* p = ch.values.data() + 4 * e;
  return {p[0], p[1], p[2], p[3]};
}

Quat hermite_rotation(const Channel& ch, const KeyLocation& at) {
  const double s = at.s, s2 = s * s, s3 = s2 * s, td = at.td;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = td * (s3 - 2 * s2 + s), h01 = -2 * s3 + 3 * s2, h11 = td * (s3 - s2);
  const double* vk = ch.values.data() + 4 * (3 * at.k + 1);
  const double* bk = ch.values.data() + 4 * (3 * at.k + 2);
  const double* vk1 = ch.values.data() + 4 * (3 * (at.k + 1) + 1);
  const double* ak1 = ch.values.data() + 4 * (3 * (at.k + 1));
  Quat r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = h00 * vk[i] + h10 * bk[i] + h01 * vk1[i] + h11 * ak1[i];
  return r;
}

Mat3 rotation3(const Quat& q) {
  const Mat4 m = rotation_matrix(q);
  return {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
}

bool is_scalar_matrix(const Mat3& a) {
  return a[1] == 0 && a[2] == 0 && a[3] == 0 && a[5] == 0 && a[6] == 0 && a[7] == 0 && a[0] == a[4] && a[0] == a[8];
}

Vec3 dq_translation(const std::array<double, 8>& d) {
  // 2 q_d q_r* with q_r* = (-x, -y, -z, w); Hamilton product in [x, y, z, w] order.
  const double ax = d[4], ay = d[5], az = d[6], aw = d[7];
  const double bx = -d[0], by = -d[1], bz = -d[2], bw = d[3];
  const double n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3];
  return {2.0 * (aw * bx + ax * bw + ay * bz - az * by) / n2, 2.0 * (aw * by - ax * bz + ay * bw + az * bx) / n2,
          2.0 * (aw * bz + ax * by - ay * bx + az * bw) / n2};
}

}  // namespace pose_math

namespace {

using ref::Real;

/// (q, K, t) of an affine matrix: q the nearest rotation of its linear part L by the reference,
/// K = R(q)^T L at the reference precision (pose_job.hpp, prepare_rig).
JointTransform decompose(const Mat4& m, const std::string& what) {
  JointTransform out;
  out.translation = {m[12], m[13], m[14]};
  Mat3 l;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) l[static_cast<std::size_t>(3 * c + r)] = m[static_cast<std::size_t>(4 * c + r)];
  if (l == identity3()) return out;  // the common case, exactly: nothing to decompose
  ref::Mat3<Real> lr;
  for (std::size_t i = 0; i < 9; ++i) lr[i] = Real(l[i]);
  const auto q = ref::clause::MAT_2_from_matrix(lr);
  if (q.status != ref::Status::ok) throw std::invalid_argument(what + ": linear part has no rotation (det <= 0 or not finite)");
  out.rotation = {q.value.x.toDouble(), q.value.y.toDouble(), q.value.z.toDouble(), q.value.w.toDouble()};
  // K from the rounded q, so that R(q) K reproduces L as closely as binary64 K allows.
  const auto rq = ref::clause::MAT_1_to_matrix(ref::Quaternion<Real>::from_xyzw(
      {Real(out.rotation[0]), Real(out.rotation[1]), Real(out.rotation[2]), Real(out.rotation[3])}));
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) {
      Real s(0);
      for (int k = 0; k < 3; ++k) s += rq.value[static_cast<std::size_t>(3 * r + k)] * lr[static_cast<std::size_t>(3 * c + k)];  // (R^T)_{rk} = R_{kr}
      out.stretch[static_cast<std::size_t>(3 * c + r)] = s.toDouble();
    }
  out.stretched = out.stretch != identity3();
  return out;
}

// ---- the method's arithmetic in its scalar type ------------------------------------------

template <class S> using Q = std::array<S, 4>;
template <class S> using V = std::array<S, 3>;
template <class S> using D = std::array<S, 8>;

template <class S> const impl::Ops<S>& ops_of(const rc_impl& t) {
  if constexpr (std::is_same_v<S, float>) return *t.f32;
  else return *t.f64;
}

template <class S, std::size_t N> std::array<S, N> to_s(const std::array<double, N>& a) {
  std::array<S, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = static_cast<S>(a[i]);
  return r;
}
template <class S, std::size_t N> std::array<double, N> to_d(const std::array<S, N>& a) {
  std::array<double, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = static_cast<double>(a[i]);
  return r;
}

/// Flattens element arrays into the ABI's contiguous layout.
template <class S, std::size_t N> std::vector<S> flat(const std::vector<std::array<S, N>>& v) {
  std::vector<S> r;
  r.reserve(v.size() * N);
  for (const auto& a : v) r.insert(r.end(), a.begin(), a.end());
  return r;
}
template <class S, std::size_t N> std::vector<std::array<S, N>> unflat(const std::vector<S>& v) {
  std::vector<std::array<S, N>> r(v.size() / N);
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t k = 0; k < N; ++k) r[i][k] = v[i * N + k];
  return r;
}

/// One sampled local transform: rotation (a value the method produced, or a keyframe/rest value
/// that it will consume), translation and scale (suite, binary64), or a node matrix's
/// decomposition.
struct Local {
  Quat q{0.0, 0.0, 0.0, 1.0};
  Vec3 t{0.0, 0.0, 0.0};
  Vec3 s{1.0, 1.0, 1.0};
  const JointTransform* matrix = nullptr;  // set for joints given by a node matrix
};

template <class S>
class Runner {
 public:
  Runner(const SkinningMethod& m, const Rig& rig) : m_(m), ops_(ops_of<S>(*m.table)), rig_(rig) {}

  void run(const PoseRequest& req, std::vector<JointTransform>& globals, std::vector<JointTransform>* skinning) {
    const std::size_t n = rig_.skeleton->joints.size();
    std::vector<Local> a = sample(req.a), b;
    if (req.b) b = sample(*req.b);
    const bool blend = req.b.has_value();
    if (blend && m_.technique == Technique::lbs) {
      blend_rotations(a, b, req.alpha);
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < 3; ++i) {
          a[j].t[i] = (1.0 - req.alpha) * a[j].t[i] + req.alpha * b[j].t[i];
          a[j].s[i] = (1.0 - req.alpha) * a[j].s[i] + req.alpha * b[j].s[i];
        }
    }
    if (blend && m_.technique == Technique::dqs)
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < 3; ++i) a[j].s[i] = (1.0 - req.alpha) * a[j].s[i] + req.alpha * b[j].s[i];

    gK_.assign(n, Stretch{});
    if (m_.technique == Technique::lbs) {
      gq_.assign(n, Q<S>{});
      gt_.assign(n, V<S>{});
      for (const auto& level : rig_.levels) level_lbs(level, a);
    } else {
      gd_.assign(n, D<S>{});
      for (const auto& level : rig_.levels) level_dqs(level, a, blend ? &b : nullptr, req.alpha);
    }
    globals.assign(n, JointTransform{});
    for (std::size_t j = 0; j < n; ++j) globals[j] = output(j);
    if (skinning != nullptr) skin_transforms(*skinning);
  }

 private:
  struct Stretch {
    Mat3 k = identity3();
    bool stretched = false;
  };

  const SkinningMethod& m_;
  const impl::Ops<S>& ops_;
  const Rig& rig_;
  std::vector<std::uint8_t> st_;
  std::vector<Q<S>> gq_;
  std::vector<V<S>> gt_;
  std::vector<D<S>> gd_;
  std::vector<Stretch> gK_;

  static Stretch local_stretch(const Local& l) {
    if (l.matrix != nullptr) return {l.matrix->stretch, l.matrix->stretched};
    Stretch k;
    k.k = {l.s[0], 0.0, 0.0, 0.0, l.s[1], 0.0, 0.0, 0.0, l.s[2]};
    k.stretched = !(l.s[0] == 1.0 && l.s[1] == 1.0 && l.s[2] == 1.0);
    return k;
  }
  /// K_child = R(q)^T K_parent R(q) K_local (pose_job.hpp), in binary64.
  static Stretch child_stretch(const Stretch& parent, const Quat& q, const Stretch& local) {
    if (!parent.stretched) return local;
    Stretch r;
    r.stretched = true;
    if (pose_math::is_scalar_matrix(parent.k)) {
      r.k = local.k;  // R^T (c I) R = c I
      for (double& x : r.k) x *= parent.k[0];
      return r;
    }
    const Mat3 rot = pose_math::rotation3(q);
    r.k = pose_math::mul3(pose_math::mul3(pose_math::transpose3(rot), pose_math::mul3(parent.k, rot)), local.k);
    return r;
  }
  /// K t in binary64, rounded to the method's format.
  static V<S> stretched(const Stretch& k, const Vec3& t) {
    return to_s<S>(k.stretched ? pose_math::mul3v(k.k, t) : t);
  }

  // ---- sampling ---------------------------------------------------------------------------

  std::vector<Local> sample(const PoseSample& ps) {
    const Skeleton& sk = *rig_.skeleton;
    const std::size_t n = sk.joints.size();
    std::vector<Local> out(n);
    for (std::size_t j = 0; j < n; ++j) {
      if (rig_.matrix_local[j]) {
        out[j].matrix = &*rig_.matrix_local[j];
        out[j].q = out[j].matrix->rotation;
        out[j].t = out[j].matrix->translation;
      } else {
        out[j].q = sk.joints[j].rest.rotation;
        out[j].t = sk.joints[j].rest.translation;
        out[j].s = sk.joints[j].rest.scale;
      }
    }
    if (ps.clip == nullptr) return out;
    const Clip& clip = *ps.clip;
    const double tc = std::clamp(ps.time, clip.start, std::max(clip.start, clip.end));
    std::vector<std::size_t> lin_joint, cub_joint;
    std::vector<Q<S>> lin_a, lin_b, cub_q;
    std::vector<S> lin_s;
    for (const Channel& ch : clip.channels) {
      if (ch.joint >= n) continue;  // a clip of another skeleton: as sample_pose does
      if (ch.path != ChannelPath::rotation) {
        const auto v = sample_channel(ch, tc);
        (ch.path == ChannelPath::translation ? out[ch.joint].t : out[ch.joint].s) = Vec3{v[0], v[1], v[2]};
        continue;
      }
      const pose_math::KeyLocation loc = pose_math::locate(ch, tc);
      switch (loc.kind) {
        case pose_math::KeyLocation::key: out[ch.joint].q = pose_math::key_quat(ch, loc.k); break;
        case pose_math::KeyLocation::linear:
          lin_joint.push_back(ch.joint);
          lin_a.push_back(to_s<S>(pose_math::key_quat(ch, loc.k)));
          lin_b.push_back(to_s<S>(pose_math::key_quat(ch, loc.k + 1)));
          lin_s.push_back(static_cast<S>(loc.s));
          break;
        case pose_math::KeyLocation::cubic:
          cub_joint.push_back(ch.joint);
          cub_q.push_back(to_s<S>(pose_math::hermite_rotation(ch, loc)));
          break;
      }
    }
    if (!lin_joint.empty()) {
      const auto q = interpolate_keys(lin_a, lin_b, lin_s);
      for (std::size_t i = 0; i < lin_joint.size(); ++i) out[lin_joint[i]].q = to_d(q[i]);
    }
    if (!cub_joint.empty()) {
      const auto q = normalize(cub_q);
      for (std::size_t i = 0; i < cub_joint.size(); ++i) out[cub_joint[i]].q = to_d(q[i]);
    }
    return out;
  }

  std::vector<Q<S>> interpolate_keys(const std::vector<Q<S>>& a, const std::vector<Q<S>>& b, const std::vector<S>& s) {
    const std::size_t n = a.size();
    if (m_.key_interpolation() == KeyInterpolation::slerp) {
      std::vector<S> out(4 * n);
      detail::call(m_, "slerp", ops_.slerp, n, st_, flat(a).data(), flat(b).data(), s.data(), out.data());
      return unflat<S, 4>(out);
    }
    // No slerp: ScLERP of rotation-only dual quaternions, whose real part is the slerp (DQ-5).
    std::vector<D<S>> da(n), db(n);
    for (std::size_t i = 0; i < n; ++i) {
      da[i] = {a[i][0], a[i][1], a[i][2], a[i][3], 0, 0, 0, 0};
      db[i] = {b[i][0], b[i][1], b[i][2], b[i][3], 0, 0, 0, 0};
    }
    std::vector<S> out(8 * n);
    detail::call(m_, "dq_sclerp", ops_.dq_sclerp, n, st_, flat(da).data(), flat(db).data(), s.data(), out.data());
    std::vector<Q<S>> r(n);
    for (std::size_t i = 0; i < n; ++i) r[i] = {out[8 * i], out[8 * i + 1], out[8 * i + 2], out[8 * i + 3]};
    return r;
  }

  std::vector<Q<S>> normalize(const std::vector<Q<S>>& q) {
    const std::size_t n = q.size();
    if (ops_.normalize != nullptr) {
      std::vector<S> out(4 * n);
      detail::call(m_, "normalize", ops_.normalize, n, st_, flat(q).data(), out.data());
      return unflat<S, 4>(out);
    }
    std::vector<D<S>> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = {q[i][0], q[i][1], q[i][2], q[i][3], 0, 0, 0, 0};
    std::vector<S> out(8 * n);
    detail::call(m_, "dq_normalize", ops_.dq_normalize, n, st_, flat(d).data(), out.data());
    std::vector<Q<S>> r(n);
    for (std::size_t i = 0; i < n; ++i) r[i] = {out[8 * i], out[8 * i + 1], out[8 * i + 2], out[8 * i + 3]};
    return r;
  }

  /// LBS pose blend: every joint's rotation by blend_qlb (1 - alpha, alpha), else nlerp.
  void blend_rotations(std::vector<Local>& a, const std::vector<Local>& b, double alpha) {
    const std::size_t n = a.size();
    std::vector<S> out(4 * n);
    if (m_.pose_blend() == PoseBlend::qlb) {
      std::vector<Q<S>> q(2 * n);
      std::vector<S> w(2 * n);
      for (std::size_t j = 0; j < n; ++j) {
        q[2 * j] = to_s<S>(a[j].q);
        q[2 * j + 1] = to_s<S>(b[j].q);
        w[2 * j] = static_cast<S>(1.0 - alpha);
        w[2 * j + 1] = static_cast<S>(alpha);
      }
      detail::call(m_, "blend_qlb", ops_.blend_qlb, n, st_, std::size_t{2}, flat(q).data(), w.data(), out.data());
    } else {
      std::vector<Q<S>> qa(n), qb(n);
      for (std::size_t j = 0; j < n; ++j) {
        qa[j] = to_s<S>(a[j].q);
        qb[j] = to_s<S>(b[j].q);
      }
      const std::vector<S> t(n, static_cast<S>(alpha));
      detail::call(m_, "nlerp", ops_.nlerp, n, st_, flat(qa).data(), flat(qb).data(), t.data(), out.data());
    }
    for (std::size_t j = 0; j < n; ++j) a[j].q = {out[4 * j], out[4 * j + 1], out[4 * j + 2], out[4 * j + 3]};
  }

  // ---- hierarchy ----------------------------------------------------------------------------

  std::size_t parent(std::size_t j) const { return static_cast<std::size_t>(rig_.skeleton->joints[j].parent); }

  void level_lbs(const std::vector<std::size_t>& level, const std::vector<Local>& loc) {
    const std::size_t m = level.size();
    if (rig_.depth[level.front()] == 0) {
      for (std::size_t j : level) {
        gq_[j] = to_s<S>(loc[j].q);
        gt_[j] = to_s<S>(loc[j].t);
        gK_[j] = local_stretch(loc[j]);
      }
      return;
    }
    std::vector<Q<S>> pq(m), lq(m);
    std::vector<V<S>> u(m);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = level[i], p = parent(j);
      pq[i] = gq_[p];
      lq[i] = to_s<S>(loc[j].q);
      u[i] = stretched(gK_[p], loc[j].t);
    }
    const auto fpq = flat(pq);
    std::vector<S> q(4 * m), r(3 * m);
    detail::call(m_, "compose", ops_.compose, m, st_, fpq.data(), flat(lq).data(), q.data());
    detail::call(m_, "apply_vector", ops_.apply_vector, m, st_, fpq.data(), flat(u).data(), r.data());
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = level[i], p = parent(j);
      gq_[j] = {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]};
      for (std::size_t c = 0; c < 3; ++c) gt_[j][c] = gt_[p][c] + r[3 * i + c];  // in the method's format
      gK_[j] = child_stretch(gK_[p], to_d(lq[i]), local_stretch(loc[j]));
    }
  }

  std::vector<D<S>> dq_from_rt(const std::vector<Q<S>>& q, const std::vector<V<S>>& t) {
    std::vector<S> out(8 * q.size());
    detail::call(m_, "dq_from_rotation_translation", ops_.dq_from_rotation_translation, q.size(), st_, flat(q).data(),
                 flat(t).data(), out.data());
    return unflat<S, 8>(out);
  }

  void level_dqs(const std::vector<std::size_t>& level, const std::vector<Local>& a, const std::vector<Local>* b,
                 double alpha) {
    const std::size_t m = level.size();
    const bool root = rig_.depth[level.front()] == 0;
    const Stretch none;
    auto parent_stretch = [&](std::size_t j) -> const Stretch& { return root ? none : gK_[parent(j)]; };
    std::vector<Q<S>> qa(m), qb(m);
    std::vector<V<S>> ua(m), ub(m);
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = level[i];
      qa[i] = to_s<S>(a[j].q);
      ua[i] = stretched(parent_stretch(j), a[j].t);
      if (b != nullptr) {
        qb[i] = to_s<S>((*b)[j].q);
        ub[i] = stretched(parent_stretch(j), (*b)[j].t);
      }
    }
    std::vector<D<S>> local = dq_from_rt(qa, ua);
    if (b != nullptr) {
      const std::vector<D<S>> lb = dq_from_rt(qb, ub);
      std::vector<S> out(8 * m);
      if (m_.pose_blend() == PoseBlend::dlb) {
        std::vector<D<S>> pair(2 * m);
        std::vector<S> w(2 * m);
        for (std::size_t i = 0; i < m; ++i) {
          pair[2 * i] = local[i];
          pair[2 * i + 1] = lb[i];
          w[2 * i] = static_cast<S>(1.0 - alpha);
          w[2 * i + 1] = static_cast<S>(alpha);
        }
        detail::call(m_, "dq_blend", ops_.dq_blend, m, st_, std::size_t{2}, flat(pair).data(), w.data(), out.data());
      } else {
        const std::vector<S> t(m, static_cast<S>(alpha));
        detail::call(m_, "dq_sclerp", ops_.dq_sclerp, m, st_, flat(local).data(), flat(lb).data(), t.data(), out.data());
      }
      local = unflat<S, 8>(out);
    }
    std::vector<D<S>> global = local;
    if (!root) {
      std::vector<D<S>> pd(m);
      for (std::size_t i = 0; i < m; ++i) pd[i] = gd_[parent(level[i])];
      std::vector<S> out(8 * m);
      detail::call(m_, "dq_compose", ops_.dq_compose, m, st_, flat(pd).data(), flat(local).data(), out.data());
      global = unflat<S, 8>(out);
    }
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = level[i];
      gd_[j] = global[i];
      const Quat lq{double(local[i][0]), double(local[i][1]), double(local[i][2]), double(local[i][3])};
      gK_[j] = child_stretch(parent_stretch(j), lq, local_stretch(a[j]));
    }
  }

  // ---- outputs ------------------------------------------------------------------------------

  JointTransform output(std::size_t j) const {
    JointTransform o;
    o.stretch = gK_[j].k;
    o.stretched = gK_[j].stretched;
    if (m_.technique == Technique::lbs) {
      o.rotation = to_d(gq_[j]);
      o.translation = to_d(gt_[j]);
    } else {
      set_motion(o, to_d(gd_[j]));
    }
    return o;
  }

  static void set_motion(JointTransform& o, const std::array<double, 8>& d) {
    o.motion = d;
    o.has_motion = true;
    o.rotation = {d[0], d[1], d[2], d[3]};
    o.translation = pose_math::dq_translation(d);
  }

  /// global * inverse bind for every joint, one call per op.
  void skin_transforms(std::vector<JointTransform>& out) {
    const std::size_t n = rig_.skeleton->joints.size();
    std::vector<Q<S>> qb(n);
    std::vector<V<S>> u(n);
    for (std::size_t j = 0; j < n; ++j) {
      qb[j] = to_s<S>(rig_.inverse_bind[j].rotation);
      u[j] = stretched(gK_[j], rig_.inverse_bind[j].translation);
    }
    out.assign(n, JointTransform{});
    for (std::size_t j = 0; j < n; ++j) {
      const Stretch kb{rig_.inverse_bind[j].stretch, rig_.inverse_bind[j].stretched};
      const Stretch k = child_stretch(gK_[j], rig_.inverse_bind[j].rotation, kb);
      out[j].stretch = k.k;
      out[j].stretched = k.stretched;
    }
    if (m_.technique == Technique::lbs) {
      const auto fgq = flat(gq_);
      std::vector<S> q(4 * n), r(3 * n);
      detail::call(m_, "compose", ops_.compose, n, st_, fgq.data(), flat(qb).data(), q.data());
      detail::call(m_, "apply_vector", ops_.apply_vector, n, st_, fgq.data(), flat(u).data(), r.data());
      for (std::size_t j = 0; j < n; ++j) {
        out[j].rotation = {double(q[4 * j]), double(q[4 * j + 1]), double(q[4 * j + 2]), double(q[4 * j + 3])};
        for (std::size_t c = 0; c < 3; ++c) out[j].translation[c] = double(S(gt_[j][c] + r[3 * j + c]));
      }
      return;
    }
    const std::vector<D<S>> db = dq_from_rt(qb, u);
    std::vector<S> d(8 * n);
    detail::call(m_, "dq_compose", ops_.dq_compose, n, st_, flat(gd_).data(), flat(db).data(), d.data());
    for (std::size_t j = 0; j < n; ++j) {
      std::array<double, 8> dj;
      for (std::size_t c = 0; c < 8; ++c) dj[c] = double(d[8 * j + c]);
      set_motion(out[j], dj);
    }
  }
};

}  // namespace

Rig prepare_rig(const Skeleton& skeleton) {
  if (mpfr::mpreal::get_default_prec() < ref::kReferenceBits)
    throw std::logic_error("prepare_rig: call rotorcert::ref::use_reference_precision() first (NUM-2)");
  Rig rig;
  rig.skeleton = &skeleton;
  const std::size_t n = skeleton.joints.size();
  rig.depth.assign(n, 0);
  rig.matrix_local.assign(n, std::nullopt);
  rig.inverse_bind.assign(n, JointTransform{});
  for (std::size_t j = 0; j < n; ++j) {
    const Joint& jt = skeleton.joints[j];
    if (jt.parent >= 0) rig.depth[j] = rig.depth[static_cast<std::size_t>(jt.parent)] + 1;  // parents first
    const auto d = static_cast<std::size_t>(rig.depth[j]);
    if (rig.levels.size() <= d) rig.levels.resize(d + 1);
    rig.levels[d].push_back(j);
    if (jt.matrix) rig.matrix_local[j] = decompose(*jt.matrix, "joint " + jt.name + " matrix");
    rig.inverse_bind[j] = decompose(jt.inverse_bind, "joint " + jt.name + " inverse bind matrix");
  }
  return rig;
}

std::string PoseJob::validate() const {
  if (method.table == nullptr) return "no implementation table";
  if (rig == nullptr || rig->skeleton == nullptr) return "no rig";
  if (globals == nullptr) return "no output for the global transforms";
  if ((method.table->scalar == RC_SCALAR_FLOAT32 && method.table->f32 == nullptr) ||
      (method.table->scalar == RC_SCALAR_FLOAT64 && method.table->f64 == nullptr))
    return "table without ops for its scalar type";
  const std::string missing = missing_ops(*method.table, method.technique);
  if (!missing.empty()) return method.name() + ": no " + missing;
  if (rig->depth.size() != rig->skeleton->joints.size()) return "rig prepared for another skeleton";
  for (const PoseSample* s : {&request.a, request.b ? &*request.b : nullptr}) {
    if (s == nullptr || s->clip == nullptr) continue;
    for (const Channel& ch : s->clip->channels)
      if (ch.path == ChannelPath::rotation && ch.interpolation == Interpolation::cubicspline) {
        const bool has_normalize = method.is_float() ? method.table->f32->normalize != nullptr
                                                     : method.table->f64->normalize != nullptr;
        const bool has_dq_normalize = method.is_float() ? method.table->f32->dq_normalize != nullptr
                                                        : method.table->f64->dq_normalize != nullptr;
        if (!has_normalize && !(method.technique == Technique::dqs && has_dq_normalize))
          return method.name() + ": CUBICSPLINE rotations need normalize";
      }
  }
  if (request.b) {
    if (method.pose_blend() == PoseBlend::none) return method.name() + ": no op to blend two poses";
    if (!std::isfinite(request.alpha)) return "blend weight is not finite";
  }
  return {};
}

bool PoseJob::run() {
  message = validate();
  if (!message.empty()) return false;
  try {
    if (method.is_float()) Runner<float>(method, *rig).run(request, *globals, skinning);
    else Runner<double>(method, *rig).run(request, *globals, skinning);
  } catch (const MethodError& e) {
    message = e.what();
    return false;
  }
  return true;
}

}  // namespace rotorcert::render

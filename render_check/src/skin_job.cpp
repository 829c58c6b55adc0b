// CPU skinning with one implementation (skin_job.hpp).
#include <rotorcert/render/skin_job.hpp>

#include <cmath>

#include <rotorcert/impl.hpp>

namespace rotorcert::render {

namespace {

template <class S> const impl::Ops<S>& ops_of(const rc_impl& t) {
  if constexpr (std::is_same_v<S, float>) return *t.f32;
  else return *t.f64;
}

template <class S> using M3 = std::array<S, 9>;  // column-major
template <class S> using V3 = std::array<S, 3>;

template <class S> V3<S> mul(const M3<S>& a, const Vec3& v) {
  const S x = static_cast<S>(v[0]), y = static_cast<S>(v[1]), z = static_cast<S>(v[2]);
  return {a[0] * x + a[3] * y + a[6] * z, a[1] * x + a[4] * y + a[7] * z, a[2] * x + a[5] * y + a[8] * z};
}

template <class S> Vec3 unit(const V3<S>& v) {
  using std::sqrt;
  const S len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {double(v[0] / len), double(v[1] / len), double(v[2] / len)};
}

template <class S>
class Skinner {
 public:
  Skinner(const SkinningMethod& m, const SkinnedMesh& mesh, const std::vector<JointTransform>& x)
      : m_(m), ops_(ops_of<S>(*m.table)), mesh_(mesh), x_(x) {}

  void run(SkinOutput& out) {
    const std::size_t nv = mesh_.positions.size();
    out.positions.assign(nv, Vec3{});
    out.normals.assign(nv, Vec3{});
    if (nv == 0) return;
    if (m_.technique == Technique::lbs) lbs(out);
    else dqs(out);
  }

 private:
  const SkinningMethod& m_;
  const impl::Ops<S>& ops_;
  const SkinnedMesh& mesh_;
  const std::vector<JointTransform>& x_;
  std::vector<std::uint8_t> st_;

  /// w_k / W in the method's format (SKIN-1/SKIN-2 divide by the weight sum).
  std::array<S, 4> weights(std::size_t v) const {
    std::array<S, 4> w;
    S total = 0;
    for (std::size_t k = 0; k < 4; ++k) total += w[k] = static_cast<S>(mesh_.weights[v][k]);
    for (auto& x : w) x /= total;
    return w;
  }

  static M3<S> stretch_of(const JointTransform& x) {
    M3<S> k;
    for (std::size_t i = 0; i < 9; ++i) k[i] = static_cast<S>(x.stretch[i]);
    return k;
  }

  void lbs(SkinOutput& out) {
    const std::size_t nj = x_.size();
    std::vector<S> q(4 * nj), mats(9 * nj);
    for (std::size_t j = 0; j < nj; ++j)
      for (std::size_t c = 0; c < 4; ++c) q[4 * j + c] = static_cast<S>(x_[j].rotation[c]);
    detail::call(m_, "to_matrix", ops_.to_matrix, nj, st_, q.data(), mats.data());
    std::vector<M3<S>> a(nj);
    std::vector<V3<S>> t(nj);
    for (std::size_t j = 0; j < nj; ++j) {
      M3<S> r;
      for (std::size_t i = 0; i < 9; ++i) r[i] = mats[9 * j + i];
      if (x_[j].stretched) {  // A = R K, in the method's format
        const M3<S> k = stretch_of(x_[j]);
        for (std::size_t c = 0; c < 3; ++c)
          for (std::size_t row = 0; row < 3; ++row)
            a[j][3 * c + row] = r[row] * k[3 * c] + r[3 + row] * k[3 * c + 1] + r[6 + row] * k[3 * c + 2];
      } else {
        a[j] = r;
      }
      for (std::size_t c = 0; c < 3; ++c) t[j][c] = static_cast<S>(x_[j].translation[c]);
    }
    for (std::size_t v = 0; v < mesh_.positions.size(); ++v) {
      const auto w = weights(v);
      M3<S> m{};
      V3<S> tv{};
      for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t j = mesh_.joints[v][k];
        for (std::size_t i = 0; i < 9; ++i) m[i] += w[k] * a[j][i];
        for (std::size_t i = 0; i < 3; ++i) tv[i] += w[k] * t[j][i];
      }
      const V3<S> p = mul(m, mesh_.positions[v]);
      out.positions[v] = {double(p[0] + tv[0]), double(p[1] + tv[1]), double(p[2] + tv[2])};
      out.normals[v] = unit(mul(m, mesh_.normals[v]));
    }
  }

  /// sum (w_k/W) K_jk x, or x when no influence is stretched.
  V3<S> stretched(std::size_t v, const std::array<S, 4>& w, const Vec3& x) const {
    bool any = false;
    for (std::size_t k = 0; k < 4; ++k) any = any || x_[mesh_.joints[v][k]].stretched;
    if (!any) return {static_cast<S>(x[0]), static_cast<S>(x[1]), static_cast<S>(x[2])};
    V3<S> r{};
    for (std::size_t k = 0; k < 4; ++k) {
      const JointTransform& xj = x_[mesh_.joints[v][k]];
      const V3<S> y = xj.stretched ? mul(stretch_of(xj), x)
                                   : V3<S>{static_cast<S>(x[0]), static_cast<S>(x[1]), static_cast<S>(x[2])};
      for (std::size_t i = 0; i < 3; ++i) r[i] += w[k] * y[i];
    }
    return r;
  }

  void dqs(SkinOutput& out) {
    const std::size_t nv = mesh_.positions.size();
    std::vector<S> w(4 * nv), p(3 * nv), n(3 * nv);
    for (std::size_t v = 0; v < nv; ++v) {
      const auto wv = weights(v);
      const V3<S> ps = stretched(v, wv, mesh_.positions[v]), ns = stretched(v, wv, mesh_.normals[v]);
      for (std::size_t k = 0; k < 4; ++k) w[4 * v + k] = wv[k];
      for (std::size_t i = 0; i < 3; ++i) {
        p[3 * v + i] = ps[i];
        n[3 * v + i] = ns[i];
      }
    }
    std::vector<S> pos(3 * nv), nor(3 * nv);
    if (m_.dqs_route() == DqsRoute::blend_and_apply) {
      std::vector<S> d(32 * nv), blended(8 * nv);
      for (std::size_t v = 0; v < nv; ++v)
        for (std::size_t k = 0; k < 4; ++k)
          for (std::size_t c = 0; c < 8; ++c) d[8 * (4 * v + k) + c] = static_cast<S>(x_[mesh_.joints[v][k]].motion[c]);
      detail::call(m_, "dq_blend", ops_.dq_blend, nv, st_, std::size_t{4}, d.data(), w.data(), blended.data());
      detail::call(m_, "dq_apply_point", ops_.dq_apply_point, nv, st_, blended.data(), p.data(), pos.data());
      for (std::size_t v = 0; v < nv; ++v)
        for (std::size_t c = 4; c < 8; ++c) blended[8 * v + c] = 0;  // the rotation alone turns normals
      detail::call(m_, "dq_apply_point", ops_.dq_apply_point, nv, st_, blended.data(), n.data(), nor.data());
    } else {
      std::vector<S> q(16 * nv), t(12 * nv), zero(12 * nv, S(0));
      for (std::size_t v = 0; v < nv; ++v)
        for (std::size_t k = 0; k < 4; ++k) {
          const auto& d = x_[mesh_.joints[v][k]].motion;
          for (std::size_t c = 0; c < 4; ++c) q[4 * (4 * v + k) + c] = static_cast<S>(d[c]);
          const auto tr = translation(d);
          for (std::size_t c = 0; c < 3; ++c) t[3 * (4 * v + k) + c] = tr[c];
        }
      detail::call(m_, "skin_dual_quaternion", ops_.skin_dual_quaternion, nv, st_, std::size_t{4}, q.data(), t.data(),
                   w.data(), p.data(), pos.data());
      detail::call(m_, "skin_dual_quaternion", ops_.skin_dual_quaternion, nv, st_, std::size_t{4}, q.data(),
                   zero.data(), w.data(), n.data(), nor.data());
    }
    for (std::size_t v = 0; v < nv; ++v) {
      out.positions[v] = {double(pos[3 * v]), double(pos[3 * v + 1]), double(pos[3 * v + 2])};
      out.normals[v] = unit(V3<S>{nor[3 * v], nor[3 * v + 1], nor[3 * v + 2]});
    }
  }

  /// Vector part of 2 dual real* / |real|^2 in the method's format.
  static V3<S> translation(const std::array<double, 8>& dd) {
    std::array<S, 8> d;
    for (std::size_t i = 0; i < 8; ++i) d[i] = static_cast<S>(dd[i]);
    const S ax = d[4], ay = d[5], az = d[6], aw = d[7], bx = -d[0], by = -d[1], bz = -d[2], bw = d[3];
    const S n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3];
    return {S(2) * (aw * bx + ax * bw + ay * bz - az * by) / n2, S(2) * (aw * by - ax * bz + ay * bw + az * bx) / n2,
            S(2) * (aw * bz + ax * by - ay * bx + az * bw) / n2};
  }
};

}  // namespace

std::string SkinJob::validate() const {
  if (method.table == nullptr) return "no implementation table";
  if (mesh == nullptr) return "no mesh";
  if (skinning == nullptr) return "no skinning transforms";
  if (output == nullptr) return "no output";
  const std::string missing = missing_ops(*method.table, method.technique);
  if (!missing.empty()) return method.name() + ": no " + missing;
  const std::size_t nv = mesh->positions.size();
  if (mesh->normals.size() != nv || mesh->joints.size() != nv || mesh->weights.size() != nv)
    return "mesh arrays differ in length";
  for (std::size_t v = 0; v < nv; ++v) {
    double total = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      if (mesh->joints[v][k] >= skinning->size()) return "vertex " + std::to_string(v) + " names a joint out of range";
      if (!(mesh->weights[v][k] >= 0)) return "vertex " + std::to_string(v) + " has a negative or NaN weight";
      total += mesh->weights[v][k];
    }
    if (!(total > 0)) return "vertex " + std::to_string(v) + " has no weight";
  }
  if (method.technique == Technique::dqs)
    for (const auto& x : *skinning)
      if (!x.has_motion) return "DQS needs the dual quaternions of a DQS PoseJob";
  return {};
}

bool SkinJob::run() {
  message = validate();
  if (!message.empty()) return false;
  try {
    if (method.is_float()) Skinner<float>(method, *mesh, *skinning).run(*output);
    else Skinner<double>(method, *mesh, *skinning).run(*output);
  } catch (const MethodError& e) {
    message = e.what();
    return false;
  }
  return true;
}

}  // namespace rotorcert::render

// Clip sampling per glTF 2.0 Appendix C, and skeleton posing (GLTF-2 of spec/SPEC.md).
#include <rotorcert/render/sample.hpp>

#include <algorithm>
#include <cmath>

#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

namespace {

/// q / |q| for a finite nonzero q; q itself otherwise (nothing to normalise).
Quat unit(const Quat& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 0.0) || !std::isfinite(n)) return q;
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

}  // namespace

Quat slerp(const Quat& a_in, const Quat& b_in, double s) {
  // SLERP-1 normalises both inputs (EDGE-5): binary32 keyframes are unit only to about 2^-24, and
  // weights computed for unit inputs would carry that norm into the result (~1e-8 rad off SLERP-1).
  const Quat a = unit(a_in), b = unit(b_in);
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const double sign = d < 0.0 ? -1.0 : 1.0;  // the shorter arc: interpolate towards -b
  // Angle between a and sign*b from atan2(|a - sb|, |a + sb|): accurate for near and far pairs,
  // unlike acos of the dot product.
  double dm = 0.0, dp = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double m = a[i] - sign * b[i], p = a[i] + sign * b[i];
    dm += m * m;
    dp += p * p;
  }
  const double theta = 2.0 * std::atan2(std::sqrt(dm), std::sqrt(dp));
  double wa, wb;
  if (theta == 0.0) {
    wa = 1.0 - s;  // identical rotations: the limit of the weights
    wb = s;
  } else {
    const double st = std::sin(theta);
    wa = std::sin((1.0 - s) * theta) / st;
    wb = std::sin(s * theta) / st;
  }
  Quat r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = wa * a[i] + sign * wb * b[i];
  return r;
}

namespace {

/// Element e of the channel's value array (width w), for element-wise arithmetic.
const double* element(const Channel& ch, std::size_t e) { return ch.values.data() + e * ch.width(); }

std::array<double, 4> copy_element(const Channel& ch, std::size_t e) {
  std::array<double, 4> r{0.0, 0.0, 0.0, 0.0};
  const double* p = element(ch, e);
  for (std::size_t i = 0; i < ch.width(); ++i) r[i] = p[i];
  return r;
}

}  // namespace

std::array<double, 4> sample_channel(const Channel& ch, double t, const QuatInterpolation& interp) {
  const std::size_t n = ch.times.size();
  const bool cubic = ch.interpolation == Interpolation::cubicspline;
  // Element index of keyframe k's value (CUBICSPLINE: the middle of the a_k, v_k, b_k triplet).
  auto value_at = [&](std::size_t k) { return cubic ? 3 * k + 1 : k; };
  if (n == 0) return {0.0, 0.0, 0.0, 1.0};
  if (!(t > ch.times.front())) return copy_element(ch, value_at(0));  // before the first (and NaN)
  if (t >= ch.times.back()) return copy_element(ch, value_at(n - 1));
  // k: the last keyframe with t_k <= t; then t_k <= t < t_{k+1}, so td > 0.
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin()) - 1;
  if (t == ch.times[k] || ch.interpolation == Interpolation::step) return copy_element(ch, value_at(k));
  const double td = ch.times[k + 1] - ch.times[k];
  const double s = (t - ch.times[k]) / td;
  const std::size_t w = ch.width();
  const bool rotation = ch.path == ChannelPath::rotation;
  std::array<double, 4> r{0.0, 0.0, 0.0, 0.0};
  if (!cubic) {
    if (rotation) {
      const auto a = copy_element(ch, k), b = copy_element(ch, k + 1);
      return interp(Quat{a[0], a[1], a[2], a[3]}, Quat{b[0], b[1], b[2], b[3]}, s);
    }
    const double *a = element(ch, k), *b = element(ch, k + 1);
    for (std::size_t i = 0; i < w; ++i) r[i] = (1.0 - s) * a[i] + s * b[i];
    return r;
  }
  // Hermite: p(s) = (2s^3 - 3s^2 + 1) v_k + td (s^3 - 2s^2 + s) b_k + (-2s^3 + 3s^2) v_k+1
  //               + td (s^3 - s^2) a_k+1
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = td * (s3 - 2 * s2 + s), h01 = -2 * s3 + 3 * s2, h11 = td * (s3 - s2);
  const double* vk = element(ch, 3 * k + 1);
  const double* bk = element(ch, 3 * k + 2);
  const double* vk1 = element(ch, 3 * (k + 1) + 1);
  const double* ak1 = element(ch, 3 * (k + 1));
  for (std::size_t i = 0; i < w; ++i) r[i] = h00 * vk[i] + h10 * bk[i] + h01 * vk1[i] + h11 * ak1[i];
  if (rotation) {
    const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    if (len > 0.0) for (auto& x : r) x /= len;  // a zero sum has no direction: left as it is
  }
  return r;
}

std::vector<Trs> rest_pose(const Skeleton& skeleton) {
  std::vector<Trs> pose;
  pose.reserve(skeleton.joints.size());
  for (const auto& j : skeleton.joints) pose.push_back(j.rest);
  return pose;
}

std::vector<Trs> sample_pose(const Skeleton& skeleton, const Clip& clip, double t, const QuatInterpolation& interp) {
  std::vector<Trs> pose = rest_pose(skeleton);
  const double tc = std::clamp(t, clip.start, std::max(clip.start, clip.end));
  for (const auto& ch : clip.channels) {
    if (ch.joint >= pose.size()) continue;  // a Clip from another skeleton: nothing to pose
    const auto v = sample_channel(ch, tc, interp);
    Trs& trs = pose[ch.joint];
    switch (ch.path) {
      case ChannelPath::translation: trs.translation = {v[0], v[1], v[2]}; break;
      case ChannelPath::scale: trs.scale = {v[0], v[1], v[2]}; break;
      case ChannelPath::rotation: trs.rotation = {v[0], v[1], v[2], v[3]}; break;
    }
  }
  return pose;
}

std::vector<Mat4> global_matrices(const Skeleton& skeleton, const std::vector<Trs>& local) {
  const std::size_t n = skeleton.joints.size();
  std::vector<Mat4> global(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Joint& jt = skeleton.joints[j];
    const Mat4 m = jt.matrix ? *jt.matrix : trs_matrix(j < local.size() ? local[j] : jt.rest);
    // parents precede children (Skeleton invariant), so global[parent] is ready
    global[j] = jt.parent < 0 ? m : multiply(global[static_cast<std::size_t>(jt.parent)], m);
  }
  return global;
}

std::vector<Mat4> skinning_matrices(const Skeleton& skeleton, const std::vector<Mat4>& global) {
  std::vector<Mat4> out(skeleton.joints.size());
  for (std::size_t j = 0; j < out.size() && j < global.size(); ++j) out[j] = multiply(global[j], skeleton.joints[j].inverse_bind);
  return out;
}

}  // namespace rotorcert::render

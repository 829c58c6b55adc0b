// Benchmark inputs. Distributions (Gen, op_layout.hpp), all in double, then rounded:
//   unit_quat     uniform on SO(3) (Shoemake's method)
//   near_quat     anchor * delta, delta about a uniform random axis by an angle uniform in
//                 [0, kNeighbourAngle]: consecutive keyframes, same hemisphere
//   scaled_quat   unit_quat times a scale uniform in [0.5, 1.5]
//   param_t       uniform in [0, 1]
//   angle         uniform in [-pi, pi]
//   unit_axis     uniform on S^2
//   point         uniform in [-1, 1]^3 (metres: a character-sized scene)
//   trivector     uniform in [-1, 1]
//   log_vec       (theta/2) axis, axis uniform on S^2, theta uniform in [0, pi]
//   rot_matrix    the matrix of a unit_quat (MAT-1), column-major
//   unit_dq       DQ-1 of a unit_quat and a point
//   near_dq       DQ-1 of (anchor rotation * delta as near_quat, anchor translation + [-0.1, 0.1]^3)
//   scaled_dq     unit_dq with both parts times a scale uniform in [0.5, 1.5]
//   cluster_quat  k rotations base * delta_j (delta_j as near_quat), one uniform base per element
//   cluster_dq    DQ-1 of cluster_quat rotations and point translations
//   weights       k values uniform in [0.05, 1] divided by their sum
#include "inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace rotorcert::bench {
namespace {

struct Quat {
  double x = 0, y = 0, z = 0, w = 1;
};
struct Vec3 {
  double x = 0, y = 0, z = 0;
};

Quat mul(const Quat& a, const Quat& b) {
  return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

class Draw {
 public:
  Draw() : rng_(kSeed) {}
  // 53 random bits, not std::uniform_real_distribution, whose algorithm each library chooses:
  // the values are then the same with every compiler and standard library.
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  }

  Quat unit_quat() {  // Shoemake 1992
    const double u1 = uniform(0, 1), u2 = uniform(0, 2 * std::numbers::pi), u3 = uniform(0, 2 * std::numbers::pi);
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    return {a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3)};
  }
  Vec3 unit_axis() {
    const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi), r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  Vec3 point() { return {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}; }
  Quat near(const Quat& anchor) {
    const Vec3 u = unit_axis();
    const double half = uniform(0, kNeighbourAngle) / 2, s = std::sin(half);
    return mul(anchor, Quat{s * u.x, s * u.y, s * u.z, std::cos(half)});
  }

 private:
  std::mt19937_64 rng_;
};

/// DQ-1: real = q, dual = 1/2 (t, 0) q; written [real xyzw, dual xyzw].
void put_dq(const Quat& q, const Vec3& t, double scale, double* out) {
  const Quat d = mul(Quat{t.x, t.y, t.z, 0}, q);
  const double r[8] = {q.x, q.y, q.z, q.w, d.x / 2, d.y / 2, d.z / 2, d.w / 2};
  for (int c = 0; c < 8; ++c) out[c] = r[c] * scale;
}

void put_quat(const Quat& q, double scale, double* out) {
  out[0] = q.x * scale, out[1] = q.y * scale, out[2] = q.z * scale, out[3] = q.w * scale;
}

void put_vec(const Vec3& v, double* out) { out[0] = v.x, out[1] = v.y, out[2] = v.z; }

/// MAT-1, column-major m[c * 3 + r].
void put_matrix(const Quat& q, double* m) {
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) m[c * 3 + row] = r[row][c];
}

}  // namespace

template <class S>
void fill_inputs(const OpSpec& op, std::size_t n, std::size_t k, S* const* in) {
  Draw draw;
  std::vector<double> v(16 * (k > 0 ? k : 1));  // one element's values of one array
  for (std::size_t i = 0; i < n; ++i) {
    // Anchors tie an element's arrays together: b near a (slerp, ScLERP), the influences of a
    // cluster near one base rotation.
    Quat anchor_q, base_q;
    Vec3 anchor_t;
    bool have_base = false;
    for (std::size_t j = 0; j < op.n_in; ++j) {
      const ArraySpec& a = op.in[j];
      const std::size_t count = a.per_influence ? k : 1;
      const std::size_t stride = static_cast<std::size_t>(a.stride);
      for (std::size_t m = 0; m < count; ++m) {
        double* e = v.data() + m * stride;
        switch (a.gen) {
          case Gen::unit_quat: put_quat(anchor_q = draw.unit_quat(), 1, e); break;
          case Gen::near_quat: put_quat(draw.near(anchor_q), 1, e); break;
          case Gen::scaled_quat: put_quat(draw.unit_quat(), draw.uniform(0.5, 1.5), e); break;
          case Gen::param_t: e[0] = draw.uniform(0, 1); break;
          case Gen::angle: e[0] = draw.uniform(-std::numbers::pi, std::numbers::pi); break;
          case Gen::unit_axis: put_vec(draw.unit_axis(), e); break;
          case Gen::point: put_vec(draw.point(), e); break;
          case Gen::trivector: e[0] = draw.uniform(-1, 1); break;
          case Gen::log_vec: {
            const Vec3 u = draw.unit_axis();
            const double half = draw.uniform(0, std::numbers::pi) / 2;
            put_vec({half * u.x, half * u.y, half * u.z}, e);
            break;
          }
          case Gen::rot_matrix: put_matrix(draw.unit_quat(), e); break;
          case Gen::unit_dq:
            anchor_q = draw.unit_quat();
            anchor_t = draw.point();
            put_dq(anchor_q, anchor_t, 1, e);
            break;
          case Gen::near_dq: {
            const Vec3 dt{draw.uniform(-0.1, 0.1), draw.uniform(-0.1, 0.1), draw.uniform(-0.1, 0.1)};
            const Quat q = draw.near(anchor_q);
            put_dq(q, {anchor_t.x + dt.x, anchor_t.y + dt.y, anchor_t.z + dt.z}, 1, e);
            break;
          }
          case Gen::scaled_dq: {
            const Quat q = draw.unit_quat();
            const Vec3 t = draw.point();
            put_dq(q, t, draw.uniform(0.5, 1.5), e);
            break;
          }
          case Gen::cluster_quat:
          case Gen::cluster_dq: {
            if (!have_base) base_q = draw.unit_quat(), have_base = true;
            const Quat q = draw.near(base_q);
            if (a.gen == Gen::cluster_quat) put_quat(q, 1, e);
            else put_dq(q, draw.point(), 1, e);
            break;
          }
          case Gen::weights: e[0] = draw.uniform(0.05, 1); break;
          case Gen::dual_vec: {
            const Vec3 u = draw.unit_axis();
            const double half = draw.uniform(0, std::numbers::pi) / 2;
            const Vec3 d = draw.point();
            const double xi[6] = {half * u.x, half * u.y, half * u.z, d.x / 2, d.y / 2, d.z / 2};
            std::copy(xi, xi + 6, e);
            break;
          }
        }
      }
      if (a.gen == Gen::weights) {
        double sum = 0;
        for (std::size_t m = 0; m < count; ++m) sum += v[m];
        for (std::size_t m = 0; m < count; ++m) v[m] /= sum;
      }
      S* dst = in[j] + i * stride * count;
      for (std::size_t c = 0; c < stride * count; ++c) dst[c] = static_cast<S>(v[c]);
    }
  }
}

template void fill_inputs<float>(const OpSpec&, std::size_t, std::size_t, float* const*);
template void fill_inputs<double>(const OpSpec&, std::size_t, std::size_t, double* const*);

}  // namespace rotorcert::bench

// assimp_adapter: the quaternion class of the Open Asset Import Library, Assimp 5.2.5 exactly as
// Debian 12 ships it (libassimp-dev 5.2.5~ds0-1+b1: /usr/include/assimp/quaternion.h + .inl,
// matrix3x3.h + .inl, vector3.h + .inl), certified through the C ABI (route "abi") as the dlopen
// plugin rotorcert_adapter_assimp.so with two tables named "assimp":
//   - float:  aiQuaternion = aiQuaterniont<ai_real>; Debian's build leaves ASSIMP_DOUBLE_PRECISION
//     undefined (assimp/config.h: "#undef ASSIMP_DOUBLE_PRECISION"), so ai_real is float
//     (defs.h:259) and this is the quaternion every aiAnimation key (aiQuatKey::mValue) holds;
//   - double: aiQuaterniont<double>, the same class template instantiated by the user. Every member
//     used here is defined inline in the headers (quaternion.inl, matrix3x3.inl, vector3.inl), so
//     the template compiles for double against the float library; libassimp itself holds no
//     quaternion code for either type.
//
// Every op is the Assimp call an Assimp user makes; conventions are mapped at this boundary and
// nothing else is done: no domain check, no rescaling, no renormalisation, no hemisphere flip the
// library does not do. Conventions (each from the headers, checked by the suite's examples):
//   - storage: aiQuaterniont is {w, x, y, z} (quaternion.h:125, constructor (w, x, y, z) at :69);
//     the ABI is [x, y, z, w]. Conversions go through the named members, never memory.
//   - product: operator* (quaternion.inl:280) is Hamilton's product: (this * t).x =
//     w t.x + x t.w + y t.z - z t.y, so compose(a, b) = a * b with no reordering.
//   - rotation: Rotate(v) (quaternion.inl:300) is q (0, v) q* (active; q* by Conjugate(), no
//     division by |q|^2), the ABI's v' = q v q*.
//   - matrix: aiMatrix3x3t is "*always* a row-major matrix" (matrix3x3.h:62), a1 a2 a3 its first
//     row; GetMatrix (quaternion.inl:170) has a2 = 2(xy - zw), the spec's MAT-1 row 0 column 1: the
//     ABI's column-major m[c*3 + r] <-> row r, column c of (a, b, c)(1, 2, 3).
//   - angles: radians (the axis-angle constructor takes sin(angle/2), cos(angle/2),
//     quaternion.inl:193).
//   - slerp: Interpolate(out, start, end, factor), "Start rotation of the interpolation at factor
//     == 0 ... End rotation, factor == 1" (quaternion.h:115), is slerp(a, b, t) with a = start,
//     b = end, t = factor.
// Status (RESULT-2): Assimp has no status channel; an element whose outputs are all NaN is
// DOMAIN_ERROR, anything else OK with the outputs as computed.
//
// Not supported (no Assimp call): inverse (Conjugate() is q*, documented as the conjugate, not an
// inverse), to_axis_angle (no quaternion accessor; aiMatrix4x4::Decompose(scaling, axis, angle,
// position) takes a 4x4 matrix), log, exp, nlerp, blends, dual quaternions and rigid motions,
// skinning, the trivector.
#include <assimp/types.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_table.hpp>

static_assert(sizeof(ai_real) == sizeof(float), "Debian 12's Assimp has ai_real = float (ASSIMP_DOUBLE_PRECISION unset)");

namespace {

using rotorcert::impl::Mat3;
using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;

// ---- conventions at the ABI boundary ------------------------------------------------------------

template <class S> aiQuaterniont<S> to_ai(const Quat<S>& q) { return aiQuaterniont<S>(q[3], q[0], q[1], q[2]); }
template <class S> Quat<S> from_ai(const aiQuaterniont<S>& q) { return {q.x, q.y, q.z, q.w}; }
template <class S> aiVector3t<S> to_ai(const Vec3<S>& v) { return aiVector3t<S>(v[0], v[1], v[2]); }
template <class S> Vec3<S> from_ai(const aiVector3t<S>& v) { return {v.x, v.y, v.z}; }
// Row-major aiMatrix3x3t (a1..a3 row 0, b1..b3 row 1, c1..c3 row 2) <-> column-major m[c*3 + r].
template <class S> aiMatrix3x3t<S> to_ai(const Mat3<S>& m) {
  return aiMatrix3x3t<S>(m[0], m[3], m[6],   // row 0: columns 0, 1, 2
                         m[1], m[4], m[7],   // row 1
                         m[2], m[5], m[8]);  // row 2
}
template <class S> Mat3<S> from_ai(const aiMatrix3x3t<S>& a) {
  return {a.a1, a.b1, a.c1,   // column 0
          a.a2, a.b2, a.c2,   // column 1
          a.a3, a.b3, a.c3};  // column 2
}

// ---- status rule (RESULT-2) -----------------------------------------------------------------------

template <class S, std::size_t N>
Status status_of(const std::array<S, N>& out) {
  for (S x : out)
    if (!std::isnan(x)) return Status::ok;
  return Status::domain_error;
}

template <class S>
struct AssimpTable {
  using Scalar = S;
  static constexpr const char* name = "assimp";
  static constexpr const char* version = "Assimp 5.2.5 (Debian 12 libassimp-dev 5.2.5~ds0-1+b1)";
  static constexpr const char* description =
      "Assimp 5.2.5 aiQuaterniont (Debian 12; float = aiQuaternion, ai_real = float; double = the "
      "header-only aiQuaterniont<double>) with no checks added. {w,x,y,z} <-> [x,y,z,w]; Hamilton "
      "operator*; Rotate = q v q* (also for bivectors); GetMatrix / aiQuaterniont(aiMatrix3x3t) "
      "row-major <-> column-major; aiQuaterniont(axis, angle); slerp = aiQuaterniont::Interpolate. "
      "Status: DOMAIN_ERROR iff every output is NaN.";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core (no INV-1: no inverse; no APPLY-3: no trivector; no AXANG-1: no angle/axis accessor)
      "QUAT-2", "NORM-1", "COMPOSE-1", "APPLY-1", "APPLY-2", "MAT-1", "MAT-2", "AXANG-2",
      // Interp (no LOG-*, EXP-*, NLERP-1: Assimp has none of them)
      "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5",
      // Robust (EDGE-9 judges weighted ops only; Assimp has none)
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", nullptr};
  // DECL-1, Assimp's documented preconditions:
  //   quaternion.h:72 aiQuaterniont(const aiMatrix3x3t&): "Construct from rotation matrix. Result is
  //     undefined if the matrix is not orthonormal."
  //   quaternion.h:117 Interpolate: "@param pFactor Interpolation factor between 0 and 1. Values
  //     outside of this range yield undefined results."
  static constexpr const char* const preconditions[] = {"from_matrix:rotation_matrix", "slerp:t_in_unit_interval",
                                                        nullptr};
  // Conventions Assimp chose (ACC-1): quaternion.inl:107-145, the matrix constructor takes w > 0
  // when the trace is positive, else makes the component of the largest diagonal entry positive
  // (x, y or z = 0.25 s) and lets w take any sign: -q of MAT-2's canonical q.
  static constexpr const char* const conventions[] = {"from_matrix:sign", nullptr};

  // -- Core --

  // quaternion.inl:263: mag = sqrt(x^2 + y^2 + z^2 + w^2); if (mag) multiply by 1/mag, else
  // unchanged.
  static Status normalize(const Quat<S>& q, Quat<S>& out) {
    aiQuaterniont<S> a = to_ai(q);
    a.Normalize();
    out = from_ai(a);
    return status_of(out);
  }
  static Status compose(const Quat<S>& a, const Quat<S>& b, Quat<S>& out) {
    out = from_ai(aiQuaterniont<S>(to_ai(a) * to_ai(b)));
    return status_of(out);
  }
  // quaternion.inl:300: (q * (0, v)) * Conjugate(q), the vector part.
  static Status apply_vector(const Quat<S>& q, const Vec3<S>& v, Vec3<S>& out) {
    out = from_ai(to_ai(q).Rotate(to_ai(v)));
    return status_of(out);
  }
  // [e23, e31, e12] rotate like a vector (APPLY-2); Assimp keeps a plane as its normal (axial)
  // vector (aiMesh::mNormals) and rotates it with the same call.
  static Status apply_bivector(const Quat<S>& q, const Vec3<S>& b, Vec3<S>& out) {
    out = from_ai(to_ai(q).Rotate(to_ai(b)));
    return status_of(out);
  }
  static Status to_matrix(const Quat<S>& q, Mat3<S>& out) {
    out = from_ai(to_ai(q).GetMatrix());
    return status_of(out);
  }
  // quaternion.inl:107: trace > 0: w = sqrt(1 + trace)/2 pivot, else the largest diagonal entry's
  // component (positive). No orthonormality or determinant check.
  static Status from_matrix(const Mat3<S>& m, Quat<S>& out) {
    out = from_ai(aiQuaterniont<S>(to_ai(m)));
    return status_of(out);
  }
  // quaternion.inl:189: axis.Normalize() (a zero axis is left unchanged, vector3.inl:100), then
  // (cos(angle/2), sin(angle/2) axis).
  static Status from_axis_angle(const S& angle, const Vec3<S>& axis, Quat<S>& out) {
    out = from_ai(aiQuaterniont<S>(to_ai(axis), angle));
    return status_of(out);
  }

  // -- Interp --

  // quaternion.inl:222: flips end when the dot < 0; acos / sin weights when 1 - cos > 1e-4, else
  // the plain linear weights 1 - t, t.
  static Status slerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    aiQuaterniont<S> r;
    aiQuaterniont<S>::Interpolate(r, to_ai(a), to_ai(b), t);
    out = from_ai(r);
    return status_of(out);
  }
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(std::uint32_t abi_version,
                                                                                     std::uint32_t index) {
  return rotorcert::impl::entry<AssimpTable<float>, AssimpTable<double>>(abi_version, index);
}

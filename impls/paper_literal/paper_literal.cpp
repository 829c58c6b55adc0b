// paper_literal: Papagiannakis (2013) exactly as printed, a documented NON-conforming
// implementation kept so that the suite shows which clauses the paper's errata break
// (spec Section 7; the predicted failures are listed in expected_failures.json).
//
// - Quaternion -> rotor by Method 2 AS PRINTED (Table 1, Appendix A):
//     Rsrc = srcQ.e(1) + srcQ.e(2)*(e2^e3) - srcQ.e(3)*(e1^e3) + srcQ.e(4)*(e1^e2)
//   = w + x e23 + y e31 + z e12 = Psi(q) = ~Phi(q)   (ERRATUM-2: the reverse rotor),
//   and rotor -> quaternion by the inverse of that same map (the "drop-in replacement").
// - slerp = the Appendix B interpolateGA as printed (ERRATUM-3), with Rsrc, Rdest from the
//   printed Method 2 and the angle-unit slip of ERRATUM-5 not involved (Method 2 has no angle).
// - Every other operation is computed in Cl(3,0) (impls/rotor/rotor3.hpp) with Psi in and
//   Psi^-1 out. Reversion is a linear isometry and an anti-automorphism that commutes with
//   exp, log, normalisation and inversion, so normalize, inverse, log, exp, nlerp, QLB and
//   the log-blend come out right; wherever a Psi-rotor meets geometry (the sandwich, the
//   matrix, eq. 5's angle and axis, the frame rotor of a matrix) or a product (compose), the
//   result is the inverse rotation or the reversed order.
// float only: the paper used float (GLM) throughout.
#include <rotorcert/impl_table.hpp>

#include "../rotor/rotor3.hpp"

namespace {

using rotorcert::impl::Mat3;
using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;
using rotorcert::rotor::Rotor3;

struct PrintedMethod2 {
  /// Psi(q/|q|) = w + x e23 + y e31 + z e12 (the paper normalises srcQ first).
  template <class S>
  static Rotor3<S> in(const Quat<S>& q) {
    const Quat<S> n = rotorcert::rotor::normalized(q);
    return {n[3], n[0], n[1], n[2]};
  }
  template <class S>
  static Rotor3<S> in_scaled(const Quat<S>& q) { return {q[3], q[0], q[1], q[2]}; }
  /// Psi^-1: w = s, x = e23, y = e31, z = e12.
  template <class S>
  static Quat<S> out(const Rotor3<S>& r) { return {r.e23, r.e31, r.e12, r.s}; }
  /// A pure quaternion x i + y j + z k is x e23 + y e31 + z e12 under Psi.
  template <class S> static Vec3<S> pure_in(const Vec3<S>& v) { return v; }
  template <class S> static Vec3<S> pure_out(const Vec3<S>& b) { return b; }
};

constexpr const char* kClauses[] = {
    // Core
    "QUAT-2", "AXANG-1", "AXANG-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "APPLY-3", "MAT-1", "MAT-2",
    // Interp
    "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
    // Blend
    "QLB-1", "LOGBLEND-1", nullptr};

struct PaperLiteral : rotorcert::rotor::RotorOps<float, PrintedMethod2> {
  using S = float;
  static constexpr const char* name = "paper_literal";
  static constexpr const char* version = "2013";
  static constexpr const char* description =
      "Papagiannakis 2013 as printed: Method 2 map w + x e23 - y e13 + z e12, Appendix B interpolation (non-conforming)";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND;
  static constexpr const char* const* clauses = kClauses;

  /// Appendix B interpolateGA, line by line:
  ///   srcQ = normalize(Start); destQ = normalize(End);
  ///   srcMV = unit_e(srcQ.w + srcQ.x e1 + srcQ.y e2 + srcQ.z e3)   -- scalar + VECTOR
  ///   Rsrc, Rdest = printed Method 2 of srcQ, destQ
  ///   RtotQ = Rdest * inverse(Rsrc); RiQ = exp(Factor/2 * log(RtotQ))
  ///   RintQ = RiQ * srcMV * inverse(RiQ); Out = (scalar, e1, e2, e3) of RintQ.
  /// No hemisphere test. The sandwich fixes the scalar: Out.w = srcQ.w for every Factor.
  static Status slerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    using namespace rotorcert::rotor;
    if (!is_rotation(a) || !is_rotation(b) || !std::isfinite(t)) return Status::domain_error;
    const Quat<S> src = normalized(a), dst = normalized(b);
    const Quat<S> src_mv = normalized(src);  // unit_e: Euclidean norm of scalar + vector
    const Rotor3<S> rsrc = PrintedMethod2::in(src), rdest = PrintedMethod2::in(dst);
    const S n2 = dot(rsrc, rsrc);
    const Rotor3<S> rsrc_inv{rsrc.s / n2, -rsrc.e23 / n2, -rsrc.e31 / n2, -rsrc.e12 / n2};
    const Rotor3<S> rtot = gp(rdest, rsrc_inv);
    const Vec3<S> l = rotorcert::rotor::log(rtot);
    const Rotor3<S> ri = rotorcert::rotor::exp(Vec3<S>{t / 2 * l[0], t / 2 * l[1], t / 2 * l[2]});
    // RiQ (w + x) RiQ^-1 = w + RiQ x ~RiQ for the unit RiQ: the scalar commutes through.
    const Vec3<S> v = sandwich_vector(ri, Vec3<S>{src_mv[0], src_mv[1], src_mv[2]});
    out = {v[0], v[1], v[2], src_mv[3]};
    return Status::ok;
  }

  /// The rotor of the matrix in GA (R e_c ~R = column c, computed by rotor_from_matrix),
  /// read out with the printed map: the conjugate of the right quaternion (ERRATUM-2).
  static Status from_matrix(const Mat3<S>& m, Quat<S>& out) {
    const std::optional<Rotor3<S>> r = rotorcert::rotor::rotor_from_matrix(m);
    if (!r) return Status::domain_error;
    out = rotorcert::rotor::canonical_sign(PrintedMethod2::out(*r));
    return Status::ok;
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(paper_literal, PaperLiteral)

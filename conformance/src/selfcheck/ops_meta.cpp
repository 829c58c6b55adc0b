// Meta ops: layout (LAYOUT-1), error metrics (METRIC-*), verdicts and bars (TOL-*), storage
// orders of common libraries (QUAT-3).
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/tolerance.hpp>

#include "ops.hpp"

namespace rotorcert::conformance {

namespace clause = ref::clause;

namespace {

/// TOL-2: the (strict, loose) bars of a class in the unit of the error: eps classes N * eps of
/// the format (radians or length units), exact classes 0, absolute classes the value itself.
std::pair<Real, Real> bars_in_error_units(const spec::ToleranceClass& c, ref::Format f, const Inputs& in) {
  const auto strict = c.strict_value(), loose = c.loose_value();
  if (!strict || !loose)
    in.fail("class", "tolerance class \"" + c.name + "\" (kind \"" + c.kind + "\") has no numeric bars");
  if (c.kind == "eps") {
    const Real eps = ref::format_epsilon<Real>(f);
    return {*strict * eps, *loose * eps};
  }
  return {*strict, *loose};
}

Outputs layout(const Inputs& in) {
  const Quat q{in.scalar("w"), in.scalar("x"), in.scalar("y"), in.scalar("z")};
  return Outputs{}.quat("q", q);
}

Outputs distance(const Inputs& in) {
  return Outputs{}.scalar("theta", clause::METRIC_1_rotation_distance(in.quat("a"), in.quat("b")));
}

Outputs eps_units(const Inputs& in) {
  return Outputs{}.scalar("units", clause::METRIC_2_eps_units(in.scalar("err"), in.format("format")));
}

Outputs vector_error(const Inputs& in) {
  return Outputs{}.scalar("err", clause::METRIC_3_vector_error(in.vec3("v"), in.vec3("ref")));
}

Outputs matrix_error(const Inputs& in) {
  return Outputs{}.scalar("err", clause::METRIC_4_matrix_error(in.mat3("m"), in.mat3("ref")));
}

Outputs bivector_error(const Inputs& in) {
  return Outputs{}.scalar("err", clause::METRIC_5_bivector_error(in.vec3("b"), in.vec3("ref")));
}

Outputs norm_defect(const Inputs& in) { return Outputs{}.scalar("err", clause::METRIC_6_norm_defect(in.quat("q"))); }

Outputs rigid_error(const Inputs& in) {
  const auto e = clause::METRIC_7_rigid_error(in.dq("d"), in.dq("ref"));
  return Outputs{}.scalar("rot", e.rotation).scalar("trans", e.translation);
}

/// TOL-1: the error (radians or length units) against the class's bars for the format. The
/// comparison is done in MPFR on the bars in error units; the lead's TOL_1_verdict takes doubles
/// in the same unit, so both sides go through it after scaling to eps units where applicable.
Outputs verdict(const Inputs& in) {
  const spec::ToleranceClass& c = in.tolerance_class("class");
  const ref::Format f = in.format("format");
  const Real err = in.scalar("err");
  const auto strict = c.strict_value(), loose = c.loose_value();
  if (!strict || !loose)
    in.fail("class", "tolerance class \"" + c.name + "\" (kind \"" + c.kind + "\") gives no verdict");
  // eps classes: the bars are in eps units, so is the error; other classes: absolute units.
  const Real e = c.kind == "eps" ? clause::METRIC_2_eps_units(err, f) : err;
  const ref::Bars bars{strict->toDouble(), loose->toDouble()};
  return Outputs{}.text("verdict", ref::to_string(clause::TOL_1_verdict(e.toDouble(), bars)));
}

Outputs tolerance_bar(const Inputs& in) {
  const auto [strict, loose] = bars_in_error_units(in.tolerance_class("class"), in.format("format"), in);
  return Outputs{}.scalar("strict", strict).scalar("loose", loose);
}

/// QUAT-3: the memory order that each library's constructor (or convention) produces from
/// (w, x, y, z): GLM's glm::quat(w, x, y, z) and Eigen's Quaternion(w, x, y, z) store x, y, z, w;
/// glTF stores x, y, z, w; MATLAB's e(1..4) = w, x, y, z.
Outputs storage_order(const Inputs& in) {
  const std::string library = in.text("library");
  const Real w = in.scalar("w"), x = in.scalar("x"), y = in.scalar("y"), z = in.scalar("z");
  if (library == "glm_ctor" || library == "eigen_ctor" || library == "gltf") return Outputs{}.array("stored", {x, y, z, w});
  if (library == "matlab") return Outputs{}.array("stored", {w, x, y, z});
  in.fail("library", "expected \"glm_ctor\", \"eigen_ctor\", \"matlab\" or \"gltf\", found \"" + library + "\"");
}

}  // namespace

void register_meta_ops(OpTable& table) {
  table["layout"] = layout;
  table["distance"] = distance;
  table["eps_units"] = eps_units;
  table["vector_error"] = vector_error;
  table["matrix_error"] = matrix_error;
  table["bivector_error"] = bivector_error;
  table["norm_defect"] = norm_defect;
  table["rigid_error"] = rigid_error;
  table["verdict"] = verdict;
  table["tolerance_bar"] = tolerance_bar;
  table["storage_order"] = storage_order;
}

}  // namespace rotorcert::conformance

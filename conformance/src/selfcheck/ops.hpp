// The selfcheck dispatcher: op name (spec/examples.json, /tmp op table) -> handler that decodes
// the example's inputs into reference types, calls the reference clause function at the
// reference precision and returns its outputs in the example's field layout.
//
// Adding an op: write a handler in the ops_*.cpp file of its family and add it to that file's
// register function. Input decoding problems throw DecodeError, which fails the example (not
// the run).
#pragma once

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/reference/cl3.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/pga.hpp>
#include <rotorcert/reference/quaternion.hpp>
#include <rotorcert/reference/result.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::conformance {

using ref::Real;
using Quat = ref::Quaternion<Real>;
using V3 = ref::Vec3<Real>;
using M9 = ref::Mat3<Real>;
using DQ = ref::DualQuaternion<Real>;
using CL3 = ref::cl3::MV<Real>;
using PGA = ref::pga::MV<Real>;

/// An example whose fields do not fit its op; the message names the JSON path.
class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An exact expression (a JSON string) at `path`; DecodeError otherwise.
Real decode_expression(const nlohmann::json& j, const std::string& path);
/// A multivector object of `algebra` ("cl3" / "pga") as 2^n dense coefficients by bitmap.
std::vector<Real> decode_multivector(const nlohmann::json& j, const std::string& algebra, const std::string& path);
/// Canonical name of basis blade `bitmap` of `algebra` ("e13", "e023").
std::string blade_label(const std::string& algebra, std::size_t bitmap);

/// Typed access to an example's "in" object. Every number is an exact expression (expr.hpp).
class Inputs {
 public:
  Inputs(const nlohmann::json& in, std::string path, const spec::Spec* spec = nullptr)
      : in_(in), path_(std::move(path)), spec_(spec) {}

  Real scalar(const std::string& key) const;
  Quat quat(const std::string& key) const;    // [x, y, z, w]
  V3 vec3(const std::string& key) const;      // [x, y, z] or bivector [e23, e31, e12]
  M9 mat3(const std::string& key) const;      // 9, column-major
  DQ dq(const std::string& key) const;        // [real xyzw, dual xyzw]
  std::vector<Real> scalars(const std::string& key) const;
  std::vector<Quat> quats(const std::string& key) const;
  std::vector<V3> vec3s(const std::string& key) const;
  std::vector<DQ> dqs(const std::string& key) const;
  std::string text(const std::string& key) const;
  /// "cl3" or "pga" (the field "algebra").
  std::string algebra() const;
  /// A multivector object {"1": .., "e12": .., "e31": ..}; blade names in any index order.
  CL3 cl3(const std::string& key) const;
  PGA pga(const std::string& key) const;

  /// The tolerance class named by the string field `key`, from the spec being checked.
  const spec::ToleranceClass& tolerance_class(const std::string& key) const;
  /// The format named by `key`: "float" (binary32) or "double" (binary64).
  ref::Format format(const std::string& key) const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::json& field(const std::string& key) const;
  std::vector<Real> numbers(const nlohmann::json& j, const std::string& path, std::size_t n) const;

  const nlohmann::json& in_;
  std::string path_;
  const spec::Spec* spec_;
};

/// One output of the reference, in the layout of the example's "out" field.
struct Got {
  enum class Kind { scalar, array, multivector, text };
  Kind kind = Kind::scalar;
  std::vector<Real> values;  // scalar: 1; array: n; multivector: 2^n dense, by bitmap
  std::string algebra;       // multivector: "cl3" or "pga"
  std::string text;          // text
  bool sign_free = false;    // a rotation-like value: "compare":"rotation" accepts -value
};

struct Outputs {
  ref::Status status = ref::Status::ok;
  std::vector<std::pair<std::string, Got>> fields;

  Outputs& scalar(const std::string& name, const Real& x);
  Outputs& array(const std::string& name, std::vector<Real> x, bool sign_free = false);
  Outputs& quat(const std::string& name, const Quat& q) { return array(name, {q.x, q.y, q.z, q.w}, true); }
  Outputs& vec3(const std::string& name, const V3& v) { return array(name, {v[0], v[1], v[2]}); }
  Outputs& mat3(const std::string& name, const M9& m) { return array(name, {m.begin(), m.end()}); }
  Outputs& dq(const std::string& name, const DQ& d);
  Outputs& cl3(const std::string& name, const CL3& m);
  Outputs& pga(const std::string& name, const PGA& m);
  Outputs& text(const std::string& name, const std::string& s);
};

template <class V>
Outputs with_status(const ref::Result<V>& r) {
  Outputs o;
  o.status = r.status;
  return o;
}

using Handler = std::function<Outputs(const Inputs&)>;
using OpTable = std::map<std::string, Handler>;

// One register function per family of ops (ops_*.cpp).
void register_meta_ops(OpTable& table);      // layout, metrics, tolerances, storage orders
void register_algebra_ops(OpTable& table);   // generic multivector ops, quaternion <-> rotor, the paper
void register_rotation_ops(OpTable& table);  // rotation_ops.hpp
void register_rigid_ops(OpTable& table);     // rigid_ops.hpp, motor.hpp

/// All handlers.
const OpTable& op_table();

}  // namespace rotorcert::conformance

#include "ops.hpp"

#include <rotorcert/spec/expr.hpp>

namespace rotorcert::conformance {

using nlohmann::json;

namespace {

Real expression(const json& j, const std::string& path) {
  if (!j.is_string()) throw DecodeError(path + ": expected a string holding an exact expression, found " + j.dump());
  try {
    return spec::evaluate(j.get<std::string>());
  } catch (const spec::ExprError& e) {
    throw DecodeError(path + ": " + e.what());
  }
}

template <class A>
ref::Multivector<A, Real> multivector(const json& j, const std::string& path) {
  if (!j.is_object()) throw DecodeError(path + ": expected a multivector object {\"e12\": ..}, found " + j.dump());
  ref::Multivector<A, Real> m;
  for (const auto& [name, value] : j.items()) {
    ref::Multivector<A, Real> blade;
    try {
      blade = ref::blade_from_name<A, Real>(name);
    } catch (const std::exception& e) {
      throw DecodeError(path + "/" + name + ": " + e.what());
    }
    m = m + expression(value, path + "/" + name) * blade;
  }
  return m;
}

}  // namespace

Real decode_expression(const json& j, const std::string& path) { return expression(j, path); }

std::vector<Real> decode_multivector(const json& j, const std::string& algebra, const std::string& path) {
  if (algebra == "cl3") {
    const auto m = multivector<ref::Cl3>(j, path);
    return {m.c.begin(), m.c.end()};
  }
  if (algebra == "pga") {
    const auto m = multivector<ref::PGA3>(j, path);
    return {m.c.begin(), m.c.end()};
  }
  throw DecodeError(path + ": unknown algebra \"" + algebra + "\"");
}

std::string blade_label(const std::string& algebra, std::size_t bitmap) {
  return algebra == "pga" ? ref::PGA3::blade_name(ref::Bitmap(bitmap)) : ref::Cl3::blade_name(ref::Bitmap(bitmap));
}

void Inputs::fail(const std::string& key, const std::string& message) const {
  throw DecodeError(path_ + "/" + key + ": " + message);
}

const json& Inputs::field(const std::string& key) const {
  const auto it = in_.find(key);
  if (it == in_.end()) throw DecodeError(path_ + ": missing input \"" + key + "\"");
  return *it;
}

std::vector<Real> Inputs::numbers(const json& j, const std::string& path, std::size_t n) const {
  if (!j.is_array() || (n != 0 && j.size() != n))
    throw DecodeError(path + ": expected an array of " + (n ? std::to_string(n) + " " : "") + "expressions, found " + j.dump());
  std::vector<Real> r;
  for (std::size_t i = 0; i < j.size(); ++i) r.push_back(expression(j[i], path + "/" + std::to_string(i)));
  return r;
}

Real Inputs::scalar(const std::string& key) const { return expression(field(key), path_ + "/" + key); }

Quat Inputs::quat(const std::string& key) const {
  const auto v = numbers(field(key), path_ + "/" + key, 4);
  return Quat::from_xyzw({v[0], v[1], v[2], v[3]});
}

V3 Inputs::vec3(const std::string& key) const {
  const auto v = numbers(field(key), path_ + "/" + key, 3);
  return {v[0], v[1], v[2]};
}

M9 Inputs::mat3(const std::string& key) const {
  const auto v = numbers(field(key), path_ + "/" + key, 9);
  M9 m;
  for (int i = 0; i < 9; ++i) m[i] = v[i];
  return m;
}

namespace {
DQ dq_from(const std::vector<Real>& v) {
  return {Quat::from_xyzw({v[0], v[1], v[2], v[3]}), Quat::from_xyzw({v[4], v[5], v[6], v[7]})};
}
}  // namespace

DQ Inputs::dq(const std::string& key) const { return dq_from(numbers(field(key), path_ + "/" + key, 8)); }

std::vector<Real> Inputs::scalars(const std::string& key) const { return numbers(field(key), path_ + "/" + key, 0); }

namespace {
template <class F>
auto list_of(const json& j, const std::string& path, F element) {
  if (!j.is_array()) throw DecodeError(path + ": expected a list, found " + j.dump());
  std::vector<decltype(element(j, path))> r;
  for (std::size_t i = 0; i < j.size(); ++i) r.push_back(element(j[i], path + "/" + std::to_string(i)));
  return r;
}
}  // namespace

std::vector<Quat> Inputs::quats(const std::string& key) const {
  return list_of(field(key), path_ + "/" + key, [this](const json& e, const std::string& p) {
    const auto v = numbers(e, p, 4);
    return Quat::from_xyzw({v[0], v[1], v[2], v[3]});
  });
}

std::vector<V3> Inputs::vec3s(const std::string& key) const {
  return list_of(field(key), path_ + "/" + key, [this](const json& e, const std::string& p) {
    const auto v = numbers(e, p, 3);
    return V3{v[0], v[1], v[2]};
  });
}

std::vector<DQ> Inputs::dqs(const std::string& key) const {
  return list_of(field(key), path_ + "/" + key,
                 [this](const json& e, const std::string& p) { return dq_from(numbers(e, p, 8)); });
}

std::string Inputs::text(const std::string& key) const {
  const json& j = field(key);
  if (!j.is_string()) fail(key, "expected a string, found " + j.dump());
  return j.get<std::string>();
}

std::string Inputs::algebra() const {
  const std::string a = text("algebra");
  if (a != "cl3" && a != "pga") fail("algebra", "expected \"cl3\" or \"pga\", found \"" + a + "\"");
  return a;
}

const spec::ToleranceClass& Inputs::tolerance_class(const std::string& key) const {
  const std::string name = text(key);
  if (!spec_) fail(key, "no spec loaded to look up tolerance class \"" + name + "\"");
  const auto it = spec_->tolerance_classes.find(name);
  if (it == spec_->tolerance_classes.end()) fail(key, "no tolerance class \"" + name + "\" in clauses.json");
  return it->second;
}

ref::Format Inputs::format(const std::string& key) const {
  const std::string f = text(key);
  if (f == "float") return ref::Format::binary32;
  if (f == "double") return ref::Format::binary64;
  fail(key, "expected \"float\" or \"double\", found \"" + f + "\"");
}

CL3 Inputs::cl3(const std::string& key) const { return multivector<ref::Cl3>(field(key), path_ + "/" + key); }
PGA Inputs::pga(const std::string& key) const { return multivector<ref::PGA3>(field(key), path_ + "/" + key); }

// ---- outputs ------------------------------------------------------------------------------

Outputs& Outputs::scalar(const std::string& name, const Real& x) {
  Got g;
  g.kind = Got::Kind::scalar;
  g.values = {x};
  fields.emplace_back(name, std::move(g));
  return *this;
}

Outputs& Outputs::array(const std::string& name, std::vector<Real> x, bool sign_free) {
  Got g;
  g.kind = Got::Kind::array;
  g.values = std::move(x);
  g.sign_free = sign_free;
  fields.emplace_back(name, std::move(g));
  return *this;
}

Outputs& Outputs::dq(const std::string& name, const DQ& d) {
  return array(name, {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w}, true);
}

Outputs& Outputs::cl3(const std::string& name, const CL3& m) {
  Got g;
  g.kind = Got::Kind::multivector;
  g.values.assign(m.c.begin(), m.c.end());
  g.algebra = "cl3";
  g.sign_free = true;
  fields.emplace_back(name, std::move(g));
  return *this;
}

Outputs& Outputs::pga(const std::string& name, const PGA& m) {
  Got g;
  g.kind = Got::Kind::multivector;
  g.values.assign(m.c.begin(), m.c.end());
  g.algebra = "pga";
  g.sign_free = true;
  fields.emplace_back(name, std::move(g));
  return *this;
}

Outputs& Outputs::text(const std::string& name, const std::string& s) {
  Got g;
  g.kind = Got::Kind::text;
  g.text = s;
  fields.emplace_back(name, std::move(g));
  return *this;
}

const OpTable& op_table() {
  static const OpTable table = [] {
    OpTable t;
    register_meta_ops(t);
    register_algebra_ops(t);
    register_rotation_ops(t);
    register_rigid_ops(t);
    return t;
  }();
  return table;
}

}  // namespace rotorcert::conformance

// Generic multivector ops (ALG-1 .. ALG-7, EXPSERIES-1) and the Hamilton product (QUAT-1),
// straight from multivector.hpp, series.hpp, cl3.hpp and pga.hpp.
#include <rotorcert/reference/series.hpp>

#include "ops.hpp"

namespace rotorcert::conformance {

namespace {

template <class A> ref::Multivector<A, Real> read(const Inputs& in, const std::string& key);
template <> CL3 read<ref::Cl3>(const Inputs& in, const std::string& key) { return in.cl3(key); }
template <> PGA read<ref::PGA3>(const Inputs& in, const std::string& key) { return in.pga(key); }

Outputs put(const std::string& name, const CL3& m) { return Outputs{}.cl3(name, m); }
Outputs put(const std::string& name, const PGA& m) { return Outputs{}.pga(name, m); }

/// Calls f(algebra tag) with the algebra named by the example's "algebra" field.
template <class F>
Outputs with_algebra(const Inputs& in, F f) {
  if (in.algebra() == "cl3") return f(ref::Cl3{});
  return f(ref::PGA3{});
}

Outputs blade_square(const Inputs& in) {
  return with_algebra(in, [&](auto tag) {
    using A = decltype(tag);
    const std::string name = in.text("blade");
    ref::Multivector<A, Real> b;
    try {
      b = ref::blade_from_name<A, Real>(name);
    } catch (const std::invalid_argument& e) {
      in.fail("blade", e.what());
    }
    return Outputs{}.scalar("value", ref::gp(b, b).scalar());
  });
}

template <class Product>
Handler binary(Product product) {
  return [product](const Inputs& in) {
    return with_algebra(in, [&](auto tag) {
      using A = decltype(tag);
      return put("r", product(read<A>(in, "a"), read<A>(in, "b")));
    });
  };
}

Outputs reverse(const Inputs& in) {
  return with_algebra(in, [&](auto tag) { return put("r", ref::reverse(read<decltype(tag)>(in, "a"))); });
}

/// ALG-5: the dual of Cl(3,0) (A lc I^-1). PGA's dual is not a clause of the spec.
Outputs dual(const Inputs& in) {
  if (in.algebra() != "cl3") in.fail("algebra", "the dual (ALG-5) is defined for \"cl3\" only");
  return put("r", ref::cl3::dual(in.cl3("a")));
}

Outputs sandwich(const Inputs& in) {
  if (in.algebra() == "cl3") return put("r", ref::cl3::sandwich(in.cl3("R"), in.cl3("x")));
  return put("r", ref::pga::sandwich(in.pga("R"), in.pga("x")));
}

Outputs pga_point(const Inputs& in) { return put("r", ref::pga::point(in.vec3("p"))); }

Outputs exp_series(const Inputs& in) {
  return with_algebra(in, [&](auto tag) { return put("r", ref::exp_series(read<decltype(tag)>(in, "b"))); });
}

Outputs quat_mul(const Inputs& in) { return Outputs{}.quat("q", in.quat("a") * in.quat("b")); }

}  // namespace

void register_algebra_ops(OpTable& table) {
  table["blade_square"] = blade_square;
  table["gp"] = binary([](const auto& a, const auto& b) { return ref::gp(a, b); });
  table["op"] = binary([](const auto& a, const auto& b) { return ref::op(a, b); });
  table["lc"] = binary([](const auto& a, const auto& b) { return ref::lc(a, b); });
  table["reverse"] = reverse;
  table["dual"] = dual;
  table["sandwich"] = sandwich;
  table["pga_point"] = pga_point;
  table["exp_series"] = exp_series;
  table["quat_mul"] = quat_mul;
}

}  // namespace rotorcert::conformance

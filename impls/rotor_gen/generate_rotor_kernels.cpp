// generate_rotor_kernels: writes rotor_gen's kernels from the reference algebra, in the manner of
// Gaigen and Gaalop (run at build time; impls/rotor_gen/CMakeLists.txt).
//
// Nothing here knows a product table. A kernel is built by multiplying symbolic multivectors with
// the reference's own blade machinery (reference/include/rotorcert/reference/algebra.hpp and
// blade.hpp: bitmaps, reordering_sign, the metric, reverse_sign), so every sign comes from
// bitmaps and the metric of Cl(3,0,0) (ALG-1) or Cl(3,0,1) (ALG-7). A symbolic multivector holds,
// per basis blade bitmap, a polynomial with integer coefficients in named input components. Like
// terms are collected as they are added; terms that cancel, that the metric kills (e0^2 = 0) or that
// lie outside the grades of the operands never appear, and the result is projected onto the
// components the kernel returns. The components are named in the spec's bases (the cyclic e23,
// e31, e12 of ALG-1; klein's point basis e032, e013, e021, e123 in PGA), and a named blade such as
// e31 = e3 e1 = -e13 is itself a product of basis vectors, so the sign of each name is derived too.
//
// Usage: generate_rotor_kernels OUT.hpp OUT.json
//   OUT.hpp   the kernels (inline templates), a header comment with each kernel's operation
//             count, and the same counts as a constexpr table;
//   OUT.json  the operation counts as data (kernels, and the fast path of each ABI op of
//             rotor_gen as the sum of the kernels it calls and its own divisions and roots).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <rotorcert/reference/algebra.hpp>
#include <rotorcert/reference/blade.hpp>

namespace {

using rotorcert::ref::Bitmap;
using rotorcert::ref::grade_of;
using rotorcert::ref::reverse_sign;

// ---- symbolic polynomials -----------------------------------------------------------------------

/// A monomial: the names of its factors, sorted (a product of input components; empty = 1).
using Monomial = std::vector<std::string>;
/// A polynomial: monomial -> integer coefficient, zero coefficients never stored.
using Poly = std::map<Monomial, long>;

void add_term(Poly& p, const Monomial& m, long c) {
  if (c == 0) return;
  const long sum = (p[m] += c);
  if (sum == 0) p.erase(m);
}
Poly operator*(const Poly& a, const Poly& b) {
  Poly r;
  for (const auto& [ma, ca] : a)
    for (const auto& [mb, cb] : b) {
      Monomial m = ma;
      m.insert(m.end(), mb.begin(), mb.end());
      std::sort(m.begin(), m.end());
      add_term(r, m, ca * cb);
    }
  return r;
}
Poly scaled(const Poly& a, long k) {
  Poly r;
  for (const auto& [m, c] : a) add_term(r, m, c * k);
  return r;
}
Poly variable(const std::string& name) { return Poly{{Monomial{name}, 1}}; }
Poly constant(long c) {
  Poly r;
  add_term(r, Monomial{}, c);
  return r;
}

/// Arithmetic operations of straight-line code. Negations are free (they fold into a subtraction
/// or a sign bit) and are not counted.
struct OpCount {
  int mul = 0, add = 0, div = 0, sqrt = 0;
  OpCount& operator+=(const OpCount& o) {
    mul += o.mul, add += o.add, div += o.div, sqrt += o.sqrt;
    return *this;
  }
  int total() const { return mul + add + div + sqrt; }
};

/// The C++ expression of a polynomial (positive terms first, so only a polynomial whose every term
/// is negative starts with a unary minus) and what it costs: one multiplication per factor after
/// the first and one for a coefficient other than +-1, one addition per term after the first.
std::string emit(const Poly& p, OpCount& count) {
  if (p.empty()) return "S(0)";
  std::vector<std::pair<Monomial, long>> terms(p.begin(), p.end());
  std::stable_partition(terms.begin(), terms.end(), [](const auto& t) { return t.second > 0; });
  std::string out;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const auto& [m, c] = terms[i];
    const long mag = std::labs(c);
    std::string factor;
    int muls = m.empty() ? 0 : int(m.size()) - 1;
    if (mag != 1 || m.empty()) {
      factor = "S(" + std::to_string(mag) + ")";
      if (!m.empty()) ++muls;
    }
    for (const std::string& v : m) factor += (factor.empty() ? "" : " * ") + v;
    if (i == 0) out = (c < 0 ? "-" : "") + factor;
    else out += (c < 0 ? " - " : " + ") + factor;
    count.mul += muls;
    if (i > 0) ++count.add;
  }
  return out;
}

// ---- symbolic multivectors of an algebra --------------------------------------------------------

template <class A>
struct Symbolic {
  std::vector<Poly> c = std::vector<Poly>(A::size);  // c[bitmap]
};

/// A named basis blade ("" the scalar, "23", "31", "032", ...: printed vector indices) as sign * bitmap: the
/// product of its basis vectors, each step signed by reordering and the metric (like the
/// reference's blade_from_name). Repeated vectors are not used in names.
template <class A>
std::pair<int, Bitmap> named_blade(const std::string& indices) {
  int sign = 1;
  Bitmap b = 0;
  for (char ch : indices) {
    const int k = A::vector_from_index(ch - '0');
    if (k < 0) throw std::runtime_error("no basis vector e" + std::string(1, ch));
    const Bitmap v = Bitmap(1) << k;
    sign *= A::product_sign(b, v);
    b ^= v;
  }
  if (sign == 0) throw std::runtime_error("blade e" + indices + " is zero");
  return {sign, b};
}

/// One component of a kernel's argument or result: a C++ name and the blade it multiplies.
struct Component {
  std::string field;   // e.g. "e31"
  std::string blade;   // printed indices, e.g. "31"; "" is the scalar
};

/// The multivector sum_k prefix.field_k * blade_k; a component whose field is a number is that
/// constant (a point's weight 1, a direction's 0).
template <class A>
Symbolic<A> argument(const std::string& prefix, const std::vector<Component>& comps) {
  Symbolic<A> x;
  for (const Component& k : comps) {
    const auto [sign, b] = named_blade<A>(k.blade);
    const bool is_constant = !k.field.empty() && (std::isdigit(static_cast<unsigned char>(k.field[0])) != 0);
    const Poly value = is_constant ? constant(std::stol(k.field)) : variable(prefix + k.field);
    for (const auto& [m, c] : value) add_term(x.c[b], m, c * sign);
  }
  return x;
}

/// Coefficient of a named blade: sign * c[bitmap] (the sign is +-1, its own inverse).
template <class A>
Poly coefficient(const Symbolic<A>& x, const std::string& blade) {
  const auto [sign, b] = named_blade<A>(blade);
  return scaled(x.c[b], sign);
}

/// Geometric product, the bilinear extension of the product of basis blades (ALG-2):
/// e_a e_b = reordering_sign(a, b) * metric_factor(a, b) * e_(a xor b).
template <class A>
Symbolic<A> gp(const Symbolic<A>& x, const Symbolic<A>& y) {
  Symbolic<A> r;
  for (Bitmap a = 0; a < Bitmap(A::size); ++a) {
    if (x.c[a].empty()) continue;
    for (Bitmap b = 0; b < Bitmap(A::size); ++b) {
      if (y.c[b].empty()) continue;
      const int sign = A::product_sign(a, b);
      if (sign == 0) continue;  // the metric kills it (e0 e0 = 0)
      for (const auto& [m, c] : x.c[a] * y.c[b]) add_term(r.c[a ^ b], m, c * sign);
    }
  }
  return r;
}

/// Reverse (ALG-4): a grade-k blade times (-1)^(k(k-1)/2).
template <class A>
Symbolic<A> reverse(const Symbolic<A>& x) {
  Symbolic<A> r;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b) r.c[b] = scaled(x.c[b], reverse_sign(grade_of(b)));
  return r;
}

/// Nonzero components outside `keep` (a kernel that drops them would be wrong, not smaller).
template <class A>
std::vector<std::string> stray_blades(const Symbolic<A>& x, const std::vector<Component>& keep) {
  std::vector<bool> kept(A::size, false);
  for (const Component& k : keep) kept[named_blade<A>(k.blade).second] = true;
  std::vector<std::string> stray;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b)
    if (!kept[b] && !x.c[b].empty()) stray.push_back(A::blade_name(b));
  return stray;
}

// ---- kernels ------------------------------------------------------------------------------------

struct Kernel {
  std::string name, signature, body, doc;
  OpCount count;
};

/// Returns `result_type{...}` of the named components of x.
template <class A>
std::string return_components(const Symbolic<A>& x, const std::vector<Component>& comps, const std::string& type,
                              OpCount& count) {
  std::string s = "  return " + type + "{";
  for (std::size_t i = 0; i < comps.size(); ++i) {
    s += (i ? ",\n      " : "\n      ") + emit(coefficient(x, comps[i].blade), count);
  }
  return s + "};\n";
}

/// The scalar part of x as an S.
template <class A>
std::string return_scalar(const Symbolic<A>& x, OpCount& count) {
  return "  return " + emit(x.c[0], count) + ";\n";
}

/// The sandwich X Y ~X projected to `out` (ALG-6, not divided by X ~X), written both ways:
///   expanded: every output a polynomial in the components of X and Y, like terms collected;
///   two-step: T = X Y into temporaries (its nonzero components only), then <T ~X>.
/// The cheaper by operation count is emitted; `report` says which and both counts.
template <class A>
std::string sandwich_body(const Symbolic<A>& x, const Symbolic<A>& y, const std::vector<Component>& out,
                          const std::string& type, OpCount& count, std::string& report) {
  const Symbolic<A> rev = reverse(x);
  OpCount expanded;
  const Symbolic<A> full = gp(gp(x, y), rev);
  const std::string expanded_body = return_components(full, out, type, expanded);

  OpCount two_step;
  const Symbolic<A> t = gp(x, y);
  std::string two_step_body;
  Symbolic<A> t_named;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b) {
    if (t.c[b].empty()) continue;
    const std::string name = "t_" + A::blade_name(b);
    two_step_body += "  const S " + name + " = " + emit(t.c[b], two_step) + ";\n";
    t_named.c[b] = variable(name);
  }
  two_step_body += return_components(gp(t_named, rev), out, type, two_step);

  const bool pick_expanded = expanded.total() <= two_step.total();
  std::ostringstream r;
  r << "expanded " << expanded.mul << " mul + " << expanded.add << " add, two-step " << two_step.mul << " mul + "
    << two_step.add << " add: " << (pick_expanded ? "expanded" : "two-step") << " emitted";
  report = r.str();
  count = pick_expanded ? expanded : two_step;
  return pick_expanded ? expanded_body : two_step_body;
}

std::string counts_comment(const OpCount& c) {
  std::ostringstream s;
  s << c.mul << " mul, " << c.add << " add/sub";
  if (c.div) s << ", " << c.div << " div";
  if (c.sqrt) s << ", " << c.sqrt << " sqrt";
  return s.str();
}

// The layouts, in the spec's names. Cl(3,0): even subalgebra s + e23 e23 + e31 e31 + e12 e12 (ALG-1,
// Rotor3's order), vectors e1, e2, e3. PGA Cl(3,0,1): motors in MOTOR-1's order, points in klein's
// basis x e032 + y e013 + z e021 + w e123 (reference/pga.hpp).
const std::vector<Component> kEven3 = {{"s", ""}, {"e23", "23"}, {"e31", "31"}, {"e12", "12"}};
const std::vector<Component> kVector3 = {{"e1", "1"}, {"e2", "2"}, {"e3", "3"}};
const std::vector<Component> kMotor = {{"s", ""},    {"e23", "23"}, {"e31", "31"}, {"e12", "12"},
                                       {"e01", "01"}, {"e02", "02"}, {"e03", "03"}, {"e0123", "0123"}};
const std::vector<Component> kPoint = {{"x", "032"}, {"y", "013"}, {"z", "021"}, {"w", "123"}};
std::vector<Component> with_weight(std::vector<Component> p, const char* w) {
  p.back().field = w;
  return p;
}

std::vector<Kernel> cl3_kernels(std::string& apply_report) {
  using A = rotorcert::ref::Cl3;
  std::vector<Kernel> k;
  const Symbolic<A> a = argument<A>("a.", kEven3), b = argument<A>("b.", kEven3), v = argument<A>("v.", kVector3);
  OpCount c;
  if (!stray_blades(gp(a, b), kEven3).empty()) throw std::runtime_error("even * even left the even subalgebra");
  std::string body = return_components(gp(a, b), kEven3, "Cl3Even<S>", c);
  k.push_back({"cl3_gp", "Cl3Even<S> cl3_gp(const Cl3Even<S>& a, const Cl3Even<S>& b)", body,
               "Geometric product a b of two even elements (ALG-2).", c});
  c = {};
  body = return_components(reverse(a), kEven3, "Cl3Even<S>", c);
  k.push_back({"cl3_reverse", "Cl3Even<S> cl3_reverse(const Cl3Even<S>& a)", body, "Reverse ~a (ALG-4).", c});
  c = {};
  body = return_scalar(gp(a, reverse(a)), c);
  k.push_back({"cl3_norm2", "S cl3_norm2(const Cl3Even<S>& a)", body, "<a ~a>_0, the squared norm.", c});
  c = {};
  body = return_scalar(gp(a, reverse(b)), c);
  k.push_back({"cl3_scalar_product", "S cl3_scalar_product(const Cl3Even<S>& a, const Cl3Even<S>& b)", body,
               "<a ~b>_0 (equal to the quaternion dot product under Phi, SLERP-2).", c});
  c = {};
  if (const auto stray = stray_blades(gp(gp(a, v), reverse(a)), kVector3); !stray.empty())
    throw std::runtime_error("a v ~a has a part outside grade 1: " + stray[0]);
  body = sandwich_body(a, v, kVector3, "Cl3Vector<S>", c, apply_report);
  k.push_back({"cl3_sandwich_vector", "Cl3Vector<S> cl3_sandwich_vector(const Cl3Even<S>& a, const Cl3Vector<S>& v)",
               body, "<a v ~a>_1, not divided by a ~a (ALG-6; " + apply_report + ").", c});
  return k;
}

std::vector<Kernel> pga_kernels(std::string& point_report, std::string& direction_report) {
  using A = rotorcert::ref::PGA3;
  std::vector<Kernel> k;
  const Symbolic<A> a = argument<A>("a.", kMotor), b = argument<A>("b.", kMotor);
  OpCount c;
  std::string body = return_components(gp(a, b), kMotor, "PgaMotor<S>", c);
  if (!stray_blades(gp(a, b), kMotor).empty()) throw std::runtime_error("motor * motor left the motors");
  k.push_back({"pga_gp", "PgaMotor<S> pga_gp(const PgaMotor<S>& a, const PgaMotor<S>& b)", body,
               "Geometric product a b of two motors (ALG-7).", c});
  c = {};
  body = return_components(reverse(a), kMotor, "PgaMotor<S>", c);
  k.push_back({"pga_reverse", "PgaMotor<S> pga_reverse(const PgaMotor<S>& a)", body, "Reverse ~a.", c});
  c = {};
  body = return_scalar(gp(a, reverse(a)), c);
  k.push_back({"pga_norm2", "S pga_norm2(const PgaMotor<S>& a)", body,
               "<a ~a>_0: the e0 terms vanish (e0^2 = 0), only the rotor part remains.", c});
  c = {};
  const Symbolic<A> p = argument<A>("p.", kPoint);
  if (!stray_blades(gp(gp(a, p), reverse(a)), kPoint).empty())
    throw std::runtime_error("a p ~a has a part outside grade 3");
  body = sandwich_body(a, p, kPoint, "PgaPoint<S>", c, point_report);
  k.push_back({"pga_sandwich", "PgaPoint<S> pga_sandwich(const PgaMotor<S>& a, const PgaPoint<S>& p)", body,
               "<a p ~a>_3 of a weighted point (any w), not divided by a ~a (" + point_report + ").", c});
  c = {};
  const Symbolic<A> pt = argument<A>("p.", with_weight(kPoint, "1"));
  body = sandwich_body(a, pt, kPoint, "PgaPoint<S>", c, point_report);
  k.push_back({"pga_sandwich_point", "PgaPoint<S> pga_sandwich_point(const PgaMotor<S>& a, const PgaPoint<S>& p)",
               body, "<a p ~a>_3 of the point p with w = 1 (p.w is not read) (" + point_report + ").", c});
  c = {};
  const Symbolic<A> d = argument<A>("p.", with_weight(kPoint, "0"));
  body = sandwich_body(a, d, kPoint, "PgaPoint<S>", c, direction_report);
  k.push_back({"pga_sandwich_direction",
               "PgaPoint<S> pga_sandwich_direction(const PgaMotor<S>& a, const PgaPoint<S>& p)", body,
               "<a p ~a>_3 of the direction p with w = 0 (p.w is not read): translations drop out (" +
                   direction_report + ").",
               c});
  return k;
}

/// The fast path of each hot ABI op of rotor_gen (impls/rotor_gen/rotor_gen.cpp): the kernels it
/// calls and its own divisions, roots and elementwise arithmetic (the guards' comparisons and the
/// library calls atan2 / sincos not counted).
struct AbiOp {
  std::string op;
  std::vector<std::string> kernels;
  OpCount own;
  std::string note;
};
// Own arithmetic, as rotor_gen.cpp writes it: "R k" is 4 mul; the hemisphere bound
// 16u (|a| |b|) + 8 denorm_min is 2 mul + 1 add; |B|^2 of a rotor is 3 mul + 2 add.
const std::vector<AbiOp> kAbiOps = {
    {"normalize", {"cl3_norm2"}, {4, 0, 1, 1}, "R (1 / sqrt(<R ~R>_0))"},
    {"compose", {"cl3_norm2", "cl3_norm2", "cl3_gp"}, {}, "Phi(a) Phi(b); the two norms are the guard"},
    // |v|^2 (3 mul + 2 add), 1 / <R ~R>_0 and three products.
    {"apply_vector", {"cl3_norm2", "cl3_sandwich_vector"}, {3 + 3, 2, 1, 0}, "<R v ~R>_1 (1 / <R ~R>_0)"},
    // R_A, R_B scaled (8 mul, 2 div, 2 sqrt), bound (2 mul + 1 add), R_A + t (R_B' - R_A) (4 mul + 8 add),
    // scaled by 1 / sqrt of its norm (4 mul, 1 div, 1 sqrt).
    {"nlerp", {"cl3_norm2", "cl3_norm2", "cl3_scalar_product", "cl3_norm2"}, {8 + 2 + 4 + 4, 1 + 8, 3, 3},
     "R_A/|R_A| + t (R_B'/|R_B| - R_A/|R_A|), normalised"},
    // R_A, R_B scaled (8 mul, 2 div, 2 sqrt), bound (2 mul + 1 add), |B|^2 of D (3 mul + 2 add), B/|B|
    // (3 mul, 1 div, 1 sqrt), |B|/s (1 div), t theta (1 mul), sin(t theta) B/|B| (3 mul); atan and
    // sincos are library calls, not counted.
    {"slerp",
     {"cl3_norm2", "cl3_norm2", "cl3_scalar_product", "cl3_gp", "cl3_gp"},
     {8 + 2 + 3 + 3 + 1 + 3, 1 + 2, 4, 3},
     "D = R_B' ~R_A, theta = atan(|B|/s), (cos(t theta) + sin(t theta) B/|B|) R_A; plus atan and sincos calls"},
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s OUT.hpp OUT.json\n", argv[0]);
    return 2;
  }
  try {
    std::string apply_report, point_report, direction_report;
    std::vector<Kernel> kernels = cl3_kernels(apply_report);
    for (Kernel& k : pga_kernels(point_report, direction_report)) kernels.push_back(std::move(k));

    std::ostringstream h;
    h << "// GENERATED by impls/rotor_gen/generate_rotor_kernels.cpp at build time. Do not edit.\n"
         "// From the reference algebra's blade tables (reference/include/rotorcert/reference/algebra.hpp,\n"
         "// blade.hpp): the even subalgebra of Cl(3,0,0) (ALG-1) and the motors of PGA Cl(3,0,1) (ALG-7),\n"
         "// products expanded symbolically, like terms collected, zero terms dropped.\n//\n"
         "// Operation counts per kernel (negations free):\n";
    for (const Kernel& k : kernels) h << "//   " << k.name << ": " << counts_comment(k.count) << "\n";
    h << "// cl3_sandwich_vector: " << apply_report << ".\n";
    h << "// pga_sandwich_point: " << point_report << ".\n";
    h << "// pga_sandwich_direction: " << direction_report << ".\n";
    h << "#pragma once\n\nnamespace rotorcert::rotor_gen {\n\n"
         "/// s + e23 e2e3 + e31 e3e1 + e12 e1e2: the even subalgebra of Cl(3,0), bivectors in the cyclic basis of\n"
         "/// ALG-1 (e31 = e3e1 = -e13); the layout of impls/rotor/rotor3.hpp's Rotor3.\n"
         "template <class S> struct Cl3Even { S s, e23, e31, e12; };\n"
         "/// e1 e1 + e2 e2 + e3 e3.\n"
         "template <class S> struct Cl3Vector { S e1, e2, e3; };\n"
         "/// A PGA motor in MOTOR-1's order:\n"
         "/// s + e23 e23 + e31 e31 + e12 e12 + e01 e01 + e02 e02 + e03 e03 + e0123 e0123.\n"
         "template <class S> struct PgaMotor { S s, e23, e31, e12, e01, e02, e03, e0123; };\n"
         "/// x e032 + y e013 + z e021 + w e123: a point (w = 1) or direction (w = 0), klein's basis.\n"
         "template <class S> struct PgaPoint { S x, y, z, w; };\n\n";
    for (const Kernel& k : kernels)
      h << "/// " << k.doc << "\n/// " << counts_comment(k.count) << ".\ntemplate <class S>\ninline " << k.signature
        << " {\n" << k.body << "}\n\n";
    h << "/// Operation counts of the kernels above (the same numbers as their comments).\n"
         "struct OpCount {\n  const char* kernel;\n  int mul, add, div, sqrt;\n};\n"
         "inline constexpr OpCount kKernelOpCounts[] = {\n";
    for (const Kernel& k : kernels)
      h << "    {\"" << k.name << "\", " << k.count.mul << ", " << k.count.add << ", " << k.count.div << ", "
        << k.count.sqrt << "},\n";
    h << "};\n\n";

    std::ostringstream j;
    j << "{\n  \"generator\": \"impls/rotor_gen/generate_rotor_kernels.cpp\",\n  \"sandwich_vector_form\": \""
      << apply_report << "\",\n  \"kernels\": {\n";
    for (std::size_t i = 0; i < kernels.size(); ++i) {
      const OpCount& c = kernels[i].count;
      j << "    \"" << kernels[i].name << "\": {\"mul\": " << c.mul << ", \"add\": " << c.add << ", \"div\": " << c.div
        << ", \"sqrt\": " << c.sqrt << "}" << (i + 1 < kernels.size() ? "," : "") << "\n";
    }
    j << "  },\n  \"ops\": {\n";
    h << "/// The fast path of each hot ABI op of rotor_gen: its kernels plus its own arithmetic.\n"
         "inline constexpr OpCount kAbiOpCounts[] = {\n";
    for (std::size_t i = 0; i < kAbiOps.size(); ++i) {
      const AbiOp& op = kAbiOps[i];
      OpCount c = op.own;
      for (const std::string& name : op.kernels) {
        const auto it = std::find_if(kernels.begin(), kernels.end(), [&](const Kernel& k) { return k.name == name; });
        if (it == kernels.end()) throw std::runtime_error("no kernel " + name);
        c += it->count;
      }
      h << "    {\"" << op.op << "\", " << c.mul << ", " << c.add << ", " << c.div << ", " << c.sqrt << "},  // "
        << op.note << "\n";
      j << "    \"" << op.op << "\": {\"mul\": " << c.mul << ", \"add\": " << c.add << ", \"div\": " << c.div
        << ", \"sqrt\": " << c.sqrt << ", \"how\": \"" << op.note << "\"}" << (i + 1 < kAbiOps.size() ? "," : "")
        << "\n";
    }
    h << "};\n\n}  // namespace rotorcert::rotor_gen\n";
    j << "  }\n}\n";

    std::ofstream(argv[1]) << h.str();
    std::ofstream(argv[2]) << j.str();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_rotor_kernels: %s\n", e.what());
    return 1;
  }
  return 0;
}

// The exact-expression evaluator of the worked examples (conformance/src/spec/expr.cpp).
#include <cmath>
#include <limits>
#include <string>

// expr.hpp brings in <mpreal.h>, which must come before any direct <mpfr.h>.
#include <rotorcert/spec/expr.hpp>

#include <gtest/gtest.h>

namespace {

using rotorcert::ref::Real;
using rotorcert::spec::evaluate;
using rotorcert::spec::ExprError;
using rotorcert::spec::parse_hexfloat;

Real pow2(long e) {
  Real x(1);
  mpfr_mul_2si(x.mpfr_ptr(), x.mpfr_srcptr(), e, MPFR_RNDN);
  return x;
}

bool is_negative_zero(const Real& x) { return mpfr::iszero(x) && mpfr_signbit(x.mpfr_srcptr()) != 0; }

TEST(Expr, DecimalNumbers) {
  EXPECT_EQ(evaluate("3"), Real(3));
  EXPECT_EQ(evaluate("0.25"), Real(0.25));
  EXPECT_EQ(evaluate(".5"), Real(0.5));
  EXPECT_EQ(evaluate("1e3"), Real(1000));
  EXPECT_EQ(evaluate("2.5E-1"), Real(0.25));
  // 0.1 is rounded once at the working precision, not converted through a double.
  Real tenth;
  mpfr_set_str(tenth.mpfr_ptr(), "0.1", 10, MPFR_RNDN);
  EXPECT_EQ(evaluate("0.1"), tenth);
  EXPECT_NE(evaluate("0.1"), Real(0.1));
}

TEST(Expr, HexfloatIsExact) {
  EXPECT_EQ(evaluate("0x1.8p-3"), Real(0.1875));
  EXPECT_EQ(evaluate("0x1p0"), Real(1));
  EXPECT_EQ(evaluate("0X1.0P+4"), Real(16));
  EXPECT_EQ(evaluate("0x10"), Real(16));  // no exponent: an integer
  EXPECT_EQ(evaluate("0x.8p1"), Real(1));
  EXPECT_EQ(evaluate("0x1.fffffffffffffp+1023"), Real(std::numeric_limits<double>::max()));
  EXPECT_EQ(evaluate("0x1.fffffep+127"), Real(double(std::numeric_limits<float>::max())));
  // The smallest subnormals: exact, with the sign.
  EXPECT_EQ(evaluate("0x1p-1074"), pow2(-1074));
  EXPECT_EQ(evaluate("0x1p-1074"), Real(std::ldexp(1.0, -1074)));
  EXPECT_EQ(evaluate("-0x1p-1074"), -pow2(-1074));
  EXPECT_EQ(evaluate("0x1p-149"), pow2(-149));
  // Outside double's range (strtod would give 0 or inf): still exact.
  EXPECT_EQ(evaluate("0x1p-1100"), pow2(-1100));
  EXPECT_EQ(evaluate("0x1.8p+2000"), Real(3) * pow2(1999));
  // A significand of more than 53 bits is kept whole (here 61 bits).
  EXPECT_EQ(evaluate("0x1.000000000000001p0"), Real(1) + pow2(-60));
  EXPECT_EQ(parse_hexfloat("0x1.8p-3"), Real(0.1875));
}

TEST(Expr, SpecialValuesKeepTheirSign) {
  EXPECT_TRUE(mpfr::isnan(evaluate("nan")));
  EXPECT_TRUE(mpfr::isinf(evaluate("inf")));
  EXPECT_GT(evaluate("inf"), Real(0));
  EXPECT_TRUE(mpfr::isinf(evaluate("-inf")));
  EXPECT_LT(evaluate("-inf"), Real(0));
  EXPECT_TRUE(is_negative_zero(evaluate("-0")));
  EXPECT_TRUE(is_negative_zero(evaluate("-0x0p0")));
  EXPECT_TRUE(is_negative_zero(evaluate("-0.0")));
  EXPECT_FALSE(is_negative_zero(evaluate("0")));
  EXPECT_TRUE(mpfr::iszero(evaluate("0")));
}

TEST(Expr, PrecedenceAndAssociativity) {
  EXPECT_EQ(evaluate("1 + 2 * 3"), Real(7));
  EXPECT_EQ(evaluate("(1 + 2) * 3"), Real(9));
  EXPECT_EQ(evaluate("8 / 4 / 2"), Real(1));       // left-associative
  EXPECT_EQ(evaluate("10 - 4 - 3"), Real(3));      // left-associative
  EXPECT_EQ(evaluate("2 ^ 3 ^ 2"), Real(512));     // right-associative: 2^(3^2)
  EXPECT_EQ(evaluate("-2 ^ 2"), Real(-4));         // ^ binds tighter than unary minus
  EXPECT_EQ(evaluate("2 ^ -1"), Real(0.5));
  EXPECT_EQ(evaluate("2^-1074"), pow2(-1074));
  EXPECT_EQ(evaluate("--3"), Real(3));
  EXPECT_EQ(evaluate("+3"), Real(3));
  EXPECT_EQ(evaluate("3/5 * 5"), Real(3) / Real(5) * Real(5));
  EXPECT_EQ(evaluate(" 1+ ( 2 ) "), Real(3));
}

TEST(Expr, ConstantsAndFunctions) {
  EXPECT_EQ(evaluate("pi"), mpfr::const_pi());
  EXPECT_EQ(evaluate("pi/2"), mpfr::const_pi() / 2);
  EXPECT_EQ(evaluate("sqrt(2)/2"), mpfr::sqrt(Real(2)) / 2);
  EXPECT_EQ(evaluate("sin(pi/6)"), mpfr::sin(mpfr::const_pi() / 6));
  EXPECT_EQ(evaluate("cos(1)"), mpfr::cos(Real(1)));
  EXPECT_EQ(evaluate("tan(1)"), mpfr::tan(Real(1)));
  EXPECT_EQ(evaluate("asin(1)"), mpfr::const_pi() / 2);
  EXPECT_EQ(evaluate("acos(0)"), mpfr::const_pi() / 2);
  EXPECT_EQ(evaluate("atan(1)"), mpfr::const_pi() / 4);
  EXPECT_EQ(evaluate("atan2(1, -1)"), mpfr::atan2(Real(1), Real(-1)));
  EXPECT_EQ(evaluate("exp(0)"), Real(1));
  EXPECT_EQ(evaluate("log(exp(2))"), mpfr::log(mpfr::exp(Real(2))));
  EXPECT_EQ(evaluate("abs(-3)"), Real(3));
  EXPECT_EQ(evaluate("2*cos(pi/8)^2"), 2 * mpfr::pow(mpfr::cos(mpfr::const_pi() / 8), 2));
  // Evaluated at the reference precision: sqrt(2)^2 - 2 is far below double's resolution.
  EXPECT_LT(mpfr::abs(evaluate("sqrt(2)^2 - 2")), Real(1e-70));
}

/// The error names the position (1-based in the message, 0-based in position()).
void expect_error(const std::string& text, std::size_t position, const std::string& fragment) {
  try {
    (void)evaluate(text);
    ADD_FAILURE() << "'" << text << "' evaluated without error";
  } catch (const ExprError& e) {
    EXPECT_EQ(e.position(), position) << text << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'" + text + "'"), std::string::npos) << e.what();
  }
}

TEST(Expr, ErrorsNameThePosition) {
  expect_error("", 0, "before the end");
  expect_error("1 +", 3, "before the end");
  expect_error("(1 + 2", 6, "expected ')'");
  expect_error("1 2", 2, "unexpected '2'");
  expect_error("foo(1)", 0, "unknown name 'foo'");
  expect_error("sqrt 2", 5, "expected '('");
  expect_error("atan2(1)", 0, "takes 2 argument(s)");
  expect_error("sin(1, 2)", 0, "takes 1 argument(s)");
  expect_error("0x", 2, "without digits");
  expect_error("0x1p", 4, "exponent");
  expect_error("1e", 2, "exponent");
  expect_error("2 # 3", 2, "unexpected '#'");
  expect_error("NaN", 0, "unknown name 'NaN'");
  expect_error("1 + * 2", 4, "unexpected '*'");
}

}  // namespace

#include <rotorcert/spec/expr.hpp>

#include <algorithm>
#include <cctype>
#include <limits>
#include <vector>

#include <mpfr.h>

namespace rotorcert::spec {

using ref::Real;

namespace {

std::string describe(const std::string& text, std::size_t position, const std::string& message) {
  return "expression error at position " + std::to_string(position + 1) + " in '" + text + "': " + message;
}

bool is_hex_digit(char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

Real nan_value() { return ref::ScalarTraits<Real>::nan(); }
Real inf_value() {
  Real x;
  mpfr_set_inf(x.mpfr_ptr(), +1);
  return x;
}

/// Hexfloat without sign. `error(offset, message)` reports an error at an offset into `text`.
template <class Error>
Real hexfloat(std::string_view text, Error error) {
  if (text.size() < 2 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X')) error(0, "expected '0x'");
  std::size_t i = 2;
  std::string digits;
  long fraction_digits = 0;
  while (i < text.size() && is_hex_digit(text[i])) digits += text[i++];
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_hex_digit(text[i])) {
      digits += text[i++];
      ++fraction_digits;
    }
  }
  if (digits.empty()) error(i, "hexadecimal literal without digits");
  long exponent = 0;
  if (i < text.size() && (text[i] == 'p' || text[i] == 'P')) {
    ++i;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    if (i >= text.size() || !is_digit(text[i])) error(i, "expected the binary exponent's digits after 'p'");
    while (i < text.size() && is_digit(text[i])) {
      exponent = exponent * 10 + (text[i++] - '0');
      if (exponent > 1000000000L) error(i, "binary exponent out of range");
    }
    if (negative) exponent = -exponent;
  }
  if (i != text.size()) error(i, "unexpected character in hexadecimal literal");

  // The significand as an integer, held exactly (4 bits per digit), then scaled by a power of
  // two (exact), then rounded once to the working precision.
  const mpfr_prec_t bits = std::max<mpfr_prec_t>(64, mpfr_prec_t(4 * digits.size() + 8));
  mpfr_t exact;
  mpfr_init2(exact, bits);
  mpfr_set_str(exact, digits.c_str(), 16, MPFR_RNDN);
  mpfr_mul_2si(exact, exact, exponent - 4 * fraction_digits, MPFR_RNDN);
  Real r;
  mpfr_set(r.mpfr_ptr(), exact, MPFR_RNDN);
  mpfr_clear(exact);
  return r;
}

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Real parse() {
    Real v = expr();
    skip_space();
    if (pos_ != text_.size()) fail(pos_, std::string("unexpected '") + text_[pos_] + "'");
    return v;
  }

 private:
  std::string text_;
  std::size_t pos_ = 0;

  [[noreturn]] void fail(std::size_t at, const std::string& message) const { throw ExprError(text_, at, message); }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) fail(pos_, pos_ < text_.size() ? std::string("expected '") + c + "', found '" + text_[pos_] + "'"
                                                   : std::string("expected '") + c + "' before the end");
  }

  Real expr() {
    Real v = term();
    for (;;) {
      if (accept('+')) v = v + term();
      else if (accept('-')) v = v - term();
      else return v;
    }
  }

  Real term() {
    Real v = unary();
    for (;;) {
      if (accept('*')) v = v * unary();
      else if (accept('/')) v = v / unary();
      else return v;
    }
  }

  Real unary() {
    if (accept('-')) return -unary();  // mpfr negation: -0 and -inf keep their sign
    if (accept('+')) return unary();
    return power();
  }

  Real power() {
    Real base = primary();
    if (accept('^')) return mpfr::pow(base, unary());  // right-associative through unary()
    return base;
  }

  Real primary() {
    skip_space();
    if (pos_ >= text_.size()) fail(pos_, "expected a number, name or '(' before the end");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      Real v = expr();
      expect(')');
      return v;
    }
    if (is_digit(c) || c == '.') return number();
    if (is_name_start(c)) return name();
    fail(pos_, std::string("unexpected '") + c + "'");
  }

  Real number() {
    const std::size_t start = pos_;
    if (text_.compare(pos_, 2, "0x") == 0 || text_.compare(pos_, 2, "0X") == 0) {
      pos_ += 2;
      while (pos_ < text_.size() && (is_hex_digit(text_[pos_]) || text_[pos_] == '.')) ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == 'p' || text_[pos_] == 'P')) {
        ++pos_;
        if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
        while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_;
      }
      return hexfloat(std::string_view(text_).substr(start, pos_ - start),
                      [&](std::size_t offset, const std::string& message) { fail(start + offset, message); });
    }
    std::size_t digits = 0;
    while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_, ++digits;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_, ++digits;
    }
    if (digits == 0) fail(start, "a number needs at least one digit");
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      if (pos_ >= text_.size() || !is_digit(text_[pos_])) fail(pos_, "expected the exponent's digits after 'e'");
      while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_;
    }
    const std::string literal = text_.substr(start, pos_ - start);
    Real v;
    if (mpfr_set_str(v.mpfr_ptr(), literal.c_str(), 10, MPFR_RNDN) != 0) fail(start, "bad number '" + literal + "'");
    return v;
  }

  Real name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    const std::string id = text_.substr(start, pos_ - start);
    if (id == "pi") return mpfr::const_pi();
    if (id == "nan") return nan_value();
    if (id == "inf") return inf_value();

    static const char* const unary_functions[] = {"sqrt", "sin", "cos", "tan", "asin", "acos",
                                                  "atan", "exp", "log", "abs"};
    const bool is_unary = std::find(std::begin(unary_functions), std::end(unary_functions), id) != std::end(unary_functions);
    if (!is_unary && id != "atan2") fail(start, "unknown name '" + id + "'");
    if (!accept('(')) fail(pos_, "expected '(' after function '" + id + "'");
    std::vector<Real> args{expr()};
    while (accept(',')) args.push_back(expr());
    expect(')');
    const std::size_t want = is_unary ? 1 : 2;
    if (args.size() != want)
      fail(start, id + " takes " + std::to_string(want) + " argument(s), got " + std::to_string(args.size()));
    const Real& x = args[0];
    if (id == "sqrt") return mpfr::sqrt(x);
    if (id == "sin") return mpfr::sin(x);
    if (id == "cos") return mpfr::cos(x);
    if (id == "tan") return mpfr::tan(x);
    if (id == "asin") return mpfr::asin(x);
    if (id == "acos") return mpfr::acos(x);
    if (id == "atan") return mpfr::atan(x);
    if (id == "exp") return mpfr::exp(x);
    if (id == "log") return mpfr::log(x);
    if (id == "abs") return mpfr::abs(x);
    return mpfr::atan2(x, args[1]);
  }
};

}  // namespace

ExprError::ExprError(const std::string& text, std::size_t position, const std::string& message)
    : std::runtime_error(describe(text, position, message)), position_(position), message_(message) {}

Real evaluate(std::string_view text) { return Parser(text).parse(); }

Real parse_hexfloat(std::string_view text) {
  const std::string copy(text);
  return hexfloat(text, [&](std::size_t offset, const std::string& message) -> void {
    throw ExprError(copy, offset, message);
  });
}

}  // namespace rotorcert::spec

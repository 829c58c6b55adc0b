// Exact-expression evaluator for the values of spec/examples.json (NUM-2).
//
// Every number in a worked example is a string holding an expression, evaluated in MPFR at the
// current default precision (the reference's 256 bits):
//   numbers      decimal "3", "0.25", "1e-60"; C99 hexfloat "0x1.8p-3", "-0x1p-1074" (exact)
//   specials     "nan", "inf", "-inf", "-0" (the sign of zero is kept), constant "pi"
//   operators    + - * / ^ (right-associative, binds tighter than unary minus: -2^2 = -4),
//                unary + and -, parentheses
//   functions    sqrt sin cos tan asin acos atan atan2(y, x) exp log abs
//
// Grammar (recursive descent, one function per rule):
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := ('+' | '-') unary | power
//   power   := primary ('^' unary)?
//   primary := number | name | name '(' expr (',' expr)* ')' | '(' expr ')'
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include <rotorcert/reference/scalar.hpp>

namespace rotorcert::spec {

/// A syntax or domain error in an expression; `position` is the 0-based offset of the problem.
class ExprError : public std::runtime_error {
 public:
  ExprError(const std::string& text, std::size_t position, const std::string& message);
  std::size_t position() const { return position_; }
  const std::string& message() const { return message_; }

 private:
  std::size_t position_;
  std::string message_;
};

/// Evaluates `text` at the current MPFR default precision. Throws ExprError.
ref::Real evaluate(std::string_view text);

/// The exact value of a C99 hexadecimal floating literal without sign ("0x1.8p-3", "0X1P+4",
/// "0x10"); throws ExprError. Exact whenever the significand fits the default precision.
ref::Real parse_hexfloat(std::string_view text);

}  // namespace rotorcert::spec

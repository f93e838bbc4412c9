#pragma once
// A small, safe arithmetic expression of the coordinates x, y, z (a velocity field in a case file:
// docs/pd.md, `velocity_formula`). Grammar, usual precedence, ^ right-associative and binding
// tighter than a unary sign (-x^2 = -(x^2), 2^-1 = 0.5):
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('+' | '-') unary | power
//   power   := primary ('^' unary)?
//   primary := number | x | y | z | pi | e | function '(' sum ')' | '(' sum ')'
// with the functions sin cos tan exp log sqrt abs and numbers as 12, 1.5, .5, 2e-3. Nothing else
// is read (no names, no calls, no loops), so a case file cannot do more than compute a number.
// The text is compiled once into postfix order and evaluated with a small stack.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "shockfield/core/types.hpp"

namespace shockfield {

/// A syntax error: what was expected and the 1-based character of the text where it was not found.
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(std::size_t character, const std::string& what)
      : std::runtime_error(what), character_(character) {}
  std::size_t character() const { return character_; }

 private:
  std::size_t character_;
};

class Expression {
 public:
  /// Compiles `text` (at most kMaxLength characters, parentheses nested at most kMaxDepth deep).
  /// ExpressionError on bad syntax.
  static Expression parse(std::string_view text);
  /// The value at the point p = (x, y, z); NaN or ±inf where the formula has none (sqrt(-1), 1/0).
  double operator()(const Vec3& p) const;
  const std::string& text() const { return text_; }

  static constexpr std::size_t kMaxLength = 10000;
  static constexpr int kMaxDepth = 100;

 private:
  enum class Op : unsigned char {
    number,
    x,
    y,
    z,
    add,
    sub,
    mul,
    div,
    pow,
    neg,
    sin,
    cos,
    tan,
    exp,
    log,
    sqrt,
    abs
  };
  struct Instruction {
    Op op;
    double value = 0.0;  ///< for Op::number
  };
  class Parser;

  std::string text_;
  std::vector<Instruction> code_;  ///< postfix order
  std::size_t stack_size_ = 0;     ///< the deepest the evaluation stack gets
};

}  // namespace shockfield

// The formula evaluator of case files (core/expression.hpp): precedence and associativity as in
// the grammar, the functions and constants against <cmath> (the same operations, so equal to the
// last bit), and every syntax error naming the 1-based character where it went wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "shockfield/core/expression.hpp"

using shockfield::Expression;
using shockfield::ExpressionError;
using shockfield::Vec3;

namespace {

double eval(const std::string& text, const Vec3& p = Vec3(0.5, -2.0, 3.0)) {
  return Expression::parse(text)(p);
}

// The character an ExpressionError names, or 0 when `text` compiles.
std::size_t error_at(const std::string& text) {
  try {
    Expression::parse(text);
  } catch (const ExpressionError& e) {
    return e.character();
  }
  return 0;
}

}  // namespace

TEST(Expression, PrecedenceAndAssociativity) {
  EXPECT_EQ(eval("2 + 3*4"), 14.0);
  EXPECT_EQ(eval("(2 + 3)*4"), 20.0);
  EXPECT_EQ(eval("8/4/2"), 1.0);       // left-associative
  EXPECT_EQ(eval("2 - 3 - 4"), -5.0);  // left-associative
  EXPECT_EQ(eval("2^3^2"), 512.0);     // right-associative
  EXPECT_EQ(eval("-2^2"), -4.0);       // ^ binds tighter than the sign
  EXPECT_EQ(eval("2^-1"), 0.5);
  EXPECT_EQ(eval("--3"), 3.0);
  EXPECT_EQ(eval("+.5e1"), 5.0);
  EXPECT_EQ(eval("1.5E-3"), 1.5e-3);
}

TEST(Expression, CoordinatesFunctionsAndConstants) {
  const Vec3 p(0.25, -2.0, 3.0);
  EXPECT_EQ(eval("x", p), 0.25);
  EXPECT_EQ(eval("y", p), -2.0);
  EXPECT_EQ(eval("z", p), 3.0);
  EXPECT_EQ(eval("1e3*(x - 0.1)", p), 1e3 * (0.25 - 0.1));
  EXPECT_EQ(eval("sin(pi*x)", p), std::sin(std::numbers::pi * 0.25));
  EXPECT_EQ(eval("cos(y) + tan(x)", p), std::cos(-2.0) + std::tan(0.25));
  EXPECT_EQ(eval("exp(-x^2)*log(z)", p), std::exp(-std::pow(0.25, 2.0)) * std::log(3.0));
  EXPECT_EQ(eval("sqrt(abs(y*8))", p), 4.0);
  EXPECT_EQ(eval("e", p), std::numbers::e);
  EXPECT_TRUE(std::isnan(eval("sqrt(y)", p)));  // no value: the caller refuses it
  EXPECT_TRUE(std::isinf(eval("1/(x - x)", p)));
}

TEST(Expression, ErrorsNameTheCharacter) {
  EXPECT_EQ(error_at("x + 1"), 0u);
  EXPECT_EQ(error_at(""), 1u);
  EXPECT_EQ(error_at("2 +"), 4u);
  EXPECT_EQ(error_at("2*(3 + x"), 9u);  // the missing ')'
  EXPECT_EQ(error_at("foo(1)"), 1u);
  EXPECT_EQ(error_at("1e+"), 4u);
  EXPECT_EQ(error_at("x y"), 3u);
  EXPECT_EQ(error_at("sin x"), 5u);
  EXPECT_EQ(error_at("1..2"), 3u);
  EXPECT_EQ(error_at("3 $"), 3u);
  EXPECT_EQ(error_at("1e999"), 1u);  // out of range
  EXPECT_EQ(error_at("x = 1"), 3u);
  // kMaxDepth nested primaries: the parentheses and the number inside them.
  const auto nested = [](int depth) {
    return std::string(depth - 1, '(') + "1" + std::string(depth - 1, ')');
  };
  EXPECT_EQ(error_at(nested(Expression::kMaxDepth)), 0u);
  EXPECT_GT(error_at(nested(Expression::kMaxDepth + 1)), 0u);
  EXPECT_GT(error_at(std::string(100000, '-') + "1"),
            0u);  // too long and too deep: refused, no stack overflow
  try {
    Expression::parse("2*(3 + x");
  } catch (const ExpressionError& e) {
    EXPECT_NE(std::string(e.what()).find("expected ')' closing the '(' at character 3"),
              std::string::npos)
        << e.what();
  }
}

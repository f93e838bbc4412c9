#include "shockfield/core/expression.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <utility>

namespace shockfield {

// Recursive descent over the grammar of expression.hpp, emitting postfix code; `depth_` bounds
// the recursion (every level of nesting passes through primary()), `height_` tracks the stack.
class Expression::Parser {
 public:
  Parser(std::string_view text, Expression& out) : text_(text), out_(out) {}

  void parse() {
    sum();
    skip_space();
    if (at_ < text_.size())
      fail(at_, fmt::format("unexpected '{}' (expected an operator or the end)", text_[at_]));
  }

 private:
  void sum() {
    product();
    while (const char c = peek()) {
      if (c != '+' && c != '-') return;
      ++at_;
      product();
      emit(c == '+' ? Op::add : Op::sub);
    }
  }
  void product() {
    unary();
    while (const char c = peek()) {
      if (c != '*' && c != '/') return;
      ++at_;
      unary();
      emit(c == '*' ? Op::mul : Op::div);
    }
  }
  void unary() {
    const char c = peek();
    if (c == '+' || c == '-') {
      const Nesting nest(*this);
      ++at_;
      unary();
      if (c == '-') emit(Op::neg);
      return;
    }
    power();
  }
  void power() {
    primary();
    if (peek() != '^') return;
    ++at_;
    unary();
    emit(Op::pow);
  }
  void primary() {
    const Nesting nest(*this);
    const char c = peek();
    const std::size_t start = at_;
    if (c == '(') {
      ++at_;
      sum();
      close(start);
    } else if ((c >= '0' && c <= '9') || c == '.') {
      number();
    } else if (is_letter(c)) {
      name();
    } else {
      fail(at_,
           at_ < text_.size()
               ? fmt::format("unexpected '{}' (expected a number, x, y, z, a function or '(')", c)
               : std::string(
                     "the text ends where a number, x, y, z, a function or '(' was expected"));
    }
  }
  void number() {
    const std::size_t start = at_;
    const auto digits = [&] {
      const std::size_t from = at_;
      while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
      return at_ > from;
    };
    bool any = digits();
    if (at_ < text_.size() && text_[at_] == '.') ++at_, any = digits() || any;
    if (!any) fail(start, "a '.' without digits (expected a number such as 0.5)");
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      ++at_;
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
      if (!digits()) fail(at_, "an exponent without digits (expected a number such as 2e-3)");
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(text_.data() + start, text_.data() + at_, value);
    if (error != std::errc() || end != text_.data() + at_ || !std::isfinite(value))
      fail(start, fmt::format("the number '{}' is out of range", text_.substr(start, at_ - start)));
    emit(Op::number, value);
  }
  void name() {
    const std::size_t start = at_;
    while (at_ < text_.size() &&
           (is_letter(text_[at_]) || (text_[at_] >= '0' && text_[at_] <= '9')))
      ++at_;
    const std::string_view word = text_.substr(start, at_ - start);
    static constexpr std::array<std::pair<std::string_view, Op>, 3> coordinates{
        {{"x", Op::x}, {"y", Op::y}, {"z", Op::z}}};
    static constexpr std::array<std::pair<std::string_view, Op>, 7> functions{{{"sin", Op::sin},
                                                                               {"cos", Op::cos},
                                                                               {"tan", Op::tan},
                                                                               {"exp", Op::exp},
                                                                               {"log", Op::log},
                                                                               {"sqrt", Op::sqrt},
                                                                               {"abs", Op::abs}}};
    for (const auto& [n, op] : coordinates)
      if (word == n) return emit(op);
    if (word == "pi") return emit(Op::number, std::numbers::pi);
    if (word == "e") return emit(Op::number, std::numbers::e);
    for (const auto& [n, op] : functions)
      if (word == n) {
        if (peek() != '(') fail(at_, fmt::format("expected '(' after the function {}", word));
        const std::size_t open = at_;
        ++at_;
        sum();
        close(open);
        return emit(op);
      }
    fail(start, fmt::format("unknown name '{}' (expected x, y, z, pi, e or one of the functions "
                            "sin cos tan exp log "
                            "sqrt abs)",
                            word));
  }
  void close(std::size_t open) {
    if (peek() == ')') {
      ++at_;
      return;
    }
    fail(at_, fmt::format("expected ')' closing the '(' at character {}", open + 1));
  }

  // Arity of each operation: numbers and coordinates push one value, binary operations pop one
  // net, functions and negation none.
  void emit(Op op, double value = 0.0) {
    out_.code_.push_back({op, value});
    if (op == Op::number || op == Op::x || op == Op::y || op == Op::z)
      out_.stack_size_ = std::max(out_.stack_size_, ++height_);
    else if (op == Op::add || op == Op::sub || op == Op::mul || op == Op::div || op == Op::pow)
      --height_;
  }
  char peek() {
    skip_space();
    return at_ < text_.size() ? text_[at_] : '\0';
  }
  void skip_space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t')) ++at_;
  }
  static bool is_letter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  }
  [[noreturn]] static void fail(std::size_t at, const std::string& what) {
    throw ExpressionError(at + 1, fmt::format("character {}: {}", at + 1, what));
  }

  // One level of nesting for as long as it lives; too deep a text is refused before the
  // recursion could exhaust the call stack.
  struct Nesting {
    explicit Nesting(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxDepth)
        fail(parser.at_, fmt::format("nested more than {} levels deep", kMaxDepth));
    }
    ~Nesting() { --parser.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;
    Parser& parser;
  };

  std::string_view text_;
  Expression& out_;
  std::size_t at_ = 0;
  std::size_t height_ = 0;
  int depth_ = 0;
};

Expression Expression::parse(std::string_view text) {
  if (text.size() > kMaxLength)
    throw ExpressionError(kMaxLength + 1,
                          fmt::format("the formula has {} characters (expected at most {})",
                                      text.size(), kMaxLength));
  Expression e;
  e.text_ = std::string(text);
  Parser(e.text_, e).parse();
  return e;
}

double Expression::operator()(const Vec3& p) const {
  std::vector<double> stack;
  stack.reserve(stack_size_);
  const auto pop = [&stack] {
    const double v = stack.back();
    stack.pop_back();
    return v;
  };
  for (const Instruction& in : code_) {
    switch (in.op) {
      case Op::number:
        stack.push_back(in.value);
        break;
      case Op::x:
        stack.push_back(p[0]);
        break;
      case Op::y:
        stack.push_back(p[1]);
        break;
      case Op::z:
        stack.push_back(p[2]);
        break;
      case Op::neg:
        stack.back() = -stack.back();
        break;
      case Op::sin:
        stack.back() = std::sin(stack.back());
        break;
      case Op::cos:
        stack.back() = std::cos(stack.back());
        break;
      case Op::tan:
        stack.back() = std::tan(stack.back());
        break;
      case Op::exp:
        stack.back() = std::exp(stack.back());
        break;
      case Op::log:
        stack.back() = std::log(stack.back());
        break;
      case Op::sqrt:
        stack.back() = std::sqrt(stack.back());
        break;
      case Op::abs:
        stack.back() = std::abs(stack.back());
        break;
      default: {
        const double b = pop();
        double& a = stack.back();
        if (in.op == Op::add)
          a += b;
        else if (in.op == Op::sub)
          a -= b;
        else if (in.op == Op::mul)
          a *= b;
        else if (in.op == Op::div)
          a /= b;
        else
          a = std::pow(a, b);
      }
    }
  }
  return stack.back();
}

}  // namespace shockfield

#include "signorini/Expression.hpp"

#include <muParser.h>

#include "signorini/Error.hpp"

namespace signorini {

// The parser binds to the address of its variables, so they live next to it.
struct Expression::Parser {
  mu::Parser parser;
  double x[3] = {0.0, 0.0, 0.0};
};

Expression::Expression(const std::string& text, const std::string& what)
    : text_(text), what_(what), parser_(std::make_unique<Parser>()) {
  try {
    parser_->parser.DefineVar("x", &parser_->x[0]);
    parser_->parser.DefineVar("y", &parser_->x[1]);
    parser_->parser.DefineVar("z", &parser_->x[2]);
    parser_->parser.SetExpr(text.empty() ? "0" : text);
    parser_->parser.Eval();  // reports syntax errors now, not in the middle of assembly
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(what + ": cannot evaluate expression \"" + text + "\": " + e.GetMsg());
  }
}

Expression::Expression(const Expression& other) : Expression(other.text_, other.what_) {}

Expression& Expression::operator=(const Expression& other) {
  Expression copy(other);
  text_.swap(copy.text_);
  what_.swap(copy.what_);
  parser_.swap(copy.parser_);
  return *this;
}

Expression::~Expression() = default;

double Expression::operator()(const double* x, int dim) const {
  for (int i = 0; i < 3; ++i) parser_->x[i] = i < dim ? x[i] : 0.0;
  return parser_->parser.Eval();
}

bool Expression::isConstantZero() const {
  const double origin[3] = {0.0, 0.0, 0.0}, probe[3] = {0.37, 0.71, 0.53};
  return (*this)(origin, 3) == 0.0 && (*this)(probe, 3) == 0.0 &&
         parser_->parser.GetUsedVar().empty();
}

}  // namespace signorini

#include "signorini/assembly/Expression.hpp"

#include <cmath>
#include <sstream>

#include <muParser.h>

#include "assembly/BatchedExpression.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {

// The parser binds to the address of its variables, so they live next to it.
struct Expression::Parser {
  mu::Parser parser;
  double x[3] = {0.0, 0.0, 0.0};
  std::unique_ptr<detail::BatchedExpression> batched;  // null: evaluated point by point
};

Expression::Expression(const std::string& text, const std::string& what)
    : text_(text), what_(what), parser_(std::make_unique<Parser>()) {
  try {
    parser_->parser.DefineVar("x", &parser_->x[0]);
    parser_->parser.DefineVar("y", &parser_->x[1]);
    parser_->parser.DefineVar("z", &parser_->x[2]);
    parser_->parser.SetExpr(text.empty() ? "0" : text);
    parser_->parser.Eval();  // reports syntax errors now, not in the middle of assembly
    parser_->batched = detail::BatchedExpression::translate(parser_->parser, parser_->x);
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

double Expression::uncheckedValue(const double* x, int dim) const {
  for (int i = 0; i < 3; ++i) parser_->x[i] = i < dim ? x[i] : 0.0;
  return parser_->parser.Eval();
}

double Expression::operator()(const double* x, int dim) const {
  const double value = uncheckedValue(x, dim);
  requireFinite(value, x, dim);
  return value;
}

void Expression::evaluate(int count, const double* points, int dim, double* values) const {
  if (parser_->batched)
    parser_->batched->evaluate(count, points, dim, values);
  else
    for (int i = 0; i < count; ++i) values[i] = uncheckedValue(points + static_cast<std::ptrdiff_t>(dim) * i, dim);
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) requireFinite(values[i], points + static_cast<std::ptrdiff_t>(dim) * i, dim);
}

void Expression::requireFinite(double value, const double* x, int dim) const {
  if (std::isfinite(value)) return;
  std::ostringstream point;
  point << "(" << x[0];
  for (int i = 1; i < dim; ++i) point << ", " << x[i];
  point << ")";
  throw InputError(what_ + ": the expression \"" + text_ + "\" is " + (std::isnan(value) ? "not a number" : "infinite") +
                   " at " + point.str() + "; give one that is finite on the whole boundary or domain");
}

bool Expression::isConstantZero() const {
  // Probes that need not lie in the domain: evaluated without the finiteness check.
  const double origin[3] = {0.0, 0.0, 0.0}, probe[3] = {0.37, 0.71, 0.53};
  return uncheckedValue(origin, 3) == 0.0 && uncheckedValue(probe, 3) == 0.0 && parser_->parser.GetUsedVar().empty();
}

}  // namespace signorini

#pragma once
/// \file
/// A user-supplied scalar expression of the coordinates x, y, z (muparser syntax), for
/// loads, tractions, gaps and prescribed displacements given in the XML.
#include <memory>
#include <string>

namespace signorini {

class Expression {
 public:
  /// Parses `text` at once: a syntax error or an unknown variable throws InputError whose
  /// message names `what` (e.g. "Problem/body force: y").
  Expression(const std::string& text, const std::string& what);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  /// The value at x (dim coordinates). Throws InputError naming `what`, the expression and
  /// the point if it is not finite (sqrt of a negative number, division by zero...).
  double operator()(const double* x, int dim) const;
  /// values[i] = the value at points[dim * i ...] for i < count: the same values as operator()
  /// point by point (up to rounding where a power has a small integer exponent), at a
  /// fraction of the cost for many points. Throws as operator() does.
  void evaluate(int count, const double* points, int dim, double* values) const;
  const std::string& text() const { return text_; }
  bool isConstantZero() const;

 private:
  double uncheckedValue(const double* x, int dim) const;
  void requireFinite(double value, const double* x, int dim) const;

  struct Parser;
  std::string text_, what_;
  std::unique_ptr<Parser> parser_;
};

}  // namespace signorini

#pragma once
// A muparser expression evaluated at many points at once. Its bytecode is translated once
// into instructions that each act on a block of points, so muparser's per-token dispatch is
// paid once per block instead of once per point; a power with a small positive integer
// constant exponent, ((2*x-1)^4), is a product of squares, as muparser already computes x^4
// of a bare variable, instead of a call of pow. Both branches of a ?: are evaluated and the
// condition selects per point.
#include <memory>
#include <vector>

#include <muParser.h>

namespace signorini::detail {

class BatchedExpression {
 public:
  /// The translation of `parser`'s bytecode whose variables are `variables[0..2]` (x, y, z),
  /// or null if it holds a token this class does not translate (assignment, string or bulk
  /// functions, several comma-separated results): such an expression is evaluated by
  /// muparser point by point.
  static std::unique_ptr<BatchedExpression> translate(const mu::ParserBase& parser, const double* variables);

  /// values[i] = the expression at points[dim * i ...], missing coordinates 0. Not
  /// thread-safe (the stack is a member), like muparser's own evaluation.
  void evaluate(int count, const double* points, int dim, double* values) const;

 private:
  enum class Op {
    Constant, Coordinate, ScaledCoordinate, CoordinatePower, IntegerPower,
    Add, Subtract, Multiply, Divide, Power, Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual, And, Or,
    Function, MultiArgumentFunction, If, EndIf
  };
  struct Instruction {
    Op op;
    int coordinate = 0;          // Coordinate, ScaledCoordinate, CoordinatePower
    int count = 0;               // exponent of the powers; arguments of a function
    double scale = 0, shift = 0;  // ScaledCoordinate: x * scale + shift; Constant: shift
    mu::generic_callable_type function{};
  };
  static constexpr int blockSize = 64;

  // The instruction of a binary operator of muparser's bytecode; false for other commands.
  static bool binaryOperator(mu::ECmdCode command, Op& op);
  void run(int count, const double* points, int dim, double* values) const;
  void binary(Op op, int count, double* left, const double* right) const;
  void call(const Instruction& instruction, int count, double* arguments) const;

  std::vector<Instruction> program_;
  int stackDepth_ = 0, conditionDepth_ = 0;
  mutable std::vector<double> stack_, conditions_, coordinates_;
};

}  // namespace signorini::detail

#include "assembly/BatchedExpression.hpp"

#include <algorithm>
#include <cmath>

namespace signorini::detail {

namespace {

// The largest exponent computed by squaring: a few products, each rounded, stay within a
// few units in the last place of pow.
constexpr int maxIntegerExponent = 16;
constexpr int maxArguments = 16;  // of min, max, sum, avg: more are left to muparser

int integerExponent(double value) {
  return value >= 2 && value <= maxIntegerExponent && value == std::floor(value) ? static_cast<int>(value) : 0;
}

double integerPower(double base, int exponent) {
  double result = 1.0;
  for (bool first = true; exponent > 0; exponent >>= 1, base *= base) {
    if (!(exponent & 1)) continue;
    result = first ? base : result * base;
    first = false;
  }
  return result;
}

}  // namespace

std::unique_ptr<BatchedExpression> BatchedExpression::translate(const mu::ParserBase& parser,
                                                                const double* variables) {
  // Several results (a, b): muparser returns the stack entry its parser counted, which a
  // malformed text (a comma before a ?) can make differ from the last value computed.
  if (parser.GetNumResults() != 1) return nullptr;
  std::unique_ptr<BatchedExpression> batched(new BatchedExpression);
  std::vector<Instruction>& program = batched->program_;
  int depth = 0, conditions = 0;
  const auto emit = [&](Instruction instruction, int pushed) {
    program.push_back(instruction);
    depth += pushed;
    batched->stackDepth_ = std::max(batched->stackDepth_, depth);
  };
  const auto coordinate = [&](const mu::SToken& token) {
    for (int k = 0; k < 3; ++k)
      if (token.Val.ptr == variables + k) return k;
    return -1;  // a variable other than x, y, z
  };

  for (const mu::SToken* token = parser.GetByteCode().GetBase(); token->Cmd != mu::cmEND; ++token) {
    switch (token->Cmd) {
      case mu::cmVAL: emit({Op::Constant, 0, 0, 0, token->Val.data2}, 1); break;
      case mu::cmVAR:
      case mu::cmVARMUL:
      case mu::cmVARPOW2:
      case mu::cmVARPOW3:
      case mu::cmVARPOW4: {
        const int k = coordinate(*token);
        if (k < 0) return nullptr;
        if (token->Cmd == mu::cmVAR) emit({Op::Coordinate, k}, 1);
        else if (token->Cmd == mu::cmVARMUL) emit({Op::ScaledCoordinate, k, 0, token->Val.data, token->Val.data2}, 1);
        else emit({Op::CoordinatePower, k, 2 + (token->Cmd - mu::cmVARPOW2)}, 1);
        break;
      }
      case mu::cmPOW: {
        // The exponent is the value pushed last; a constant small integer one is replaced.
        const int exponent = !program.empty() && program.back().op == Op::Constant ? integerExponent(program.back().shift) : 0;
        if (exponent == 0) {
          emit({Op::Power}, -1);
          break;
        }
        program.pop_back();
        emit({Op::IntegerPower, 0, exponent}, -1);
        break;
      }
      case mu::cmFUNC: {
        const int argc = token->Fun.argc;
        if (argc > 3 || -argc > maxArguments) return nullptr;
        Instruction call{argc >= 0 ? Op::Function : Op::MultiArgumentFunction, 0, std::abs(argc)};
        call.function = token->Fun.cb;
        emit(call, 1 - std::abs(argc));
        break;
      }
      case mu::cmIF:
        emit({Op::If}, -1);
        batched->conditionDepth_ = std::max(batched->conditionDepth_, ++conditions);
        break;
      case mu::cmELSE: break;  // the else branch is evaluated too, above the then branch's value
      case mu::cmENDIF:
        emit({Op::EndIf}, -1);
        --conditions;
        break;
      default: {
        Op op;
        if (!binaryOperator(token->Cmd, op)) return nullptr;  // assignment, string and bulk functions, user operators
        emit({op}, -1);
      }
    }
    if (depth < 0 || conditions < 0) return nullptr;
  }
  if (depth != 1 || conditions != 0) return nullptr;
  batched->stack_.resize(static_cast<std::size_t>(batched->stackDepth_) * blockSize);
  batched->conditions_.resize(static_cast<std::size_t>(batched->conditionDepth_) * blockSize);
  batched->coordinates_.resize(3 * blockSize);
  return batched;
}

bool BatchedExpression::binaryOperator(mu::ECmdCode command, Op& op) {
  switch (command) {
    case mu::cmADD: op = Op::Add; return true;
    case mu::cmSUB: op = Op::Subtract; return true;
    case mu::cmMUL: op = Op::Multiply; return true;
    case mu::cmDIV: op = Op::Divide; return true;
    case mu::cmLT: op = Op::Less; return true;
    case mu::cmLE: op = Op::LessEqual; return true;
    case mu::cmGT: op = Op::Greater; return true;
    case mu::cmGE: op = Op::GreaterEqual; return true;
    case mu::cmEQ: op = Op::Equal; return true;
    case mu::cmNEQ: op = Op::NotEqual; return true;
    case mu::cmLAND: op = Op::And; return true;
    case mu::cmLOR: op = Op::Or; return true;
    default: return false;
  }
}

void BatchedExpression::evaluate(int count, const double* points, int dim, double* values) const {
  for (int first = 0; first < count; first += blockSize)
    run(std::min(blockSize, count - first), points + static_cast<std::ptrdiff_t>(dim) * first, dim, values + first);
}

// One block: the coordinates transposed into rows of the block, then the program, each
// instruction over every point. Stack level s holds stack_[s * blockSize ...].
void BatchedExpression::run(int count, const double* points, int dim, double* values) const {
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < count; ++i) coordinates_[k * blockSize + i] = k < dim ? points[dim * i + k] : 0.0;
  const auto level = [&](int s) { return &stack_[static_cast<std::size_t>(s) * blockSize]; };
  int top = -1, condition = -1;
  for (const Instruction& instruction : program_) {
    const double* x = &coordinates_[instruction.coordinate * blockSize];
    switch (instruction.op) {
      case Op::Constant: std::fill_n(level(++top), count, instruction.shift); break;
      case Op::Coordinate: std::copy_n(x, count, level(++top)); break;
      case Op::ScaledCoordinate: {
        double* out = level(++top);
        for (int i = 0; i < count; ++i) out[i] = x[i] * instruction.scale + instruction.shift;
        break;
      }
      case Op::CoordinatePower: {  // as muparser: x * x * x, left to right
        double* out = level(++top);
        for (int i = 0; i < count; ++i) {
          double p = x[i];
          for (int e = 1; e < instruction.count; ++e) p *= x[i];
          out[i] = p;
        }
        break;
      }
      case Op::IntegerPower: {
        double* out = level(top);
        for (int i = 0; i < count; ++i) out[i] = integerPower(out[i], instruction.count);
        break;
      }
      case Op::Function:
      case Op::MultiArgumentFunction:
        top -= instruction.count - 1;
        call(instruction, count, level(top));
        break;
      case Op::If:
        std::copy_n(level(top--), count, &conditions_[static_cast<std::size_t>(++condition) * blockSize]);
        break;
      case Op::EndIf: {
        const double* chosen = &conditions_[static_cast<std::size_t>(condition--) * blockSize];
        double* then = level(top - 1);
        const double* otherwise = level(top--);
        for (int i = 0; i < count; ++i) then[i] = chosen[i] != 0 ? then[i] : otherwise[i];
        break;
      }
      default:
        binary(instruction.op, count, level(top - 1), level(top));
        --top;
    }
  }
  std::copy_n(level(0), count, values);
}

void BatchedExpression::binary(Op op, int count, double* left, const double* right) const {
  const auto apply = [&](auto f) {
    for (int i = 0; i < count; ++i) left[i] = f(left[i], right[i]);
  };
  switch (op) {
    case Op::Add: apply([](double a, double b) { return a + b; }); break;
    case Op::Subtract: apply([](double a, double b) { return a - b; }); break;
    case Op::Multiply: apply([](double a, double b) { return a * b; }); break;
    case Op::Divide: apply([](double a, double b) { return a / b; }); break;
    case Op::Power: apply([](double a, double b) { return std::pow(a, b); }); break;
    case Op::Less: apply([](double a, double b) { return double(a < b); }); break;
    case Op::LessEqual: apply([](double a, double b) { return double(a <= b); }); break;
    case Op::Greater: apply([](double a, double b) { return double(a > b); }); break;
    case Op::GreaterEqual: apply([](double a, double b) { return double(a >= b); }); break;
    case Op::Equal: apply([](double a, double b) { return double(a == b); }); break;
    case Op::NotEqual: apply([](double a, double b) { return double(a != b); }); break;
    case Op::And: apply([](double a, double b) { return double(a && b); }); break;
    case Op::Or: apply([](double a, double b) { return double(a || b); }); break;
    default: break;
  }
}

// The arguments are stack levels arguments[0], arguments[blockSize], ...; the result
// replaces the first.
void BatchedExpression::call(const Instruction& instruction, int count, double* arguments) const {
  const mu::generic_callable_type& f = instruction.function;
  const auto argument = [&](int a, int i) { return arguments[a * blockSize + i]; };
  double gathered[maxArguments];
  switch (instruction.op == Op::MultiArgumentFunction ? -1 : instruction.count) {
    case 0:
      for (int i = 0; i < count; ++i) arguments[i] = f.call_fun<0>();
      break;
    case 1:
      for (int i = 0; i < count; ++i) arguments[i] = f.call_fun<1>(argument(0, i));
      break;
    case 2:
      for (int i = 0; i < count; ++i) arguments[i] = f.call_fun<2>(argument(0, i), argument(1, i));
      break;
    case 3:
      for (int i = 0; i < count; ++i) arguments[i] = f.call_fun<3>(argument(0, i), argument(1, i), argument(2, i));
      break;
    default:
      for (int i = 0; i < count; ++i) {
        for (int a = 0; a < instruction.count; ++a) gathered[a] = argument(a, i);
        arguments[i] = f.call_multfun(gathered, instruction.count);
      }
  }
}

}  // namespace signorini::detail

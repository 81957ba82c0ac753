// IPOPT (with MUMPS) on a QP exported by `signorini --export-qp DIR`: min 1/2 v'Qv - b'v
// subject to Av <= d, for comparison with Signorini's interior point methods on the same
// discrete problem. Built only where Debian's coinor-libipopt-dev is installed.
//
//     signorini_bench_ipopt DIR [name=value ...]
//
// Reads DIR/{Q,b,A,d}.mtx with CHOLMOD's Matrix Market reader, solves from v = 0 (feasible:
// the gaps are nonnegative) and prints one JSON record: status, objective, iterations and the
// seconds spent in IpoptApplication::OptimizeTNLP (reading excluded). The extra arguments are
// IPOPT options (numbers are set as numbers, other values as strings).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <cholmod.h>

namespace {

using Ipopt::Index;
using Ipopt::Number;

// A matrix as coordinate triplets (0-based), and a dense vector.
struct Triplets {
  Index rows = 0, cols = 0;
  std::vector<Index> row, col;
  std::vector<Number> value;
};

class Cholmod {
 public:
  Cholmod() { cholmod_start(&common_); }
  ~Cholmod() { cholmod_finish(&common_); }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;

  // Entries of the file; with lowerOnly, those on and below the diagonal.
  Triplets readSparse(const std::string& path, bool lowerOnly) {
    FILE* file = open(path);
    cholmod_sparse* S = cholmod_read_sparse(file, &common_);
    std::fclose(file);
    if (!S) throw std::runtime_error(path + ": not a sparse Matrix Market matrix");
    if (S->stype != 0) throw std::runtime_error(path + ": expected a general (unsymmetric-storage) matrix");
    Triplets t;
    t.rows = static_cast<Index>(S->nrow);
    t.cols = static_cast<Index>(S->ncol);
    const auto* p = static_cast<const int*>(S->p);
    const auto* i = static_cast<const int*>(S->i);
    const auto* x = static_cast<const double*>(S->x);
    for (Index j = 0; j < t.cols; ++j)
      for (int k = p[j]; k < p[j + 1]; ++k) {
        if (lowerOnly && i[k] < j) continue;
        t.row.push_back(i[k]);
        t.col.push_back(j);
        t.value.push_back(x[k]);
      }
    cholmod_free_sparse(&S, &common_);
    return t;
  }

  std::vector<Number> readDense(const std::string& path) {
    FILE* file = open(path);
    cholmod_dense* D = cholmod_read_dense(file, &common_);
    std::fclose(file);
    if (!D || D->ncol != 1) throw std::runtime_error(path + ": not a dense Matrix Market vector");
    const auto* x = static_cast<const double*>(D->x);
    std::vector<Number> v(x, x + D->nrow);
    cholmod_free_dense(&D, &common_);
    return v;
  }

 private:
  static FILE* open(const std::string& path) {
    FILE* file = std::fopen(path.c_str(), "r");
    if (!file) throw std::runtime_error("cannot open " + path);
    return file;
  }

  cholmod_common common_;
};

struct ContactQp {
  Triplets Qlower, A;
  std::vector<Number> b, d;
};

// min 1/2 v'Qv - b'v subject to Av <= d: the Hessian is Q (constant), the Jacobian A.
class ContactQpNlp : public Ipopt::TNLP {
 public:
  explicit ContactQpNlp(const ContactQp& qp) : qp_(qp) {}

  Number objective = 0;

  bool get_nlp_info(Index& n, Index& m, Index& nnzJacobian, Index& nnzHessian, IndexStyleEnum& style) override {
    n = qp_.Qlower.rows;
    m = qp_.A.rows;
    nnzJacobian = static_cast<Index>(qp_.A.value.size());
    nnzHessian = static_cast<Index>(qp_.Qlower.value.size());
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* vLower, Number* vUpper, Index m, Number* gLower, Number* gUpper) override {
    for (Index i = 0; i < n; ++i) vLower[i] = -2e19, vUpper[i] = 2e19;  // beyond nlp_*_bound_inf: free
    for (Index i = 0; i < m; ++i) gLower[i] = -2e19, gUpper[i] = qp_.d[i];
    return true;
  }

  bool get_starting_point(Index n, bool initV, Number* v, bool initZ, Number*, Number*, Index, bool initLambda,
                          Number*) override {
    if (initZ || initLambda || !initV) return false;
    std::fill(v, v + n, 0.0);
    return true;
  }

  bool eval_f(Index n, const Number* v, bool, Number& f) override {
    std::vector<Number> Qv(n);
    multiplyQ(v, Qv.data());
    f = 0;
    for (Index i = 0; i < n; ++i) f += v[i] * (0.5 * Qv[i] - qp_.b[i]);
    return true;
  }

  bool eval_grad_f(Index n, const Number* v, bool, Number* gradient) override {
    multiplyQ(v, gradient);
    for (Index i = 0; i < n; ++i) gradient[i] -= qp_.b[i];
    return true;
  }

  bool eval_g(Index, const Number* v, bool, Index m, Number* g) override {
    std::fill(g, g + m, 0.0);
    for (std::size_t k = 0; k < qp_.A.value.size(); ++k) g[qp_.A.row[k]] += qp_.A.value[k] * v[qp_.A.col[k]];
    return true;
  }

  bool eval_jac_g(Index, const Number*, bool, Index, Index, Index* rows, Index* cols, Number* values) override {
    return copyStructureOrValues(qp_.A, 1.0, rows, cols, values);
  }

  bool eval_h(Index, const Number*, bool, Number objectiveFactor, Index, const Number*, bool, Index, Index* rows,
              Index* cols, Number* values) override {
    return copyStructureOrValues(qp_.Qlower, objectiveFactor, rows, cols, values);
  }

  void finalize_solution(Ipopt::SolverReturn, Index, const Number*, const Number*, const Number*, Index,
                         const Number*, const Number*, Number f, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    objective = f;
  }

 private:
  // Q v from its lower triangle.
  void multiplyQ(const Number* v, Number* Qv) const {
    std::fill(Qv, Qv + qp_.Qlower.rows, 0.0);
    const Triplets& Q = qp_.Qlower;
    for (std::size_t k = 0; k < Q.value.size(); ++k) {
      Qv[Q.row[k]] += Q.value[k] * v[Q.col[k]];
      if (Q.row[k] != Q.col[k]) Qv[Q.col[k]] += Q.value[k] * v[Q.row[k]];
    }
  }

  static bool copyStructureOrValues(const Triplets& t, Number factor, Index* rows, Index* cols, Number* values) {
    if (values) {
      for (std::size_t k = 0; k < t.value.size(); ++k) values[k] = factor * t.value[k];
    } else {
      std::copy(t.row.begin(), t.row.end(), rows);
      std::copy(t.col.begin(), t.col.end(), cols);
    }
    return true;
  }

  const ContactQp& qp_;
};

ContactQp readQp(const std::string& dir) {
  Cholmod cholmod;
  ContactQp qp{cholmod.readSparse(dir + "/Q.mtx", true), cholmod.readSparse(dir + "/A.mtx", false),
               cholmod.readDense(dir + "/b.mtx"), cholmod.readDense(dir + "/d.mtx")};
  const std::size_t n = qp.Qlower.rows, m = qp.A.rows;
  if (qp.Qlower.cols != qp.Qlower.rows || qp.A.cols != qp.Qlower.rows || qp.b.size() != n || qp.d.size() != m)
    throw std::runtime_error(dir + ": the sizes of Q, A, b and d do not match");
  return qp;
}

void setOption(Ipopt::OptionsList& options, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos) throw std::runtime_error("IPOPT option \"" + assignment + "\" is not name=value");
  const std::string name = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  char* end = nullptr;
  const long asInteger = std::strtol(value.c_str(), &end, 10);
  if (!value.empty() && *end == '\0') {
    options.SetIntegerValue(name, static_cast<Index>(asInteger));
    return;
  }
  const double asNumber = std::strtod(value.c_str(), &end);
  if (!value.empty() && *end == '\0')
    options.SetNumericValue(name, asNumber);
  else
    options.SetStringValue(name, value);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: signorini_bench_ipopt DIR [ipopt-option=value ...]\n";
    return 2;
  }
  try {
    const ContactQp qp = readQp(argv[1]);
    Ipopt::SmartPtr<ContactQpNlp> nlp = new ContactQpNlp(qp);
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
    Ipopt::OptionsList& options = *app->Options();
    options.SetIntegerValue("print_level", 0);
    // What a QP lets IPOPT know: derivatives evaluated once.
    options.SetStringValue("hessian_constant", "yes");
    options.SetStringValue("jac_c_constant", "yes");
    options.SetStringValue("jac_d_constant", "yes");
    for (int i = 2; i < argc; ++i) setOption(options, argv[i]);
    if (app->Initialize() != Ipopt::Solve_Succeeded) throw std::runtime_error("IPOPT did not initialise");

    const auto start = std::chrono::steady_clock::now();
    const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::printf("{\"n\": %d, \"m\": %d, \"status\": %d, \"converged\": %s, \"objective\": %.15e, "
                "\"iterations\": %d, \"seconds\": %.6f}\n",
                qp.Qlower.rows, qp.A.rows, static_cast<int>(status),
                status == Ipopt::Solve_Succeeded ? "true" : "false", nlp->objective,
                Ipopt::IsValid(app->Statistics()) ? static_cast<int>(app->Statistics()->IterationCount()) : -1, seconds);
    return status == Ipopt::Solve_Succeeded ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "signorini_bench_ipopt: " << e.what() << "\n";
    return 2;
  }
}

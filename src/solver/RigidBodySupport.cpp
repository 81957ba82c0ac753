#include "solver/RigidBodySupport.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Collectives.hpp"
#include "signorini/core/Error.hpp"
#include "solver/linear/StiffnessParts.hpp"

namespace signorini {
namespace {

// Motions whose energy (or constraint movement) is below this fraction of its scale are free.
constexpr double kFree = 1e-12;

// A small dense matrix, column-major, the same on every rank.
using Dense = std::vector<double>;

// UᵀV, summed over the ranks.
Dense innerProducts(const MultiVector& U, const MultiVector& V) {
  const int k = static_cast<int>(U.getNumVectors()), l = static_cast<int>(V.getNumVectors());
  Dense local(k * l, 0.0), global(k * l, 0.0);
  // One pass over the rows for all k l products: the columns are long, k and l at most 6.
  std::vector<Teuchos::ArrayRCP<const double>> u(k), v(l);
  for (int a = 0; a < k; ++a) u[a] = U.getData(a);
  for (int b = 0; b < l; ++b) v[b] = V.getData(b);
  for (std::size_t i = 0; i < U.getLocalLength(); ++i)
    for (int b = 0; b < l; ++b)
      for (int a = 0; a < k; ++a) local[a + k * b] += u[a][i] * v[b][i];
  Teuchos::reduceAll(*U.getMap()->getComm(), Teuchos::REDUCE_SUM, k * l, local.data(), global.data());
  return global;
}

// K y = theta B y (B = I when empty): eigenvalues ascending, B-orthonormal eigenvectors; no
// eigenvalues if LAPACK fails.
struct Eigen {
  std::vector<double> values;
  Dense vectors;
};
Eigen symmetricEigen(Dense K, Dense B, int k) {
  Eigen e{std::vector<double>(k), std::move(K)};
  const int lwork = 8 * k + 16;
  std::vector<double> work(lwork);
  int info = 0;
  Teuchos::LAPACK<int, double> lapack;
  if (B.empty())
    lapack.SYEV('V', 'U', k, e.vectors.data(), k, e.values.data(), work.data(), lwork, &info);
  else
    lapack.SYGV(1, 'V', 'U', k, e.vectors.data(), k, B.data(), k, e.values.data(), work.data(), lwork, &info);
  if (info != 0) e.values.clear();  // B not positive definite: the modes are not independent
  return e;
}

// Columns sum_a Y(a, j) U_a for j < count.
RCP<MultiVector> combine(const MultiVector& U, const Dense& Y, int count) {
  const int k = static_cast<int>(U.getNumVectors());
  auto result = rcp(new MultiVector(U.getMap(), count));
  for (int j = 0; j < count; ++j)
    for (int a = 0; a < k; ++a) result->getVectorNonConst(j)->update(Y[a + k * j], *U.getVector(a), 1.0);
  return result;
}

// The stiffness scale of Q: its mean diagonal entry, or the Rayleigh quotient of a random
// vector (the same in expectation) when Q is an operator only.
double stiffnessScale(const ContactQP& qp, const MultigridInput& multigrid) {
  const StiffnessParts stiffness(qp, multigrid);
  if (stiffness.available()) return stiffness.diagonal()->meanValue();
  Vector x(qp.Q->getDomainMap());
  x.randomize();
  Vector Qx(qp.Q->getRangeMap());
  qp.Q->apply(x, Qx);
  return Qx.dot(x) / x.dot(x);
}

// The unit vector along v, its largest component positive unless `keepSign`.
std::string vectorText(const double* v, int dim, bool keepSign) {
  double norm = 0;
  int largest = 0;
  for (int c = 0; c < dim; ++c) {
    norm += v[c] * v[c];
    if (std::abs(v[c]) > std::abs(v[largest])) largest = c;
  }
  norm = std::sqrt(norm);
  if (!keepSign && v[largest] < 0) norm = -norm;
  std::string text = "(";
  for (int c = 0; c < dim; ++c) {
    char number[32];
    const double value = std::abs(v[c]) < 1e-8 * std::abs(norm) ? 0.0 : v[c] / norm;
    std::snprintf(number, sizeof number, "%s%.3g", c ? ", " : "", value);
    text += number;
  }
  return text + ")";
}

// The nodes (blockSize entries of u each) that u moves: more than 1e-8 of its largest move.
std::vector<char> movingNodes(const Vector& u, int dim) {
  auto data = u.getData();
  const std::size_t nodes = u.getLocalLength() / dim;
  std::vector<double> squares(nodes, 0.0);
  for (std::size_t i = 0; i < nodes; ++i)
    for (int c = 0; c < dim; ++c) squares[i] += data[dim * i + c] * data[dim * i + c];
  const double largest = maxOverRanks(*u.getMap()->getComm(), squares.empty() ? 0.0 : *std::max_element(squares.begin(), squares.end()));
  std::vector<char> moves(nodes);
  for (std::size_t i = 0; i < nodes; ++i) moves[i] = squares[i] > 1e-16 * largest;
  return moves;
}

// "the body", or of several bodies "the body around (x, y)", the centroid of the nodes u moves.
std::string movingBody(const Vector& u, const MultigridInput& multigrid) {
  if (multigrid.nodeBodies.empty() || multigrid.coordinates.is_null()) return "the body";
  const int dim = multigrid.blockSize;
  const Comm& comm = *u.getMap()->getComm();
  const std::vector<char> moves = movingNodes(u, dim);
  const double count = sumOverRanks(comm, static_cast<double>(std::count(moves.begin(), moves.end(), 1)));
  std::string text = "the body around (";
  for (int c = 0; c < dim; ++c) {
    auto x = multigrid.coordinates->getData(c);
    const double centroid = sumOverEntries(comm, moves.size(), [&](std::size_t i) { return moves[i] ? x[i] : 0.0; }) / count;
    char number[32];
    std::snprintf(number, sizeof number, "%s%.3g", c ? ", " : "", centroid);
    text += number;
  }
  return text + ")";
}

// "a translation along (0, 1)" or "a rotation about an axis along (0, 0, 1)" for the rigid
// motion u (blockSize components per node); a direction of either sign unless `keepSign`. The axis of u(x) = t + w x (x - x0) solves
// J w = sum (x - x0) x (u - u0), J the inertia tensor of the nodes about their centroid x0.
std::string describeMotion(const Vector& u, const MultigridInput& multigrid, bool keepSign) {
  const int dim = multigrid.blockSize;
  const Comm& comm = *u.getMap()->getComm();
  auto data = u.getData();
  const std::size_t nodes = u.getLocalLength() / dim;
  // Over the nodes that move: the motion of one body of several is zero on the others.
  const std::vector<char> moves = movingNodes(u, dim);
  const long long numNodes = sumOverRanks(comm, static_cast<long long>(std::count(moves.begin(), moves.end(), 1)));
  const auto onMoving = [&](auto term) { return [&, term](std::size_t i) { return moves[i] ? term(i) : 0.0; }; };
  double mean[3] = {0, 0, 0};
  for (int c = 0; c < dim; ++c)
    mean[c] = sumOverEntries(comm, nodes, onMoving([&, c](std::size_t i) { return data[dim * i + c]; })) / numNodes;
  const double square = sumOverEntries(comm, u.getLocalLength(),
                                       [&](std::size_t i) { return moves[i / dim] ? data[i] * data[i] : 0.0; });
  double meanSquare = 0;
  for (int c = 0; c < dim; ++c) meanSquare += mean[c] * mean[c];
  if (square - numNodes * meanSquare <= 1e-10 * square) return "a translation along " + vectorText(mean, dim, keepSign);
  if (dim != 3 || multigrid.coordinates.is_null()) return "a rotation";

  Teuchos::ArrayRCP<const double> x[3];
  for (int c = 0; c < 3; ++c) x[c] = multigrid.coordinates->getData(c);
  double centroid[3];
  for (int c = 0; c < 3; ++c)
    centroid[c] = sumOverEntries(comm, nodes, onMoving([&, c](std::size_t i) { return x[c][i]; })) / numNodes;
  Dense inertia(9, 0.0), moment(3, 0.0), localInertia(9, 0.0), localMoment(3, 0.0);
  for (std::size_t i = 0; i < nodes; ++i) {
    if (!moves[i]) continue;
    double y[3], w[3];
    for (int c = 0; c < 3; ++c) {
      y[c] = x[c][i] - centroid[c];
      w[c] = data[3 * i + c] - mean[c];
    }
    const double yy = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    for (int a = 0; a < 3; ++a) {
      const int p = (a + 1) % 3, q = (a + 2) % 3;
      localMoment[a] += y[p] * w[q] - y[q] * w[p];
      for (int b = 0; b < 3; ++b) localInertia[a + 3 * b] += (a == b ? yy : 0.0) - y[a] * y[b];
    }
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 9, localInertia.data(), inertia.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 3, localMoment.data(), moment.data());
  // w = J^-1 moment, by J's eigenvectors (J is symmetric positive definite for a 3D body).
  const Eigen j = symmetricEigen(inertia, {}, 3);
  double axis[3] = {0, 0, 0};
  for (int e = 0; e < 3; ++e) {
    const double* v = &j.vectors[3 * e];
    const double coefficient = (v[0] * moment[0] + v[1] * moment[1] + v[2] * moment[2]) / j.values[e];
    for (int c = 0; c < 3; ++c) axis[c] += coefficient * v[c];
  }
  return "a rotation about an axis along " + vectorText(axis, 3, keepSign);
}

// The first free motion of F (orthonormal columns) that moves no constraint row, or null.
RCP<Vector> motionNoConstraintStops(const ContactQP& qp, const MultiVector& F) {
  const int f = static_cast<int>(F.getNumVectors());
  if (qp.A->getRangeMap()->getGlobalNumElements() == 0) return rcp(new Vector(*F.getVector(0), Teuchos::Copy));
  MultiVector AF(qp.A->getRangeMap(), f);
  qp.A->apply(F, AF);
  const Eigen seen = symmetricEigen(innerProducts(AF, AF), {}, f);
  const double norm = qp.A->getFrobeniusNorm();
  const double meanRowSquare = norm * norm / qp.A->getRangeMap()->getGlobalNumElements();
  if (seen.values[0] > kFree * meanRowSquare) return Teuchos::null;
  return rcp(new Vector(*combine(F, seen.vectors, 1)->getVector(0), Teuchos::Copy));
}

// The load's component along the free motions, if no constraint resists it, or null.
RCP<Vector> motionTheLoadPullsFree(const ContactQP& qp, const MultiVector& F) {
  const int f = static_cast<int>(F.getNumVectors());
  Dense load(f);
  for (int j = 0; j < f; ++j) load[j] = F.getVector(j)->dot(*qp.b);
  double loadNorm = 0;
  for (double value : load) loadNorm += value * value;
  if (std::sqrt(loadNorm) <= kFree * qp.b->norm2()) return Teuchos::null;
  auto r = rcp(new Vector(F.getMap()));
  for (int j = 0; j < f; ++j) r->update(load[j], *F.getVector(j), 1.0);
  Vector Ar(qp.A->getRangeMap());
  qp.A->apply(*r, Ar);
  auto a = Ar.getData();
  double largest = -1.0;
  for (std::size_t i = 0; i < Ar.getLocalLength(); ++i) largest = std::max(largest, a[i]);
  return maxOverRanks(*Ar.getMap()->getComm(), largest) > kFree * Ar.normInf() ? Teuchos::null : r;
}

}  // namespace

RCP<const MultiVector> checkRigidBodyMotionsHeld(const ContactQP& qp, const MultigridInput& multigrid) {
  const RCP<const MultiVector> modes = multigrid.bodyMotions(qp);
  if (modes.is_null() || modes->getNumVectors() == 0) return Teuchos::null;
  const MultiVector& R = *modes;
  const int k = static_cast<int>(R.getNumVectors());
  MultiVector QR(qp.Q->getRangeMap(), k);
  qp.Q->apply(R, QR);
  // theta = rᵀQr / rᵀr: ~0 for the motions no prescribed displacement removes.
  const Eigen energy = symmetricEigen(innerProducts(R, QR), innerProducts(R, R), k);
  if (energy.values.empty()) return Teuchos::null;  // dependent modes: nothing to conclude from them
  const double scale = stiffnessScale(qp, multigrid);
  int free = 0;
  while (free < k && energy.values[free] <= kFree * scale) ++free;
  if (free == 0) return Teuchos::null;
  const RCP<const MultiVector> F = combine(R, energy.vectors, free);  // orthonormal columns

  if (const RCP<Vector> r = motionNoConstraintStops(qp, *F))
    throw InputError(movingBody(*r, multigrid) + " is free to move by " + describeMotion(*r, multigrid, false) +
                     ": no prescribed displacement removes it and no contact constraint stops it "
                     "(frictionless contact holds a body only in the obstacle's direction); prescribe "
                     "displacements that remove it on a boundary (Problem/Dirichlet), for instance the "
                     "normal component on a symmetry plane");
  if (const RCP<Vector> r = motionTheLoadPullsFree(qp, *F))
    throw InputError("the load pulls " + movingBody(*r, multigrid) + " off the obstacle by " +
                     describeMotion(*r, multigrid, true) +
                     ", which no prescribed displacement removes and no contact constraint resists: the "
                     "problem has no equilibrium; prescribe a displacement that holds the body "
                     "(Problem/Dirichlet) or check the direction of the load");
  return F;
}

}  // namespace signorini

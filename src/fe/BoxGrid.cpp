#include "fe/BoxGrid.hpp"

#include <algorithm>
#include <cmath>

#include "fe/RectilinearGrid.hpp"
#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

const std::vector<std::array<int, 4>> squareTriangles = {{0, 1, 3, 0}, {0, 3, 2, 0}};  // (a,b,e), (a,e,c)
const std::vector<std::array<int, 4>> evenCubeTets = {
    {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}, {1, 2, 4, 7}};
const std::vector<std::array<int, 4>> oddCubeTets = {
    {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}, {0, 3, 5, 6}};

int cornerOffset(int corner, int axis) { return (corner >> axis) & 1; }

// Barycentric coordinates of the point xi (in box units) in a simplex of box corners.
void barycentric(int dim, const std::array<int, 4>& s, const double* xi, double* lambda) {
  double e[3][3] = {}, r[3] = {};
  for (int a = 0; a < dim; ++a) {
    for (int k = 0; k < dim; ++k) e[a][k] = cornerOffset(s[k + 1], a) - cornerOffset(s[0], a);
    r[a] = xi[a] - cornerOffset(s[0], a);
  }
  if (dim == 2) {
    const double det = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    lambda[1] = (r[0] * e[1][1] - e[0][1] * r[1]) / det;
    lambda[2] = (e[0][0] * r[1] - r[0] * e[1][0]) / det;
  } else {
    auto det3 = [](const double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double det = det3(e);
    for (int k = 0; k < 3; ++k) {  // Cramer's rule: column k replaced by r
      double m[3][3];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) m[a][c] = c == k ? r[a] : e[a][c];
      lambda[k + 1] = det3(m) / det;
    }
  }
  lambda[0] = 1.0;
  for (int k = 1; k <= dim; ++k) lambda[0] -= lambda[k];
}

}  // namespace

const std::vector<std::array<int, 4>>& boxSimplexCorners(int dim, int parity) {
  if (dim == 2) return squareTriangles;
  return parity % 2 == 0 ? evenCubeTets : oddCubeTets;
}

long long BoxGrid::numVertices() const {
  long long count = 1;
  for (int a = 0; a < dim; ++a) count *= cells[a] + 1;
  return count;
}

void BoxGrid::vertexCoordinates(long long vertex, double* x) const {
  for (int a = 0; a < dim; ++a) {
    const long long index = vertex % (cells[a] + 1);
    vertex /= cells[a] + 1;
    x[a] = lengths[a] * double(index) / double(cells[a]);  // division last: far faces land exactly on L
  }
}

long long BoxGrid::vertexAt(const double* x) const {
  long long id = 0, stride = 1;
  for (int a = 0; a < dim; ++a) {
    const double t = x[a] / lengths[a] * double(cells[a]);
    const double index = std::round(t);
    if (std::abs(t - index) > 1e-8 || index < 0 || index > double(cells[a])) return -1;
    id += stride * static_cast<long long>(index);
    stride *= cells[a] + 1;
  }
  return id;
}

void BoxGrid::interpolation(const double* x, long long* vertices, double* weights) const {
  long long box[3] = {0, 0, 0};
  double xi[3] = {0, 0, 0};
  for (int a = 0; a < dim; ++a) {
    const double t = std::clamp(x[a] / lengths[a], 0.0, 1.0) * double(cells[a]);
    box[a] = std::min(static_cast<long long>(std::floor(t)), cells[a] - 1);
    xi[a] = std::clamp(t - double(box[a]), 0.0, 1.0);
  }
  boxSimplexInterpolation(dim, cells, box, xi, vertices, weights);
}

void boxSimplexInterpolation(int dim, const std::array<long long, 3>& cells, const long long* box, const double* xi,
                             long long* vertices, double* weights) {
  // The simplex whose smallest barycentric coordinate is largest holds xi.
  const auto& simplices = boxSimplexCorners(dim, static_cast<int>((box[0] + box[1] + (dim == 3 ? box[2] : 0)) % 2));
  double best[4] = {}, bestMin = -1e300;
  const std::array<int, 4>* chosen = nullptr;
  for (const auto& s : simplices) {
    double lambda[4];
    barycentric(dim, s, xi, lambda);
    const double smallest = *std::min_element(lambda, lambda + dim + 1);
    if (smallest > bestMin) {
      bestMin = smallest;
      chosen = &s;
      std::copy(lambda, lambda + dim + 1, best);
    }
  }
  double sum = 0.0;
  for (int k = 0; k <= dim; ++k) sum += best[k] = std::max(best[k], 0.0);
  for (int k = 0; k <= dim; ++k) {
    long long id = 0, stride = 1;
    for (int a = 0; a < dim; ++a) {
      id += stride * (box[a] + cornerOffset((*chosen)[k], a));
      stride *= cells[a] + 1;
    }
    vertices[k] = id;
    weights[k] = best[k] / sum;
  }
}

std::shared_ptr<const GeometricGrid> BoxGrid::coarser() const { return RectilinearGrid(*this).coarser(); }

std::string BoxGrid::description() const {
  std::string text;
  for (int a = 0; a < dim; ++a) text += (a ? " x " : "") + std::to_string(cells[a]);
  return text + " box grid";
}

}  // namespace signorini

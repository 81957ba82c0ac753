#pragma once
/// \file
/// An isotropic linear elastic material: Young's modulus E and Poisson's ratio nu, and in 2D
/// plane strain or plane stress.

namespace signorini {

struct IsotropicMaterial {
  double youngsModulus = 1.0;
  double poissonRatio = 0.3;
  bool planeStrain = true;  ///< 2D only: false selects plane stress

  /// Lame parameters of the 3D law, which plane strain shares:
  /// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
  /// Throw InputError unless E > 0 and -1 < nu < 1/2.
  double lame1() const;
  double lame2() const;
  /// The lambda a dim-dimensional model uses: plane stress (dim 2, !planeStrain) replaces it by
  /// 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2).
  double effectiveLame1(int dim) const;
};

}  // namespace signorini

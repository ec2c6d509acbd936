// Kernel-gradient renormalisation (Randles & Libersky 1996; SPEC.md "Fluid"):
//   M_i = sum_j V_j grad_i W_ij (x) (x_j - x_i),   L_i = M_i^-1,
// so that sum_j V_j (f_j - f_i) L_i grad_i W_ij is exact for a linear f.
#pragma once

#include <Eigen/LU>

#include "sphcore/types.hpp"

namespace sph {

// The accumulated term of M_i for neighbour j.
inline Mat2 renormalisation_term(double V_j, const Vec2& grad_W_ij, const Vec2& x_ij) {
  return V_j * grad_W_ij * (-x_ij).transpose();
}

// L_i = M_i^-1; the identity where the support is too sparse to invert
// reliably (a lone particle or a thin sheet of spray), since there the
// correction would amplify noise instead of removing a bias.
inline Mat2 renormalisation_matrix(const Mat2& M) {
  constexpr double kSmallestDeterminant = 0.25;  // a full support gives det(M) = 1
  const double det = M.determinant();
  if (!(det > kSmallestDeterminant)) return Mat2::Identity();
  return M.inverse();
}

}  // namespace sph

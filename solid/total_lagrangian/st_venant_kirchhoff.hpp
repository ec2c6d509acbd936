// St Venant-Kirchhoff hyperelasticity in plane strain (e.g. Bonet & Wood,
// "Nonlinear continuum mechanics for finite element analysis", ch. 6):
//   E = (F^T F - I) / 2,  S = lambda tr(E) I + 2 mu E,  P = F S,
//   sigma = P F^T / J,    psi = lambda/2 tr(E)^2 + mu E:E.
// F is the in-plane 2x2 block; F_zz = 1 and E_zz = 0, so the out-of-plane
// stress is S_zz = lambda tr(E) (sigma_zz = S_zz / J). lambda = K - 2G/3 is
// the three-dimensional Lame constant, the same plane-strain convention as
// the Jaumann solid (docs/physics.md, "Jaumann solid": the 1/3 of its deviator), so that both
// models agree for small strains: sigma = lambda tr(eps) I + 2G eps.
// Exact under rigid rotation (objective) and linear elastic for small strain;
// it softens under strong compression (J < ~0.6), which the solver's runaway
// check on J keeps out of reach.
#pragma once

#include <Eigen/LU>

#include "sphcore/types.hpp"

namespace cosph::solid::tl {

using sph::Mat2;

inline double lame_lambda(double K, double G) {
  return K - 2.0 * G / 3.0;
}

struct SvkStress {
  Mat2 P;           // first Piola-Kirchhoff
  Mat2 sigma;       // Cauchy, in-plane
  double sigma_zz;  // Cauchy, out-of-plane
  double psi;       // strain energy per unit reference volume
};

inline SvkStress st_venant_kirchhoff(const Mat2& F, double lambda, double mu) {
  const Mat2 E = 0.5 * (F.transpose() * F - Mat2::Identity());
  const double trace = E.trace();
  const Mat2 S = lambda * trace * Mat2::Identity() + 2.0 * mu * E;
  const Mat2 P = F * S;
  const double J = F.determinant();
  return {P, P * F.transpose() / J, lambda * trace / J,
          0.5 * lambda * trace * trace + mu * E.squaredNorm()};
}

}  // namespace cosph::solid::tl

// Monaghan's artificial viscosity Pi_ij (docs/physics.md, "Artificial
// viscosity"), one formula for every pair: the fluid, the solids and the
// coupler call it, so a fluid-solid pair is damped exactly as a pair inside
// one phase.
#pragma once

#include <algorithm>
#include <cmath>

#include "sphcore/types.hpp"

namespace sph {

// Monaghan's artificial viscosity Pi_ij; zero for receding pairs (v_ij . x_ij >= 0).
// h_ij, c_ij, rho_ij are pair averages.
inline double artificial_viscosity(const Vec2& x_ij, const Vec2& v_ij, double h_ij, double c_ij,
                                   double rho_ij, double A, double B) {
  const double v_dot_x = v_ij.dot(x_ij);
  if (v_dot_x >= 0.0) return 0.0;
  // theta_ij = h_ij v.x / d, d = r^2 + 0.01 h_ij^2, over one division: the
  // two in a row were the latency that set the pace of the solid's pair loop.
  const double h_v_dot_x = h_ij * v_dot_x;
  const double d = x_ij.squaredNorm() + 0.01 * h_ij * h_ij;
  return (-A * c_ij * h_v_dot_x * d + B * h_v_dot_x * h_v_dot_x) / (d * d * rho_ij);
}

// The same Pi_ij for pairs that share h and c (one fluid), with one division
// and no branch: in flowing water whether a pair approaches is a coin toss,
// and the mispredicted branch of artificial_viscosity() costs more than
// computing Pi for every pair (docs/performance.md). In a bending solid the
// pattern is regular and the branch wins.
// Equal to artificial_viscosity() to round-off; exactly +0 for receding pairs,
// where h v_ij . x_ij is clamped to 0.
//   Pi_ij = (-A c h v.x d + B (h v.x)^2) / (d^2 rho_ij),  d = r^2 + 0.01 h^2.
class UniformArtificialViscosity {
 public:
  UniformArtificialViscosity(double h, double c, double A, double B)
      : h_(h), minus_A_c_(-A * c), B_(B), eta2_(0.01 * h * h) {}

  double operator()(const Vec2& x_ij, const Vec2& v_ij, double rho_ij) const {
    const double h_v_dot_x = h_ * std::min(v_ij.dot(x_ij), 0.0);
    const double d = x_ij.squaredNorm() + eta2_;
    return (minus_A_c_ * h_v_dot_x * d + B_ * h_v_dot_x * h_v_dot_x) / (d * d * rho_ij);
  }

 private:
  double h_, minus_A_c_, B_, eta2_;
};

}  // namespace sph

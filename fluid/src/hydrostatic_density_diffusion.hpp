// Density diffusion with the hydrostatic part removed (Fourtakas, Dominguez,
// Vacondio & Rogers 2019, Computers & Fluids 190:346, "Local uniform stencil
// (LUST) boundary condition for arbitrary 3-D boundaries in parallel
// smoothed particle hydrodynamics (SPH) models"; DualSPHysics's
// DDT2), in place of delta-SPH's correction by renormalised gradients:
//   drho_i/dt += delta h c0 sum_j V_j psi_ij . grad_i W_ij,
//   psi_ij = 2 (rho_ji^T - rho_ji^H) (x_j - x_i) / r_ij^2,
//   rho_ji^T = rho_j - rho_i,
//   rho_ji^H = rho0 ( (1 + rho0 g z_ij / C_B)^(1/gamma) - 1 ),  C_B = rho0 c0^2 / gamma,
// the density difference hydrostatic pressure alone would give, z_ij = z_i - z_j
// measured up (against gravity). What diffuses is the dynamic part of the
// density only, and no gradient needs computing.
#pragma once

#include <cmath>

#include "equation_of_state.hpp"
#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Vec2;

class HydrostaticDensityDifference {
 public:
  HydrostaticDensityDifference(const Vec2& gravity, const TaitEquationOfState& eos)
      : rho0_(eos.rho0()), minus_rho0_g_over_CB_(-eos.rho0() * gravity / eos.P0()) {}

  // rho_ji^H; rho0 g z_ij = -rho0 g_vector . x_ij.
  double operator()(const Vec2& x_ij) const {
    return rho0_ *
           (std::pow(1.0 + minus_rho0_g_over_CB_.dot(x_ij), 1.0 / TaitEquationOfState::kGamma) -
            1.0);
  }

 private:
  double rho0_;
  Vec2 minus_rho0_g_over_CB_;
};

// One pair's share of the sum, without the factor delta h c0 (as
// density_diffusion_pair of density_diffusion.hpp): with grad_i W_ij = F_ij x_ij,
// psi_ij . grad_i W_ij = -2 (rho_ji^T - rho_ji^H) F_ij.
inline double hydrostatic_density_diffusion_pair(double rho_i, double rho_j,
                                                 double rho_hydrostatic_ji, double F_ij,
                                                 double V_j) {
  return -2.0 * V_j * (rho_j - rho_i - rho_hydrostatic_ji) * F_ij;
}

}  // namespace cosph::fluid

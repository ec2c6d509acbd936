#include "tl_dynamics.hpp"

#include "clamp_reach.hpp"
#include "hourglass_control.hpp"
#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/outer_product_sum.hpp"
#include "sphcore/parallel.hpp"
#include "st_venant_kirchhoff.hpp"

namespace cosph::solid::tl {

void compute_deformation_and_stress(TLParticles& P) {
  sph::parallel_for(in_reach(P), sph::kTeamAtAnySize, [&](long i) {
    if (P.inert[i]) return;  // at rest for good: F = I, no stress
    const Vec2 u_i = P.x[i] - P.X[i];
    sph::OuterProductSum grad_u;
    for (const ReferenceNeighbour& neighbour : P.neighbours[i]) {
      const int j = neighbour.j;
      const Vec2 u_ji = (P.x[j] - P.X[j]) - u_i;
      grad_u.add(P.V0[j] * u_ji, neighbour.grad_W0_tilde);
    }
    const Mat2 F = Mat2::Identity() + grad_u.matrix();
    const SvkStress stress = st_venant_kirchhoff(F, P.lambda[i], P.mu[i]);
    P.F[i] = F;
    P.J[i] = F.determinant();
    P.rho[i] = P.m[i] / (P.V0[i] * P.J[i]);
    P.P_L0[i] = stress.P * P.L0[i];
    P.sigma[i] = stress.sigma;
    P.sigma_zz[i] = stress.sigma_zz;
    P.strain_energy[i] = stress.psi;
  });
}

void compute_accelerations(TLParticles& P, const ForceParameters& par) {
  const bool with_hourglass = par.hourglass_alpha > 0.0;
  sph::parallel_for(in_reach(P), sph::kTeamAtAnySize, [&](long i) {
    if (P.clamped[i]) {
      P.a[i] = Vec2::Zero();
      return;
    }
    const Vec2 x_i = P.x[i], v_i = P.v[i], X_i = P.X[i];
    const double m_i = P.m[i], V0_i = P.V0[i], c_i = P.c[i];
    const double rho_i = P.rho[i];
    const Mat2& P_L0_i = P.P_L0[i];
    Vec2 f_i = Vec2::Zero();
    for (const ReferenceNeighbour& neighbour : P.neighbours[i]) {
      const int j = neighbour.j;
      const double V0_j = P.V0[j];
      // Stress: V0_i V0_j (P_i L0_i + P_j L0_j) grad0 W_ij.
      f_i += (V0_i * V0_j) * ((P_L0_i + P.P_L0[j]) * neighbour.grad_W0);
      // Artificial viscosity along the current direction.
      const Vec2 x_ij = x_i - P.x[j];
      const double r_ij = x_ij.norm();
      const double rho_j = P.rho[j];
      const double Pi_ij = sph::artificial_viscosity(
          x_ij, v_i - P.v[j], par.h, 0.5 * (c_i + P.c[j]), 0.5 * (rho_i + rho_j), par.A, par.B);
      if (Pi_ij != 0.0 && r_ij > 0.0)
        f_i -= ((m_i * P.m[j]) * Pi_ij * neighbour.dW0_dr / r_ij) * x_ij;
      if (with_hourglass)
        f_i += hourglass_force(par.hourglass_alpha, P.F[i], P.F[j], P.E[i], P.E[j], V0_i, V0_j,
                               neighbour.W0, P.X[j] - X_i, -x_ij, r_ij);
    }
    P.a[i] = par.gravity + f_i / m_i;
  });
}

}  // namespace cosph::solid::tl

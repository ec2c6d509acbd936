// The shell's forces: Reissner's beam (reissner_beam.hpp) discretised in
// total-Lagrangian SPH along the reference line. With the corrected gradient
// weights G_ij of shell_line.hpp,
//   x'_i = sum_j (x_j - x_i) G_ij,   kappa_i = sum_j (theta_j - theta_i) G_ij,
// the resultants n_i, M_i follow pointwise, and the forces are the exact
// derivatives of the discrete strain energy U = sum_i V_i w_i:
//   m_i dv_i/dt     = sum_j (V_i n_i G_ij - V_j n_j G_ji) + f_ext
//   J_i domega_i/dt = sum_j (V_i M_i G_ij - V_j M_j G_ji) + V_i x'_i x n_i + m_ext
// (the total-Lagrangian SPH of Bonet & Lok 1999 / Vignjevic et al. 2006,
// reduced to a line as in Wu, Zhang & Hu 2024). Pairwise the sums are equal
// and opposite, so linear momentum is kept; with the hourglass control
// (line_hourglass.hpp) and kick-drift-kick the scheme is symplectic.
#pragma once

#include "shell_particles.hpp"
#include "shell_section.hpp"

namespace cosph::solid::shell {

struct ShellForceParameters {
  ShellSection section;
  double phi0;             // reference angle of the line's tangent
  double hourglass_alpha;  // line_hourglass.hpp; 0: none
  double ds;               // the particles' spacing along the line
};

// x', kappa, N, Q, M and the strain energy of every particle.
void compute_strains(ShellParticles& P, const ShellForceParameters& parameters);

// a and alpha from the strains (compute_strains first); zero for clamped.
void compute_accelerations(ShellParticles& P, const ShellForceParameters& parameters);

}  // namespace cosph::solid::shell

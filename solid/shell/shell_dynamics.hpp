// The shell's forces: Reissner's beam (reissner_beam.hpp) in total-Lagrangian
// SPH along the reference line, with its strains taken at stress points
// midway between neighbouring particles (Dyka & Ingel 1995, Comput. Struct.
// 57; Randles & Libersky 2000, IJNME 48). At the stress point s between
// particles i and j = i + 1, ds apart, the corrected SPH gradient over the
// two particles its kernel reaches, and their mean, give
//   x'_s = (x_j - x_i) / ds,  kappa_s = (theta_j - theta_i) / ds,
//   phi_s = phi0_s + (theta_i + theta_j) / 2,
// phi0_s the reference angle of the chord from i to j (of the line, when it
// is straight),
// and the resultants n_s, M_s follow pointwise. The forces are the exact
// derivatives of the discrete strain energy U = sum_s ds w_s:
//   f_i += n_s,  f_j -= n_s,
//   m_i += M_s + ds/2 x'_s x n_s,  m_j += -M_s + ds/2 x'_s x n_s.
// Equal and opposite in each pair: momentum is kept; with kick-drift-kick the
// scheme is symplectic. In the linear limit this is the two-node Timoshenko
// element with one-point (reduced) integration, free of shear locking.
//
// Zero-energy modes: the particle-centred SPH gradient of a line takes its
// differences over +-1 and +-2 spacings and does not see a zigzag
// (x_j = x_i + (-1)^j u); its near-zero-energy modes soften a clamped plate
// at first order in ds, and a pair (hourglass) control stiff enough to stop
// them stiffens the smooth modes too. Between neighbours a zigzag strains
// every stress point: the stress points are the zero-energy-mode control, and
// the scheme has no other.
#pragma once

#include "shell_damping.hpp"
#include "shell_particles.hpp"
#include "shell_section.hpp"

namespace cosph::solid::shell {

struct ShellForceParameters {
  ShellSection section;
  ShellDamping damping;  // none: all zero
};

// x', kappa, N, Q, M and the strain energy at every stress point, and each
// particle's N, Q, M (the mean of its stress points'). N, Q, M carry the
// damping's viscous part (shell_damping.hpp), from the rates of the
// particles' current v and omega; the strain energy is the elastic part.
void compute_strains(ShellParticles& P, const ShellForceParameters& parameters);

// a and alpha from the strains (compute_strains first); zero for clamped.
void compute_accelerations(ShellParticles& P);

}  // namespace cosph::solid::shell

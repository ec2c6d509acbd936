// Hourglass control of the shell's line. The corrected SPH gradient along a
// line sees a zigzag (x_j = x_i + (-1)^j u) as no strain at all: its central
// differences skip every other particle, so the zigzag costs no energy and
// would grow unchecked. Each neighbour pair is penalised for the part of its
// chord that the mean of the two particles' gradients does not predict
// (Ganzenmueller 2015, CMAME 286, adapted to a line):
//   delta_ij = (x_j - x_i) - (x'_i + x'_j) / 2 S_ij
//   f_i += alpha K V_i V_j W_ij / S_ij^2 delta_ij,  f_j -= the same,
//   K = min(GA, EI / ds^2)
// (a zigzag of the mid-line bends the plate at the particles' scale ds: K is
// the bending stiffness at that scale, bounded by the shear stiffness GA; with
// GA alone the control stiffened a plate of ds = 2t by 70 %),
// and for the rotation, with the bending stiffness,
//   dtheta_ij = (theta_j - theta_i) - (kappa_i + kappa_j) / 2 S_ij
//   m_i += alpha EI V_i V_j W_ij / S_ij^2 dtheta_ij,  m_j -= the same.
// Pairwise equal and opposite: momentum is kept. For a smooth field delta is
// -x''' S^3 / 12 + ..., third order: a rigid motion or a uniform curvature
// costs nothing, and the control fades as the resolution grows. Pairs of two
// clamped particles are left out (neither moves).
#pragma once

#include <algorithm>
#include <vector>

#include "shell_particles.hpp"
#include "shell_section.hpp"

namespace cosph::solid::shell {

// Adds the control's forces and moments (not yet divided by mass or inertia).
inline void add_hourglass_control(const ShellParticles& P, const ShellSection& section,
                                  double alpha, double ds, std::vector<Vec2>& force,
                                  std::vector<double>& moment) {
  if (alpha <= 0.0) return;
  const double EI = section.EI(), K = std::min(section.GA(), EI / (ds * ds));
  for (std::size_t i = 0; i < P.size(); ++i) {
    for (const LineNeighbour& b : P.neighbours[i]) {
      const std::size_t j = static_cast<std::size_t>(b.j);
      if (j < i || (P.clamped[i] && P.clamped[j])) continue;  // each moving pair once
      const double weight = alpha * P.V[i] * P.V[j] * b.W / (b.S_ij * b.S_ij);
      const Vec2 delta = (P.x[j] - P.x[i]) - 0.5 * (P.dx_dS[i] + P.dx_dS[j]) * b.S_ij;
      const double dtheta = (P.theta[j] - P.theta[i]) - 0.5 * (P.kappa[i] + P.kappa[j]) * b.S_ij;
      force[i] += weight * K * delta;
      force[j] -= weight * K * delta;
      moment[i] += weight * EI * dtheta;
      moment[j] -= weight * EI * dtheta;
    }
  }
}

}  // namespace cosph::solid::shell

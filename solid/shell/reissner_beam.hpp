// Reissner's geometrically exact beam in the plane (Reissner 1972, ZAMP 23:
// "On one-dimensional finite-strain beam theory: the plane problem"; the 2-D
// reduction of the Uflyand-Mindlin shell of Wu, Zhang & Hu 2024, J. Comput.
// Phys. 113113). With phi = phi0 + theta the director's angle, the frame
//   t = (cos phi, sin phi),  d = (-sin phi, cos phi)
// and the mid-line's tangent x' = dx/dS, the strains are
//   axial eps = x'.t - 1,  shear gamma = x'.d,  curvature kappa = theta'
// and the resultants, linear in them (small strain, any rotation),
//   N = EA eps,  Q = GA gamma,  M = EI kappa,  force n = N t + Q d.
// The strain energy per unit length is (EA eps^2 + GA gamma^2 + EI kappa^2) / 2,
// and its derivative in theta, the moment the force exerts on the director,
// is x' x n (the z-component of the cross product).
#pragma once

#include <cmath>

#include "shell_section.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid::shell {

using sph::Vec2;

struct DirectorFrame {
  Vec2 t, d;  // tangent and normal of the cross-section
  static DirectorFrame at(double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {Vec2(c, s), Vec2(-s, c)};
  }
};

struct BeamResultants {
  double N, Q, M;
  Vec2 n;                // N t + Q d
  double couple;         // x' x n
  double strain_energy;  // per unit reference length
};

inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

inline BeamResultants beam_resultants(const Vec2& dx_dS, double phi, double kappa,
                                      const ShellSection& section) {
  const DirectorFrame frame = DirectorFrame::at(phi);
  const double eps = dx_dS.dot(frame.t) - 1.0;
  const double gamma = dx_dS.dot(frame.d);
  const double N = section.EA() * eps, Q = section.GA() * gamma, M = section.EI() * kappa;
  const Vec2 n = N * frame.t + Q * frame.d;
  return {N, Q, M, n, cross(dx_dS, n), 0.5 * (N * eps + Q * gamma + M * kappa)};
}

}  // namespace cosph::solid::shell

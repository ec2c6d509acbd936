// The shell's particles, struct-of-arrays: one line of particles on the
// plate's mid-surface (in 2-D, its mid-line), each with a position and a
// rotation as degrees of freedom. The reference line (X, S, the neighbour
// lists and their corrected kernel gradients) is fixed when the solver starts.
// Clamped particles neither move nor turn.
#pragma once

#include <cstdint>
#include <vector>

#include "sphcore/types.hpp"

namespace cosph::solid::shell {

using sph::Vec2;

// A neighbour j of particle i along the reference line.
struct LineNeighbour {
  int j;
  double S_ij;  // S_j - S_i, the signed reference distance along the line
  double W;     // the 1-D kernel at |S_ij| (line_kernel.hpp)
  double G;     // corrected gradient weight: d(.)/dS at i ~ sum_j ((.)_j - (.)_i) G
};

struct ShellParticles {
  // Fixed: identity, reference line and inertia (per unit depth).
  std::vector<int> id;
  std::vector<Vec2> X;    // reference position on the mid-line
  std::vector<double> S;  // reference arc length along the line
  std::vector<double> V;  // length of line the particle stands for, ds
  std::vector<double> m;  // rho t ds
  std::vector<double> J;  // rotational inertia rho t^3 / 12 ds
  std::vector<double> c;  // axial sound speed sqrt(E' / rho), E' = E / (1 - nu^2)
  std::vector<std::uint8_t> clamped;
  std::vector<std::vector<LineNeighbour>> neighbours;

  // State: mid-line position and velocity, rotation of the director against
  // the reference (counter-clockwise positive) and its rate.
  std::vector<Vec2> x, v;
  std::vector<double> theta, omega;
  // Imposed from outside (the coupler's share, the end load): linear and
  // angular accelerations.
  std::vector<Vec2> external_a;
  std::vector<double> external_alpha;
  // The total accelerations of the last closing kick (own and imposed; zero
  // for clamped): what the faces' accelerations sent to the coupler are made of.
  std::vector<Vec2> kick_a;
  std::vector<double> kick_alpha;

  // Derived from the state each step (shell_dynamics.hpp).
  std::vector<Vec2> dx_dS;            // the mid-line's tangent, dx/dS
  std::vector<double> kappa;          // d theta / dS
  std::vector<double> N, Q, M;        // axial force, shear force (N/m), bending moment (N m/m)
  std::vector<double> strain_energy;  // per unit reference length, J/m^2
  std::vector<Vec2> a;                // dv/dt from the shell's own forces (zero for clamped)
  std::vector<double> alpha;          // d omega/dt from the shell's own moments

  std::size_t size() const { return x.size(); }

  void resize_derived() {
    const std::size_t n = size();
    dx_dS.assign(n, Vec2::Zero());
    kappa.assign(n, 0.0);
    N.assign(n, 0.0);
    Q.assign(n, 0.0);
    M.assign(n, 0.0);
    strain_energy.assign(n, 0.0);
    a.assign(n, Vec2::Zero());
    alpha.assign(n, 0.0);
    external_a.assign(n, Vec2::Zero());
    external_alpha.assign(n, 0.0);
    kick_a.assign(n, Vec2::Zero());
    kick_alpha.assign(n, 0.0);
  }
};

}  // namespace cosph::solid::shell

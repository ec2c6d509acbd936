// The shell's particles, struct-of-arrays: one line of particles on the
// plate's mid-surface (in 2-D, its mid-line), each with a position and a
// rotation as degrees of freedom, and the stress points between neighbours
// where the strains are taken (shell_dynamics.hpp). The reference line (X, S,
// the stress points) is fixed when the solver starts. Clamped particles
// neither move nor turn.
#pragma once

#include <cstdint>
#include <vector>

#include "sphcore/types.hpp"

namespace cosph::solid::shell {

using sph::Vec2;

// The stress points, one midway between each pair of neighbouring particles
// (i, i + 1) of which at least one is free: the strains, resultants and strain
// energy of the line between them.
struct ShellStressPoints {
  std::vector<int> i;                 // the particle before; the one after is i + 1
  std::vector<double> ds;             // reference length between the two (their chord), m
  std::vector<double> phi0;           // reference angle of the chord
  std::vector<Vec2> dx_dS;            // the mid-line's tangent x'
  std::vector<double> kappa;          // d theta / dS
  std::vector<double> N, Q, M;        // axial force, shear force (N/m), bending moment (N m/m)
  std::vector<Vec2> n;                // force resultant N t + Q d, N/m
  std::vector<double> couple;         // x' x n, N/m
  std::vector<double> strain_energy;  // per unit reference length, J/m^2

  std::size_t size() const { return i.size(); }
  void add(int before, double length, double angle) {
    i.push_back(before);
    ds.push_back(length);
    phi0.push_back(angle);
    dx_dS.emplace_back(Vec2::Zero());
    for (auto* field : {&kappa, &N, &Q, &M, &couple, &strain_energy}) field->push_back(0.0);
    n.emplace_back(Vec2::Zero());
  }
};

struct ShellParticles {
  // Fixed: identity, reference line and inertia (per unit depth).
  std::vector<int> id;
  std::vector<Vec2> X;    // reference position on the mid-line
  std::vector<double> S;  // reference arc length along the line
  // Reference angle of the section's tangent (the director's is phi0 +
  // theta): the mean direction of the particle's chords to its neighbours.
  std::vector<double> phi0;
  std::vector<double> V;  // length of line the particle stands for: ds, ds/2 at the ends
  std::vector<double> m;  // rho t V
  std::vector<double> J;  // rotational inertia rho t^3 / 12 V
  std::vector<double> c;  // axial sound speed sqrt(E' / rho), E' = E / (1 - nu^2)
  std::vector<std::uint8_t> clamped;
  ShellStressPoints stress;

  // State: mid-line position and velocity, rotation of the director against
  // the reference (counter-clockwise positive) and its rate.
  std::vector<Vec2> x, v;
  std::vector<double> theta, omega;
  // Imposed from outside (the coupler's share, the end load): linear and
  // angular accelerations.
  std::vector<Vec2> external_a;
  std::vector<double> external_alpha;
  // The total accelerations of the last closing kick (own and imposed; zero
  // for clamped): what the interface particles' accelerations sent to the coupler are made of.
  std::vector<Vec2> kick_a;
  std::vector<double> kick_alpha;

  // Derived from the state each step (shell_dynamics.hpp).
  std::vector<double> N, Q, M;  // the particle's resultants: the mean of its stress points'
  std::vector<Vec2> a;          // dv/dt from the shell's own forces (zero for clamped)
  std::vector<double> alpha;    // d omega/dt from the shell's own moments

  std::size_t size() const { return x.size(); }

  void resize_derived() {
    const std::size_t n = size();
    N.assign(n, 0.0);
    Q.assign(n, 0.0);
    M.assign(n, 0.0);
    a.assign(n, Vec2::Zero());
    alpha.assign(n, 0.0);
    external_a.assign(n, Vec2::Zero());
    external_alpha.assign(n, 0.0);
    kick_a.assign(n, Vec2::Zero());
    kick_alpha.assign(n, 0.0);
  }
};

}  // namespace cosph::solid::shell

// The total-Lagrangian solid's particles, struct-of-arrays. The reference
// configuration (X, V0, the neighbour lists and their corrected kernel
// gradients) is fixed when the solver starts; only x, v and what derives from
// them change. Clamped particles carry stress but do not move.
#pragma once

#include <cstdint>
#include <vector>

#include "sphcore/types.hpp"

namespace cosph::solid::tl {

using sph::Mat2;
using sph::Vec2;

// A neighbour j of particle i in the reference configuration.
struct ReferenceNeighbour {
  int j;
  double W0;           // W(|X_i - X_j|)
  double dW0_dr;       // dW/dr at |X_i - X_j|, for terms that act along the current x_ij
  Vec2 grad_W0;        // grad_i W_ij at the reference positions
  Vec2 grad_W0_tilde;  // L0_i grad_W0: the corrected gradient of F_i
};

struct TLParticles {
  // Fixed: identity, reference configuration and material.
  std::vector<int> id;
  std::vector<Vec2> X;  // reference (initial) position
  std::vector<double> m, V0;
  std::vector<double> lambda, mu, E, c;  // Lame constants, Young's modulus, P-wave speed
  std::vector<std::uint8_t> clamped;
  // Clamped, and so is every reference neighbour: clamped particles never
  // move, so u = 0 all around it for good, F = I and its stress is zero (the
  // values resize_derived gives). No pass visits it, nor does any free
  // particle read it: it is out of reach (clamp_reach.hpp).
  std::vector<std::uint8_t> inert;
  // The passes visit the particles before this one: one past the last that
  // is not inert.
  std::size_t reach_end = static_cast<std::size_t>(-1);
  std::vector<Mat2> L0;  // reference kernel-gradient correction
  std::vector<std::vector<ReferenceNeighbour>> neighbours;

  // State.
  std::vector<Vec2> x, v;
  // Acceleration imposed from outside (the coupler's fluid forces); zero alone.
  std::vector<Vec2> external_a;
  // The total acceleration of the last closing kick (own, gravity and the
  // coupler's; zero for clamped): the moving wall's a_w sent to the coupler.
  std::vector<Vec2> kick_a;

  // Derived from the state each step.
  std::vector<Mat2> F;                // deformation gradient
  std::vector<double> J;              // det F
  std::vector<double> rho;            // m / (V0 J), the density
  std::vector<Mat2> P_L0;             // first Piola-Kirchhoff stress times L0, the momentum flux
  std::vector<Mat2> sigma;            // Cauchy stress P F^T / J (in-plane)
  std::vector<double> sigma_zz;       // out-of-plane Cauchy stress of plane strain
  std::vector<double> strain_energy;  // per unit reference volume
  std::vector<Vec2> a;                // dv/dt from the solid's own forces (zero for clamped)

  std::size_t size() const { return x.size(); }

  void resize_derived() {
    const std::size_t n = size();
    F.assign(n, Mat2::Identity());
    J.assign(n, 1.0);
    rho.resize(n);
    for (std::size_t i = 0; i < n; ++i) rho[i] = m[i] / V0[i];  // J = 1
    P_L0.assign(n, Mat2::Zero());
    sigma.assign(n, Mat2::Zero());
    sigma_zz.assign(n, 0.0);
    strain_energy.assign(n, 0.0);
    a.assign(n, Vec2::Zero());
    external_a.assign(n, Vec2::Zero());
    kick_a.assign(n, Vec2::Zero());
  }
};

}  // namespace cosph::solid::tl

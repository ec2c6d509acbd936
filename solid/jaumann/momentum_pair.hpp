// The Jaumann solid's momentum pair term (docs/physics.md, "Momentum" and
// "Artificial stress"): the bracket of sphcore/momentum_bracket.hpp with
// sigma L for sigma (jaumann_dynamics.hpp), Monaghan's artificial viscosity
// and the artificial stress of Gray, Monaghan & Swift (artificial_stress.hpp),
// worked out once per pair by the momentum pass.
#pragma once

#include <cmath>

#include "jaumann_particles.hpp"
#include "solid_parameters.hpp"
#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/momentum_bracket.hpp"

namespace cosph::solid::jaumann {

// What the momentum bracket takes from particle i, read once for all its pairs
// (inverse_rho as compute_accelerations fills it).
struct PairSide {
  PairSide(const JaumannParticles& P, long i)
      : x(P.x[i]),
        v(P.v[i]),
        m(P.m[i]),
        rho(P.rho[i]),
        c(P.c[i]),
        inverse_rho(P.inverse_rho[i]),
        sigma_L(P.sigma_L[i]),
        R(P.R[i]) {}
  Vec2 x, v;
  double m, rho, c, inverse_rho;
  const Mat2 &sigma_L, &R;
};

enum class ArtificialStressTerm { none, fourth_power, any_power };

// The momentum pair term with sigma L for sigma (jaumann_dynamics.hpp), its
// bracket times grad_i W_ij,
//   ( (sigma_i L_i + sigma_j L_j) / (rho_i rho_j) - Pi_ij I + f_ij^n (R_i + R_j) ) . grad_i W_ij:
// j's contribution to dv_i/dt is m_j times it, i's to dv_j/dt -m_i times it.
// The artificial stress's term is a template argument: its flags, tested in
// every pair, cost measurably in the solid's step.
template <ArtificialStressTerm kArtificialStress>
class MomentumPair {
 public:
  MomentumPair(const JaumannParticles& P, const SolidParameters& par)
      : P_(P),
        h_(par.h),
        A_(par.A),
        B_(par.B),
        n_(par.artificial_stress.exponent),
        inverse_W_dx_(1.0 / sph::kernel::W(par.dx, par.h)) {}

  Vec2 operator()(const PairSide& i, const Neighbour& neighbour) const {
    const int j = neighbour.j;
    const Vec2 x_ij = i.x - P_.x[j];
    const double Pi_ij = sph::artificial_viscosity(x_ij, i.v - P_.v[j], h_, 0.5 * (i.c + P_.c[j]),
                                                   0.5 * (i.rho + P_.rho[j]), A_, B_);
    sph::MomentumBracket b =
        sph::momentum_bracket(i.sigma_L, P_.sigma_L[j], i.inverse_rho * P_.inverse_rho[j], Pi_ij);
    if constexpr (kArtificialStress != ArtificialStressTerm::none) {
      const Mat2& R_j = P_.R[j];
      const double f_n = f_to_the_n(neighbour.W_ij * inverse_W_dx_);
      b.xx += f_n * (i.R(0, 0) + R_j(0, 0));
      b.xy += f_n * (i.R(0, 1) + R_j(0, 1));
      b.yx += f_n * (i.R(1, 0) + R_j(1, 0));
      b.yy += f_n * (i.R(1, 1) + R_j(1, 1));
    }
    return b.times(neighbour.grad_W_ij);
  }

 private:
  // f_ij^n, f_ij = W(r_ij) / W(dx).
  double f_to_the_n(double f) const {
    if constexpr (kArtificialStress == ArtificialStressTerm::fourth_power) {
      const double f2 = f * f;
      return f2 * f2;
    } else {
      return std::pow(f, n_);
    }
  }

  const JaumannParticles& P_;
  double h_, A_, B_, n_, inverse_W_dx_;
};

}  // namespace cosph::solid::jaumann

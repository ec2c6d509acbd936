// The particle shifting of delta-plus-SPH (docs/physics.md, "Particle
// shifting"; Sun, Colagrossi, Marrone & Zhang 2017, Comput. Methods Appl.
// Mech. Engrg. 315:25, "The delta-plus-SPH model: simple procedures for a
// further improvement of the SPH scheme"): each step every water particle is
// moved a little towards where its neighbours are sparser,
//   delta r_i = -CFL Ma (2h)^2 sum_j [1 + R (W_ij / W(dx))^n] grad_i W_ij V_j,
// R = 0.2, n = 4 (the paper's values; the R term pushes apart particles closer
// than dx), Ma = 0.1, the Mach number of the sound speed's rule c0 = 10 U_max,
// and CFL = c0 dt / h, the Courant number of the step taken: the paper's steps
// are all at its CFL, ours are shorter where the acceleration limits them (an
// impact), and a shift per step, not per unit time, would then pile up. The
// sum runs over water and walls.
// Near the free surface the sum would push particles out of the water, where
// the kernel has no neighbours, so (the paper's free-surface treatment) with
// lambda_i the smallest eigenvalue of M_i = sum_j V_j grad_i W_ij (x) (x_j - x_i)
// (Marrone, Colagrossi, Le Touze & Graziani 2010, J. Comput. Phys. 229:3652),
// 1 in a full support:
//   lambda_i < 0.4                    spray, a corner: no shift;
//   lambda_i <= 0.75 (on the surface), or a water neighbour on the surface
//   (within the support of one, its kernel is cut too): only the part along
//   the surface, (I - n_i (x) n_i) delta r_i;
//   otherwise (inside)                delta r_i,
// with the surface normal n_i = nu_i / |nu_i|, nu_i = -L_i sum_j grad_i W_ij V_j,
// L_i = M_i^-1. (On a square lattice the first row has lambda = 0.51, the
// second 0.90 though its kernel reaches past the surface.) As in the paper, no other value is
// corrected for the shift, which is a small fraction of dx per step.
#pragma once

#include <Eigen/LU>
#include <cmath>

#include "sphcore/types.hpp"

namespace cosph::fluid {

using sph::Mat2;
using sph::Vec2;

// One particle's sums over its neighbours.
struct ShiftingSums {
  Vec2 weighted = Vec2::Zero();                 // sum_j [1 + R (W_ij / W(dx))^n] V_j grad_i W_ij
  Vec2 plain = Vec2::Zero();                    // sum_j V_j grad_i W_ij
  Vec2 M_x = Vec2::Zero(), M_y = Vec2::Zero();  // columns of M_i

  // Vg = V_j grad_i W_ij; weight = 1 + R (W_ij / W(dx))^n.
  void add(double weight, const Vec2& Vg, const Vec2& x_ij) {
    weighted += weight * Vg;
    plain += Vg;
    M_x -= x_ij.x() * Vg;
    M_y -= x_ij.y() * Vg;
  }

  Mat2 M() const {
    Mat2 m;
    m << M_x, M_y;
    return m;
  }
};

// The smallest eigenvalue of the symmetric part of M: 1 inside a full
// support, falling towards 0 at a free surface.
inline double smallest_eigenvalue(const Mat2& M) {
  const double mean = 0.5 * (M(0, 0) + M(1, 1)), half_difference = 0.5 * (M(0, 0) - M(1, 1));
  const double off = 0.5 * (M(0, 1) + M(1, 0));
  return mean - std::sqrt(half_difference * half_difference + off * off);
}

class DeltaPlusShifting {
 public:
  static constexpr double kR = 0.2;          // the paper's R
  static constexpr double kMach = 0.1;       // Ma = U_max / c0 of the sound speed's rule
  static constexpr double kSurface = 0.4;    // lambda below: on the free surface
  static constexpr double kInterior = 0.75;  // lambda above: inside the water

  // W_dx = W(dx, h) of the kernel the sums use; c0 dt / h the step's CFL.
  DeltaPlusShifting(double c0_dt_over_h, double h, double W_dx)
      : scale_(-c0_dt_over_h * kMach * (2.0 * h) * (2.0 * h)), inverse_W_dx_(1.0 / W_dx) {}

  // 1 + R (W_ij / W(dx))^n with n = 4.
  double pair_weight(double W_ij) const {
    const double w = W_ij * inverse_W_dx_, w2 = w * w;
    return 1.0 + kR * w2 * w2;
  }

  static bool on_surface(double lambda) { return lambda <= kInterior; }

  // delta r_i, with `near_surface` true if a water neighbour is on_surface.
  Vec2 shift(const ShiftingSums& sums, bool near_surface) const {
    const Vec2 delta_r = scale_ * sums.weighted;
    const Mat2 M = sums.M();
    const double lambda = smallest_eigenvalue(M);
    if (!on_surface(lambda) && !near_surface) return delta_r;
    if (lambda < kSurface || M.determinant() <= 0.0) return Vec2::Zero();
    const Vec2 nu = -(M.inverse() * sums.plain);
    const double length = nu.norm();
    if (length == 0.0) return delta_r;
    const Vec2 n = nu / length;
    return delta_r - n.dot(delta_r) * n;
  }

 private:
  double scale_, inverse_W_dx_;
};

}  // namespace cosph::fluid

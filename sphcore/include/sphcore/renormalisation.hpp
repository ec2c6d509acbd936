// Kernel-gradient renormalisation (Randles & Libersky 1996; docs/physics.md,
// "Kernel"):
//   M_i = sum_j V_j grad_i W_ij (x) (x_j - x_i),   L_i = M_i^-1,
// so that sum_j V_j (f_j - f_i) L_i grad_i W_ij is exact for a linear f.
#pragma once

#include <Eigen/LU>

#include "sphcore/types.hpp"

namespace sph {

// The accumulated term of M_i for neighbour j.
inline Mat2 renormalisation_term(double V_j, const Vec2& grad_W_ij, const Vec2& x_ij) {
  return V_j * grad_W_ij * (-x_ij).transpose();
}

// M_i and the raw velocity gradient sum_j V_j (v_j - v_i) (x) grad_i W_ij,
// summed over a particle's neighbours as 2-vectors (the columns of M, the rows
// of grad v), each one register: summed as Eigen 2x2 matrices they went
// through the stack, and the store-forwarding stalls doubled the cost of the
// pass that sums them (in the fluid and in the solid alike).
struct GradientSums {
  Vec2 M_x = Vec2::Zero(), M_y = Vec2::Zero();    // columns of M
  Vec2 Gv_x = Vec2::Zero(), Gv_y = Vec2::Zero();  // rows of grad v: grad v_x, grad v_y

  // Vg = V_j grad_i W_ij; adds renormalisation_term(V_j, grad_W_ij, x_ij) to M.
  void add(const Vec2& Vg, const Vec2& x_ij, const Vec2& v_ij) {
    M_x -= x_ij.x() * Vg;
    M_y -= x_ij.y() * Vg;
    Gv_x -= v_ij.x() * Vg;
    Gv_y -= v_ij.y() * Vg;
  }
  // Another part of the same sums (a pass that hands pairs' terms on).
  GradientSums& operator+=(const GradientSums& other) {
    M_x += other.M_x, M_y += other.M_y;
    Gv_x += other.Gv_x, Gv_y += other.Gv_y;
    return *this;
  }
  Mat2 M() const {
    Mat2 m;
    m << M_x, M_y;
    return m;
  }
  Mat2 raw_velocity_gradient() const {
    Mat2 g;
    g << Gv_x.transpose(), Gv_y.transpose();
    return g;
  }
};

// L_i = M_i^-1; the identity where the support is too sparse to invert
// reliably (a lone particle or a thin sheet of spray), since there the
// correction would amplify noise instead of removing a bias.
// These matrix forms (with M() and raw_velocity_gradient() above) are the
// rule as written: the particle passes take it by components, through
// renormalised_gradient below, and the tests hold that form to these.
constexpr double kSmallestDeterminant = 0.25;  // a full support gives det(M) = 1
inline bool can_renormalise(const Mat2& M) {
  return M.determinant() > kSmallestDeterminant;
}

inline Mat2 renormalisation_matrix(const Mat2& M) {
  return can_renormalise(M) ? Mat2(M.inverse()) : Mat2::Identity();
}

// L_i, and the velocity gradient grad v_i = (raw gradient) L_i^T, of a
// particle's sums, by components: as renormalisation_matrix(sums.M()) and a
// 2x2 product they went through the stack, and reading each matrix back
// whole from two half-width stores stalled every particle's rate.
struct RenormalisedGradient {
  Mat2 L;
  Mat2 grad_v;        // grad_v(a, b) = dv_a/dx_b
  bool renormalised;  // can_renormalise(M): otherwise L is the identity
};
inline RenormalisedGradient renormalised_gradient(const GradientSums& sums) {
  const double M_xx = sums.M_x.x(), M_yx = sums.M_x.y(), M_xy = sums.M_y.x(), M_yy = sums.M_y.y();
  const double det = M_xx * M_yy - M_yx * M_xy;
  RenormalisedGradient out;
  out.renormalised = det > kSmallestDeterminant;
  double L_xx = 1.0, L_xy = 0.0, L_yx = 0.0, L_yy = 1.0;
  if (out.renormalised) {
    const double inverse_det = 1.0 / det;
    L_xx = M_yy * inverse_det, L_xy = -M_xy * inverse_det;
    L_yx = -M_yx * inverse_det, L_yy = M_xx * inverse_det;
  }
  out.L(0, 0) = L_xx, out.L(0, 1) = L_xy, out.L(1, 0) = L_yx, out.L(1, 1) = L_yy;
  // grad_v(a, b) = sum_c raw(a, c) L(b, c): row a of the raw gradient against row b of L.
  out.grad_v(0, 0) = sums.Gv_x.x() * L_xx + sums.Gv_x.y() * L_xy;
  out.grad_v(0, 1) = sums.Gv_x.x() * L_yx + sums.Gv_x.y() * L_yy;
  out.grad_v(1, 0) = sums.Gv_y.x() * L_xx + sums.Gv_y.y() * L_xy;
  out.grad_v(1, 1) = sums.Gv_y.x() * L_yx + sums.Gv_y.y() * L_yy;
  return out;
}

}  // namespace sph

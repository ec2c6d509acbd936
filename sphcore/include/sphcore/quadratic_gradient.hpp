// Gradient weights that are exact for quadratic fields, at a free surface too:
// a kernel-weighted least-squares fit of the second-order Taylor series
//   f_j - f_i = grad f . d + (1/2) d . H . d,   d = x_j - x_i,
// around particle i (moving-least-squares SPH). It yields one weight vector
// b_ij per neighbour, with grad f_i = sum_j (f_j - f_i) (x) b_ij.
//
// Why: the renormalised kernel gradient (renormalisation.hpp) is exact for
// linear fields only. Bending puts a quadratic displacement into a plate
// (u_x = -kappa x y); at a free surface, where the neighbourhood is one-sided,
// the linear-exact gradient reads the strain as if the particle sat nearer the
// neutral axis (7 % low at 10 particles across, 13 % at 6, for h = 1.3 dx), and
// the plate comes out too soft.
#pragma once

#include <Eigen/Cholesky>

#include "sphcore/types.hpp"

namespace sph {

class QuadraticGradient {
 public:
  // `scale` is a length of the neighbourhood (h): the fit works in d / scale
  // so that its matrix stays well conditioned whatever the units.
  explicit QuadraticGradient(double scale) : inverse_scale_(1.0 / scale) {}

  // Neighbour j with fit weight w_ij (V_j W_ij) at offset d = x_j - x_i.
  void add(double weight, const Vec2& d) {
    const Basis p = basis(d);
    moments_.noalias() += (weight * p).lazyProduct(p.transpose());
  }

  // Factorises the moments; false when the neighbourhood cannot fix a
  // quadratic (too few neighbours, or all on a line).
  bool solve() {
    const Eigen::LDLT<Moments> fit(moments_);
    const auto pivots = fit.vectorD();
    if (fit.info() != Eigen::Success ||
        !(pivots.minCoeff() > kSmallestPivotRatio * pivots.maxCoeff()))
      return false;
    // The gradient is the first two coefficients: rows 0 and 1 of the inverse
    // moments, i.e. (symmetric) its first two columns.
    gradient_row_x_ = fit.solve(Basis::Unit(0));
    gradient_row_y_ = fit.solve(Basis::Unit(1));
    return true;
  }

  // b_ij, after a successful solve(), for the same weight and offset as add().
  Vec2 gradient_weight(double weight, const Vec2& d) const {
    const Basis p = basis(d);
    return (weight * inverse_scale_) * Vec2(gradient_row_x_.dot(p), gradient_row_y_.dot(p));
  }

 private:
  using Basis = Eigen::Matrix<double, 5, 1>;
  using Moments = Eigen::Matrix<double, 5, 5>;
  // Smallest over largest pivot of the moments: a lattice's corner quarter
  // neighbourhood gives about 0.02, a surface one 0.01, the interior 0.2; a
  // row of particles, or two (y^2 then follows from y), gives zero.
  static constexpr double kSmallestPivotRatio = 1e-3;

  Basis basis(const Vec2& d) const {
    const Vec2 s = d * inverse_scale_;
    Basis p;
    p << s.x(), s.y(), 0.5 * s.x() * s.x(), s.x() * s.y(), 0.5 * s.y() * s.y();
    return p;
  }

  double inverse_scale_;
  Moments moments_ = Moments::Zero();
  Basis gradient_row_x_ = Basis::Zero(), gradient_row_y_ = Basis::Zero();
};

}  // namespace sph

// The quadratic-exact gradient (quadratic_gradient.hpp) against the
// renormalised kernel gradient at a free surface, where the neighbourhood is
// one-sided: for the bending field u = (x y, x^2 / 2) both are exact in the
// interior, only the fit stays exact at the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sphcore/kernel.hpp"
#include "sphcore/quadratic_gradient.hpp"
#include "sphcore/renormalisation.hpp"

namespace {

using sph::Mat2;
using sph::Vec2;

constexpr double kDx = 0.1, kH = 1.3 * kDx;

Vec2 bending_field(const Vec2& x) {
  return Vec2(x.x() * x.y(), 0.5 * x.x() * x.x());
}

Mat2 bending_gradient(const Vec2& x) {
  return (Mat2() << x.y(), x.x(), x.x(), 0.0).finished();  // (a, b) = du_a/dx_b
}

// A half-plane lattice y <= 0 seen from the particle at (0, y_i).
std::vector<Vec2> lattice_below_surface() {
  std::vector<Vec2> points;
  for (int row = 0; row < 8; ++row)
    for (int column = -8; column <= 8; ++column)
      points.emplace_back(column * kDx, -(row + 0.5) * kDx);
  return points;
}

struct Gradients {
  Mat2 renormalised, fitted;
};

Gradients gradients_at(const Vec2& x_i, const std::vector<Vec2>& points) {
  const double V = kDx * kDx, reach = sph::kernel::kSupport * kH;
  Mat2 M = Mat2::Zero(), raw = Mat2::Zero();
  sph::QuadraticGradient fit(kH);
  std::vector<Vec2> neighbours;
  for (const Vec2& x_j : points) {
    const Vec2 x_ij = x_i - x_j;
    const double r = x_ij.norm();
    if (r >= reach || r == 0.0) continue;
    const Vec2 grad_W = sph::kernel::grad_W(x_ij, r, kH);
    M += sph::renormalisation_term(V, grad_W, x_ij);
    raw += (bending_field(x_j) - bending_field(x_i)) * (V * grad_W).transpose();
    fit.add(V * sph::kernel::W(r, kH), x_j - x_i);
    neighbours.push_back(x_j);
  }
  Gradients result{raw * sph::renormalisation_matrix(M).transpose(), Mat2::Zero()};
  EXPECT_TRUE(fit.solve());
  for (const Vec2& x_j : neighbours)
    result.fitted +=
        (bending_field(x_j) - bending_field(x_i)) *
        fit.gradient_weight(V * sph::kernel::W((x_j - x_i).norm(), kH), x_j - x_i).transpose();
  return result;
}

TEST(QuadraticGradient, ExactForABendingFieldAtAFreeSurface) {
  const std::vector<Vec2> points = lattice_below_surface();
  const Vec2 surface(0.0, -0.5 * kDx);
  const Gradients at_surface = gradients_at(surface, points);
  EXPECT_LT((at_surface.fitted - bending_gradient(surface)).norm(), 1e-10);
  // The linear-exact gradient misreads the axial strain du_x/dx = y there:
  // it sees the particle nearer the middle of the plate.
  EXPECT_GT(std::abs(at_surface.renormalised(0, 0) - surface.y()), 0.1 * kDx);
}

TEST(QuadraticGradient, ExactInTheInteriorLikeTheRenormalisedGradient) {
  const std::vector<Vec2> points = lattice_below_surface();
  const Vec2 interior(0.0, -4.5 * kDx);
  const Gradients inside = gradients_at(interior, points);
  EXPECT_LT((inside.fitted - bending_gradient(interior)).norm(), 1e-10);
  EXPECT_LT((inside.renormalised - bending_gradient(interior)).norm(), 1e-10);
}

TEST(QuadraticGradient, RefusesANeighbourhoodOnALine) {
  sph::QuadraticGradient fit(kH);
  for (int k = -3; k <= 3; ++k)
    if (k != 0) fit.add(1.0, Vec2(k * kDx, 0.0));
  EXPECT_FALSE(fit.solve());
}

}  // namespace

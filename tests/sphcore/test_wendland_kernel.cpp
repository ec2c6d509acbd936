// The Wendland C2 kernel (wendland_kernel.hpp; docs/physics.md, "Kernel")
// against its defining properties: unit integral over the plane, compact
// support 2h, C2 smoothness at the edge, the slope of its value, the pair
// loops' precomputed forms, and the choice of shape (kernel_shape.hpp) that
// the neighbour list carries.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plane_integral.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/neighbour_list.hpp"
#include "sphcore/wendland_kernel.hpp"

namespace {

using sph::Vec2;
namespace c2 = sph::kernel::wendland_c2;

TEST(WendlandC2, IntegratesToOneOverThePlane) {
  for (const double h : {1.0, 0.013}) {
    const double integral =
        cosph::testing::plane_integral([](double r, double h_) { return c2::W(r, h_); }, h);
    EXPECT_NEAR(integral, 1.0, 1e-4) << "h = " << h;
  }
}

TEST(WendlandC2, VanishesSmoothlyAtTheSupportAndPeaksAtTheCentre) {
  const double h = 0.02, norm = c2::normalisation(h);
  for (const double q : {2.0, 2.5, 10.0}) {
    EXPECT_EQ(c2::W(q * h, h), 0.0) << "q = " << q;
    EXPECT_EQ(c2::dW_dr(q * h, h), 0.0) << "q = " << q;
  }
  // C2 at q = 2: W ~ (2 - q)^4 and dW/dr ~ (2 - q)^3 just inside.
  const double eps = 1e-3;
  const double edge = norm * std::pow(eps / 2.0, 4) * 5.0;
  EXPECT_NEAR(c2::W((2.0 - eps) * h, h), edge, 1e-2 * edge);
  EXPECT_LT(c2::dW_dr((2.0 - eps) * h, h), 0.0);
  EXPECT_LT(std::abs(c2::dW_dr((2.0 - eps) * h, h)), 1e-8 * norm / h);
  EXPECT_DOUBLE_EQ(c2::W(0.0, h), norm);
  EXPECT_EQ(c2::dW_dr(0.0, h), 0.0);
}

TEST(WendlandC2, SlopeMatchesFiniteDifferenceOfValue) {
  const double h = 0.013, step = 1e-6 * h;
  for (double q = 0.01; q < 1.995; q += 0.0137) {
    const double r = q * h;
    const double central = (c2::W(r + step, h) - c2::W(r - step, h)) / (2.0 * step);
    EXPECT_NEAR(c2::dW_dr(r, h), central, 1e-6 * c2::normalisation(h) / h) << "q = " << q;
  }
}

TEST(WendlandC2, PrecomputedFormsMatchThePlainFunctionsAndTheShapeChoosesThem) {
  for (const double h : {0.0013, 0.026, 1.0}) {
    const c2::Value W_of(h);
    const c2::GradientFactor F_of(h);
    const sph::kernel::ShapedValue shaped(sph::kernel::Shape::wendland_c2, h);
    const sph::kernel::ShapedValue cubic(sph::kernel::Shape::cubic_spline, h);
    const double scale = c2::normalisation(h);
    for (double q = 0.01; q < 2.2; q += 0.01) {
      const double r = q * h;
      EXPECT_NEAR(W_of(r), c2::W(r, h), 1e-13 * scale) << "q = " << q;
      EXPECT_EQ(shaped(r), W_of(r)) << "q = " << q;
      EXPECT_NEAR(cubic(r), sph::kernel::W(r, h), 1e-13 * scale) << "q = " << q;
      EXPECT_NEAR(F_of(r) * r, c2::dW_dr(r, h), 1e-13 * scale / h) << "q = " << q;
    }
  }
}

// On a square lattice the Wendland sums are a partition of unity and the
// gradients cancel, and the neighbour list built for the Wendland shape holds
// its F_ij, not the cubic spline's.
TEST(WendlandC2, LatticeSumsAndTheNeighbourListOfItsShape) {
  const double dx = 0.01, h = 1.3 * dx;
  std::vector<Vec2> x;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) x.emplace_back(i * dx, j * dx);
  const long centre = 60;  // (0, 0)
  ASSERT_EQ(x[centre], Vec2::Zero());
  double sum_W = 0.0;
  Vec2 sum_grad = Vec2::Zero();
  for (const Vec2& x_j : x) {
    const double r = x_j.norm();
    sum_W += dx * dx * c2::W(r, h);
    if (r > 0.0) sum_grad += dx * dx * c2::dW_dr(r, h) * (-x_j) / r;
  }
  EXPECT_NEAR(sum_W, 1.0, 2e-2);
  EXPECT_LT(sum_grad.norm(), 1e-12 / h);

  sph::CellGrid grid;
  const double reach = sph::kernel::kSupport * h + 0.25 * h;
  grid.build(x, reach, 2);
  std::vector<Vec2> sorted(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) sorted[k] = x[grid.order()[k]];
  sph::CandidateList candidates;
  candidates.build(grid, sorted, reach, [](long) { return true; });
  sph::NeighbourList list;
  list.build(candidates, sorted, h, sph::kernel::Shape::wendland_c2);
  const c2::GradientFactor F_of(h);
  std::size_t pairs = 0;
  for (long i = 0; i < static_cast<long>(sorted.size()); ++i) {
    const auto neighbours = list.neighbours(i);
    const auto F = list.gradient_factors(i);
    for (std::size_t k = 0; k < neighbours.size(); ++k, ++pairs) {
      const double r = (sorted[i] - sorted[neighbours[k]]).norm();
      EXPECT_DOUBLE_EQ(F[k], F_of(r));
    }
  }
  EXPECT_GT(pairs, 1000u);
}

}  // namespace

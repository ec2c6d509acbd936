// The pair terms every phase shares (pair_terms.hpp; docs/physics.md,
// "Momentum", "Artificial viscosity" and "Von Mises failure"): momentum
// exchange equal and opposite, artificial viscosity only for approaching
// pairs, the von Mises stress of textbook states.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/momentum_bracket.hpp"
#include "sphcore/von_mises.hpp"

namespace {

using sph::Mat2;
using sph::Vec2;

Mat2 random_symmetric(std::mt19937& random, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  const double xy = u(random);
  return (Mat2() << u(random), xy, xy, u(random)).finished();
}

struct Pair {
  double m_i, m_j, rho_i, rho_j, h;
  Mat2 sigma_i, sigma_j;
  Vec2 x_ij, v_ij;
};

Pair random_pair(std::mt19937& random, bool equal_masses) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Pair p;
  p.h = 0.013;
  p.rho_i = 990.0 + 20.0 * u(random);
  p.rho_j = 990.0 + 20.0 * u(random);
  p.m_i = p.rho_i * 1e-4;
  p.m_j = equal_masses ? p.m_i : p.rho_j * 1e-4 * (0.5 + u(random));
  p.sigma_i = random_symmetric(random, 1e4);
  p.sigma_j = random_symmetric(random, 1e4);
  const double r = 2.0 * p.h * (0.01 + 0.98 * u(random)), angle = 6.283 * u(random);
  p.x_ij = r * Vec2(std::cos(angle), std::sin(angle));
  p.v_ij = Vec2(u(random) - 0.5, u(random) - 0.5);
  return p;
}

// m_i a_i (from j) and m_j a_j (from i), each computed from its own side as a
// solver does: grad_j W_ji from x_ji, Pi from (x_ji, v_ji).
std::pair<Vec2, Vec2> forces(const Pair& p) {
  const double c = 20.0, A = 0.05, B = 1.0, rho_ij = 0.5 * (p.rho_i + p.rho_j);
  const double r = p.x_ij.norm();
  const Vec2 x_ji = -p.x_ij, v_ji = -p.v_ij;
  const double Pi_ij = sph::artificial_viscosity(p.x_ij, p.v_ij, p.h, c, rho_ij, A, B);
  const double Pi_ji = sph::artificial_viscosity(x_ji, v_ji, p.h, c, rho_ij, A, B);
  const Vec2 a_i = sph::momentum_pair(p.m_j, p.sigma_i, p.sigma_j, p.rho_i, p.rho_j, Pi_ij,
                                      sph::kernel::grad_W(p.x_ij, r, p.h));
  const Vec2 a_j = sph::momentum_pair(p.m_i, p.sigma_j, p.sigma_i, p.rho_j, p.rho_i, Pi_ji,
                                      sph::kernel::grad_W(x_ji, x_ji.norm(), p.h));
  return {p.m_i * a_i, p.m_j * a_j};
}

TEST(MomentumPair, EqualMassesExchangeExactlyOppositeForces) {
  std::mt19937 random(42);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto [f_i, f_j] = forces(random_pair(random, true));
    ASSERT_NE(f_i, Vec2::Zero());
    // Bitwise: no tolerance.
    ASSERT_EQ(f_i.x(), -f_j.x()) << "trial " << trial;
    ASSERT_EQ(f_i.y(), -f_j.y()) << "trial " << trial;
  }
}

TEST(MomentumPair, UnequalMassesExchangeOppositeForcesToRoundOff) {
  // m_i (m_j b) and m_j (m_i b) may differ in the last bits: floating-point
  // products do not associate (two roundings on each side). The bracket b
  // itself is symmetric bitwise.
  std::mt19937 random(7);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto [f_i, f_j] = forces(random_pair(random, false));
    ASSERT_LE((f_i + f_j).norm(), 2e-15 * f_i.norm()) << "trial " << trial;
  }
}

TEST(MomentumPair, PressureRepelsAndTensionAttracts) {
  const double h = 0.01, m = 0.1, rho = 1000.0;
  const Vec2 x_ij(0.01, 0.0);  // i to the right of j
  const Vec2 grad = sph::kernel::grad_W(x_ij, x_ij.norm(), h);
  const Mat2 pressure = -1e3 * Mat2::Identity(), tension = 1e3 * Mat2::Identity();
  EXPECT_GT(sph::momentum_pair(m, pressure, pressure, rho, rho, 0.0, grad).x(), 0.0);
  EXPECT_LT(sph::momentum_pair(m, tension, tension, rho, rho, 0.0, grad).x(), 0.0);
}

TEST(ArtificialViscosity, ZeroForRecedingPositiveForApproaching) {
  const double h = 0.013, c = 20.0, rho = 1000.0, A = 0.02, B = 0.5;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int approaching = 0, receding = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 x_ij = 0.02 * Vec2(u(random), u(random)), v_ij(u(random), u(random));
    const double Pi = sph::artificial_viscosity(x_ij, v_ij, h, c, rho, A, B);
    if (v_ij.dot(x_ij) >= 0.0) {
      EXPECT_EQ(Pi, 0.0);
      ++receding;
    } else {
      EXPECT_GT(Pi, 0.0);
      // Monaghan's form: -A c theta / rho + B theta^2 / rho.
      const double theta = h * v_ij.dot(x_ij) / (x_ij.squaredNorm() + 0.01 * h * h);
      EXPECT_NEAR(Pi, (-A * c * theta + B * theta * theta) / rho, 1e-12 * Pi);
      ++approaching;
    }
  }
  EXPECT_GT(approaching, 500);
  EXPECT_GT(receding, 500);
  // Head-on and perpendicular: a velocity across the separation does nothing.
  EXPECT_EQ(sph::artificial_viscosity(Vec2(0.01, 0.0), Vec2(0.0, 1.0), h, c, rho, A, B), 0.0);
  EXPECT_GT(sph::artificial_viscosity(Vec2(0.01, 0.0), Vec2(-1.0, 0.0), h, c, rho, A, 0.0), 0.0);
}

// The fluid's branch-free form gives the same Pi to round-off, and exactly
// zero (not -0) for receding and perpendicular pairs.
TEST(ArtificialViscosity, UniformFormIsTheSamePi) {
  const double h = 0.013, c = 20.0, rho = 1000.0, A = 0.02, B = 0.5;
  const sph::UniformArtificialViscosity Pi_of(h, c, A, B);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 x_ij = 0.02 * Vec2(u(random), u(random)), v_ij(u(random), u(random));
    const double expected = sph::artificial_viscosity(x_ij, v_ij, h, c, rho, A, B);
    const double Pi = Pi_of(x_ij, v_ij, rho);
    if (expected == 0.0) {
      EXPECT_EQ(Pi, 0.0);
      EXPECT_FALSE(std::signbit(Pi));
    } else {
      EXPECT_NEAR(Pi, expected, 1e-13 * expected);
    }
  }
  EXPECT_EQ(Pi_of(Vec2(0.01, 0.0), Vec2(0.0, 1.0), rho), 0.0);
}

TEST(VonMises, TextbookStates) {
  for (const double s : {250e6, -3.0, 1e-3}) {
    const Mat2 uniaxial = (Mat2() << s, 0.0, 0.0, 0.0).finished();
    EXPECT_NEAR(sph::von_mises(uniaxial), std::abs(s), 1e-14 * std::abs(s));
    const Mat2 uniaxial_y = (Mat2() << 0.0, 0.0, 0.0, s).finished();
    EXPECT_NEAR(sph::von_mises(uniaxial_y), std::abs(s), 1e-14 * std::abs(s));
    const Mat2 shear = (Mat2() << 0.0, s, s, 0.0).finished();
    EXPECT_NEAR(sph::von_mises(shear), std::sqrt(3.0) * std::abs(s), 1e-14 * std::abs(s));
    // Equal and opposite principal stresses are pure shear seen at 45 degrees.
    const Mat2 rotated_shear = (Mat2() << s, 0.0, 0.0, -s).finished();
    EXPECT_NEAR(sph::von_mises(rotated_shear), std::sqrt(3.0) * std::abs(s), 1e-14 * std::abs(s));
  }
  EXPECT_EQ(sph::von_mises(Mat2::Zero()), 0.0);
}

TEST(VonMises, InPlaneHydrostaticStressFollowsTheSpecFormula) {
  // The formula sqrt((3 s_ab s_ab - s_aa s_bb) / 2) over the 2x2 tensor
  // is the plane-stress von Mises stress: an in-plane pressure -p I (with
  // sigma_zz = 0) is equibiaxial compression and gives |p|, not 0. Only a full
  // 3-D hydrostatic state (sigma_zz = -p as well) has zero von Mises stress.
  // See the report: under plane strain a pressurised solid particle counts as
  // stressed by this formula.
  for (const double p : {1e5, -2.0}) {
    EXPECT_NEAR(sph::von_mises(-p * Mat2::Identity()), std::abs(p), 1e-14 * std::abs(p));
  }
}

TEST(VonMises, InvariantUnderRotation) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 100; ++trial) {
    const Mat2 sigma = random_symmetric(random, 1e6);
    const double angle = 0.0628 * trial;
    const Mat2 R =
        (Mat2() << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)).finished();
    EXPECT_NEAR(sph::von_mises(R * sigma * R.transpose()), sph::von_mises(sigma), 1e-9);
  }
}

}  // namespace

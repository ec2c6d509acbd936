// The cross-phase terms of the coupler (coupler/src/cross_phase_forces), for
// both interface models: momentum conservation to round-off, the pair range
// h_f + h_s, the direction and size of the push of a fluid at pressure P on a
// solid, and (moving_wall) the solid's share in the water's continuity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cross_phase_forces.hpp"
#include "sphcore/kernel.hpp"

namespace {

using cosph::coupler::compute_cross_phase_forces;
using cosph::coupler::CrossPhaseForces;
using cosph::coupler::CrossPhaseParameters;
using cosph::coupler::InterfaceModel;
using sph::Mat2;
using sph::Vec2;

const CrossPhaseParameters kDamped{.model = InterfaceModel::stress_sum, .A = 0.05, .B = 0.5};
const CrossPhaseParameters kWall{.model = InterfaceModel::moving_wall, .A = 0.05, .B = 0.5};

// n particles scattered over [x0, x0 + width] x [0, width], every field random.
sph::InterfaceParticles random_cloud(int n, double x0, double width, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  sph::InterfaceParticles P;
  for (int i = 0; i < n; ++i) {
    Mat2 sigma;
    sigma << -1e4 * u(random), 1e3 * (u(random) - 0.5), 1e3 * (u(random) - 0.5), -1e4 * u(random);
    sigma(1, 0) = sigma(0, 1);
    P.add(i, Vec2(x0 + width * u(random), width * u(random)),
          Vec2(u(random) - 0.5, u(random) - 0.5), sigma, 0.5 + u(random), 900.0 + 300.0 * u(random),
          1e-3 * (1.0 + u(random)), 20.0 + 40.0 * u(random));
  }
  return P;
}

// A dx-spaced block of particles at rest with stress -P I.
sph::InterfaceParticles block(double x_min, double x_max, double height, double dx, double rho,
                              double P) {
  sph::InterfaceParticles out;
  const long columns = std::lround((x_max - x_min) / dx), rows = std::lround(height / dx);
  for (long i = 0; i < columns; ++i)
    for (long j = 0; j < rows; ++j)
      out.add(
          i * rows + j,
          Vec2(x_min + (static_cast<double>(i) + 0.5) * dx, (static_cast<double>(j) + 0.5) * dx),
          Vec2::Zero(), -P * Mat2::Identity(), rho * dx * dx, rho, 1.3 * dx, 20.0);
  return out;
}

TEST(CrossPhaseForces, ConserveMomentumToRoundOff) {
  for (unsigned seed : {1u, 2u, 3u}) {
    // Overlapping clouds: every kind of pair, approaching and receding.
    const auto F = random_cloud(300, 0.0, 0.02, seed);
    const auto S = random_cloud(200, 0.01, 0.02, seed + 100);
    const CrossPhaseForces out = compute_cross_phase_forces(F, S, seed == 2u ? kWall : kDamped);
    ASSERT_GT(out.pairs, 100);
    Vec2 total = Vec2::Zero();
    double scale = 0.0;
    for (std::size_t f = 0; f < F.size(); ++f) {
      total += F.m[f] * out.fluid_a[f];
      scale += F.m[f] * out.fluid_a[f].norm();
    }
    for (std::size_t s = 0; s < S.size(); ++s) {
      total += S.m[s] * out.solid_a[s];
      scale += S.m[s] * out.solid_a[s].norm();
    }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(total.norm(), 1e-12 * scale) << "seed " << seed;
    EXPECT_LT((out.force_on_fluid + out.force_on_solid).norm(), 1e-12 * scale);
    EXPECT_GT(out.force_on_fluid.norm(), 1e-6 * scale);  // the check is not 0 = 0
  }
}

TEST(CrossPhaseForces, PairsAreThoseWithinTheSumOfSmoothingLengths) {
  const auto F = random_cloud(250, 0.0, 0.02, 11);
  const auto S = random_cloud(250, 0.005, 0.02, 12);
  long expected = 0;
  for (std::size_t f = 0; f < F.size(); ++f)
    for (std::size_t s = 0; s < S.size(); ++s)
      expected += (F.x[f] - S.x[s]).norm() < F.h[f] + S.h[s];
  EXPECT_EQ(compute_cross_phase_forces(F, S, kDamped).pairs, expected);
}

// One fluid particle (h = 1 mm) and one solid particle (h = 2 mm): they interact
// up to r = 3 mm = 2 h_fs, beyond 2 min(h) and short of 2 max(h).
TEST(CrossPhaseForces, TwoParticlesInteractJustInsideHfPlusHs) {
  auto pair_at = [](double r) {
    sph::InterfaceParticles F, S;
    F.add(0, Vec2(0.0, 0.0), Vec2::Zero(), -1e3 * Mat2::Identity(), 1.0, 1000.0, 1e-3, 20.0);
    S.add(0, Vec2(r, 0.0), Vec2::Zero(), Mat2::Zero(), 1.0, 1000.0, 2e-3, 20.0);
    return compute_cross_phase_forces(F, S, kDamped);
  };
  for (double r : {2.5e-3, 2.99e-3}) {
    const CrossPhaseForces out = pair_at(r);
    EXPECT_EQ(out.pairs, 1) << "r = " << r;
    EXPECT_LT(out.fluid_a[0].x(), 0.0) << "r = " << r;
  }
  for (double r : {3.01e-3, 3.9e-3}) {
    const CrossPhaseForces out = pair_at(r);
    EXPECT_EQ(out.pairs, 0) << "r = " << r;
    EXPECT_EQ(out.fluid_a[0], Vec2::Zero()) << "r = " << r;
  }
}

// Water at pressure P left of x = 0 against a stress-free solid at rest right of
// it, both over 0 <= y <= L. With sigma_s = 0 the pair sum is
// -P sum_s sum_f V_s V_f grad_s W ~ -P (surface integral of the kernel
// fraction phi over the solid's boundary) = P L / 2 along +x, phi = 1/2 at the
// interface. So the solid is pushed away from the fluid by P L / 2.
TEST(CrossPhaseForces, FluidPressurePushesTheSolidAway) {
  const double P = 1e4, L = 0.03, dx = 1e-3;
  const auto F = block(-0.02, 0.0, L, dx, 1000.0, P);
  const auto S = block(0.0, 0.01, L, dx, 1100.0, 0.0);
  const CrossPhaseForces out = compute_cross_phase_forces(F, S, kDamped);
  EXPECT_GT(out.force_on_solid.x(), 0.0);
  EXPECT_NEAR(out.force_on_solid.x(), 0.5 * P * L, 0.03 * 0.5 * P * L);
  EXPECT_LT(std::abs(out.force_on_solid.y()), 1e-9 * out.force_on_solid.x());
  for (std::size_t s = 0; s < S.size(); ++s) EXPECT_GE(out.solid_a[s].x(), 0.0) << "solid " << s;
  for (std::size_t f = 0; f < F.size(); ++f) EXPECT_LE(out.fluid_a[f].x(), 0.0) << "fluid " << f;
}

// The same water against a solid whose own stress is a tension along the
// interface growing to 100 P, as on the stretched face of a bent plate. As a
// moving wall the solid is pushed by the water's pressure times the wetted
// length, P L (the wall takes the water's pressure, so the kernel fraction 1/2
// counts twice), and not along the interface, whatever its own stress. In the
// study's stress sum the tension's gradient enters the water's momentum.
TEST(CrossPhaseForces, MovingWallFeelsTheWaterPressureNotItsOwnStress) {
  const double P = 1e4, L = 0.03, dx = 1e-3;
  const auto F = block(-0.02, 0.0, L, dx, 1000.0, P);
  auto S = block(0.0, 0.01, L, dx, 1100.0, 0.0);
  for (std::size_t s = 0; s < S.size(); ++s)
    S.sigma[s] << 0.0, 0.0, 0.0, 100.0 * P * S.x[s].y() / L;
  const CrossPhaseForces wall = compute_cross_phase_forces(F, S, kWall);
  EXPECT_NEAR(wall.force_on_solid.x(), P * L, 0.03 * P * L);
  EXPECT_LT(std::abs(wall.force_on_solid.y()), 1e-9 * P * L);
  const CrossPhaseForces stress_sum = compute_cross_phase_forces(F, S, kDamped);
  EXPECT_GT(std::abs(stress_sum.force_on_solid.y()), 0.2 * P * L);  // 0.4 P L here
}

// A solid moving into water at rest compresses it: drho_f > 0 within reach
// of the solid, 0 beyond, and the water's volume shrinks at u L / 2 (the
// kernel's half-space fraction; the fluid's own pairs carry the rest as the
// water starts to move). Receding, the signs turn.
TEST(CrossPhaseForces, MovingWallCompressesTheWaterItMovesInto) {
  const double L = 0.03, dx = 1e-3, u = 0.5;
  const auto F = block(-0.02, 0.0, L, dx, 1000.0, 0.0);
  for (double direction : {-1.0, 1.0}) {
    auto S = block(0.0, 0.01, L, dx, 1100.0, 0.0);
    for (Vec2& v : S.v) v = Vec2(direction * u, 0.0);
    const CrossPhaseForces out = compute_cross_phase_forces(F, S, kWall);
    ASSERT_EQ(out.fluid_drho.size(), F.size());
    double volume_rate = 0.0;
    for (std::size_t f = 0; f < F.size(); ++f) {
      volume_rate += F.m[f] / F.rho[f] * out.fluid_drho[f] / F.rho[f];
      const double gap = -F.x[f].x();
      if (gap > F.h[f] + S.h[0]) {
        EXPECT_EQ(out.fluid_drho[f], 0.0);
      } else if (gap < dx) {
        EXPECT_GT(-direction * out.fluid_drho[f], 0.0) << "fluid " << f;
      }
    }
    EXPECT_NEAR(volume_rate, -direction * 0.5 * u * L, 0.03 * 0.5 * u * L);
  }
}

// Water at rest on a wall that accelerates uniformly with a, and moves the
// water with it: in the wall's frame the water is hydrostatic under g - a, so
// P = rho (g - a) . n d at depth d below the surface (n the wall's inward
// normal, here -y). Adami's extrapolation recovers the pressure at the wall
// particle, P_w = rho (g - a) . n H, to round-off (the field is linear), and
// only with a_w: taken as a fixed wall it is off by rho a . (x_w - x_bar), x_bar
// the kernel-weighted mean position of the water around it.
TEST(CrossPhaseForces, AcceleratingWallGetsTheExtrapolatedPressureOfGMinusA) {
  const double rho = 1000.0, dx = 1e-3, H = 0.02;
  const Vec2 g(0.0, -9.81), a(1.5, 4.0), n(0.0, -1.0);
  const double depth_gradient = rho * (g - a).dot(n);  // dP/d(depth), Pa/m
  sph::InterfaceParticles F;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const Vec2 x((i - 9.5) * dx, (j + 0.5) * dx);
      const double P = depth_gradient * (H - x.y());
      F.add(20 * i + j, x, Vec2::Zero(), -P * Mat2::Identity(), rho * dx * dx, rho, 1.3 * dx, 20.0);
    }
  sph::InterfaceParticles S;
  S.add(0, Vec2(0.0, 0.0), Vec2::Zero(), a, Mat2::Zero(), 1100.0 * dx * dx, 1100.0, 1.3 * dx, 50.0);
  CrossPhaseParameters wall = kWall;
  wall.gravity = g;
  wall.wall_acceleration = true;
  const double expected = depth_gradient * H;
  const CrossPhaseForces moving = compute_cross_phase_forces(F, S, wall);
  ASSERT_EQ(moving.wall_pressure.size(), 1u);
  EXPECT_NEAR(moving.wall_pressure[0], expected, 1e-9 * expected);

  // Without coupling.wall_acceleration the acceleration sent is not used.
  CrossPhaseParameters without = wall;
  without.wall_acceleration = false;
  const double ignored = compute_cross_phase_forces(F, S, without).wall_pressure[0];

  // The same wall sent without its acceleration is taken as fixed.
  S.a.clear();
  const CrossPhaseForces fixed = compute_cross_phase_forces(F, S, wall);
  EXPECT_EQ(ignored, fixed.wall_pressure[0]);
  double weight = 0.0;
  Vec2 x_bar = Vec2::Zero();
  for (const Vec2& x_f : F.x) {
    const double W = sph::kernel::W(x_f.norm(), 1.3 * dx);
    weight += W, x_bar += W * x_f;
  }
  x_bar /= weight;
  const double error = rho * a.dot(S.x[0] - x_bar);  // what leaving a_w out adds
  ASSERT_GT(std::abs(error), 1.0);                   // Pa: a real difference
  EXPECT_NEAR(fixed.wall_pressure[0] - error, expected, 1e-6 * expected);
}

// The study's rule has no share in the continuity: nothing is sent.
TEST(CrossPhaseForces, StressSumSendsNoDensityRate) {
  const auto F = random_cloud(50, 0.0, 0.01, 5);
  const auto S = random_cloud(50, 0.005, 0.01, 6);
  EXPECT_TRUE(compute_cross_phase_forces(F, S, kDamped).fluid_drho.empty());
}

}  // namespace

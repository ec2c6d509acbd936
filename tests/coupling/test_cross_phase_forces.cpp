// The cross-phase terms of the coupler (coupler/src/cross_phase_forces), for
// both interface models: momentum conservation to round-off, the pair range
// h_f + h_s, the direction and size of the push of a fluid at pressure P on a
// solid, and (moving_wall) the solid's share in the water's continuity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "coupler_settings.hpp"
#include "cross_phase_forces.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/kernel_shape.hpp"
#include "sphcore/riemann_dissipation.hpp"
#include "sphcore/wendland_kernel.hpp"

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

// fluid.dissipation riemann: the coupler's pair terms are the water's own
// against its walls (sphcore/riemann_dissipation.hpp). One water particle
// approaching one solid particle below it, under gravity, the solid
// accelerating (coupling.wall_acceleration): the density rate and the
// acceleration written out from the paper's terms. The wall's side of the
// Riemann problem mirrors the water particle, P_s = P_f + rho_f (g - a_s) .
// (x_s - x_f); with one water particle in reach, Adami's P_w is that same
// pressure.
TEST(CrossPhaseForces, RiemannDissipationGivesTheWatersWallTerms) {
  const double rho_f = 1003.0, P_f = 2500.0, c0 = 20.0, rho0 = 1000.0, h = 1.3e-3;
  const double m_s = 2.2e-3, rho_s = 1100.0, V_s = m_s / rho_s;
  const Vec2 x_f(0.0, 0.0), x_s(0.3e-3, -0.9e-3), g(0.0, -9.81), a_s(1.5, 40.0);
  const auto water_moving_at = [&](const Vec2& v_f) {
    sph::InterfaceParticles F;
    F.add(0, x_f, v_f, -P_f * Mat2::Identity(), rho_f * 1e-6, rho_f, h, c0);
    return F;
  };
  sph::InterfaceParticles S;
  S.add(0, x_s, Vec2::Zero(), a_s, Mat2::Zero(), m_s, rho_s, h, 50.0);
  CrossPhaseParameters riemann = kWall;
  riemann.gravity = g;
  riemann.wall_acceleration = true;
  riemann.riemann_dissipation = true;
  riemann.rho0 = rho0;
  const Vec2 x_fs = x_f - x_s;
  const double r = x_fs.norm(), dW_dr = sph::kernel::dW_dr(r, h);
  const Vec2 e = x_fs / r;  // from the solid to the water
  const double P_s = P_f + rho_f * (g - a_s).dot(x_s - x_f);
  ASSERT_GT(std::abs(P_f - P_s), 10.0);  // Pa: a real pressure jump across the pair

  // Continuity, the water drifting slowly towards the solid: the central term
  // plus density flowing from the higher pressure to the lower, P_f - P_s over
  // rho0 c0, along dW/dr.
  const Vec2 slow(0.001, -0.003);
  const auto F = water_moving_at(slow);
  const CrossPhaseForces out = compute_cross_phase_forces(F, S, riemann);
  ASSERT_EQ(out.pairs, 1);
  const double central = rho_f * V_s * slow.dot(dW_dr * e);
  const double drho = central + rho_f * V_s * (P_f - P_s) / (rho0 * c0) * dW_dr;
  EXPECT_NEAR(out.fluid_drho[0], drho, 1e-12 * std::abs(drho));
  EXPECT_GT(std::abs(drho - central), 0.2 * std::abs(central));  // the term is felt
  EXPECT_NEAR(compute_cross_phase_forces(F, S, kWall).fluid_drho[0], central,
              1e-12 * std::abs(central));  // and only with riemann

  // Momentum, the water approaching fast: P* = (P_f + P_w) / 2 + rho_f beta
  // (U_f - U_s) / 2, beta = min(3 (U_f - U_s), c0), U_f - U_s = -v_fs . e > 0.
  // With one water particle in reach, Adami's P_w is P_s.
  const Vec2 fast(0.5, -1.5);
  const auto G = water_moving_at(fast);
  const CrossPhaseForces hit = compute_cross_phase_forces(G, S, riemann);
  ASSERT_NEAR(hit.wall_pressure[0], P_s, 1e-9 * P_s);
  const double approach = -fast.dot(e);
  ASSERT_GT(approach, 0.0);
  const double Pi = std::min(3.0 * approach, c0) * approach / rho_f;
  ASSERT_GT(rho_f * Pi, 0.5 * (P_f + P_s) / rho_f);  // the dissipation matters
  const Vec2 a_f = V_s * (-(P_f + P_s) / rho_f - rho_f * Pi) * dW_dr * e;
  EXPECT_LT((hit.fluid_a[0] - a_f).norm(), 1e-12 * a_f.norm());
  EXPECT_LT((m_s * hit.solid_a[0] + G.m[0] * hit.fluid_a[0]).norm(), 1e-12 * G.m[0] * a_f.norm());
}

// Water at rest over a solid floor, hydrostatic under gravity, dx-spaced with
// the floor's particles continuing its lattice below it. The water's own
// Riemann terms (over the water) drain the bottom rows into the water above,
// where the pressure is lower; the floor's terms, its side mirroring each
// water particle, must give exactly that back, as the water's own floor does
// (fluid's test RiemannDissipation.AWallPassesNoDensityToWaterAtRestWithoutGravity,
// and the still tank of StillTankWith). Without them the bottom of a tank
// beside a plate sinks below hydrostatic pressure.
TEST(CrossPhaseForces, RiemannFloorHoldsHydrostaticWaterWithoutDrain) {
  const double rho = 1000.0, c0 = 20.0, dx = 1e-3, h = 1.3 * dx, H = 0.012;
  const Vec2 g(0.0, -9.81);
  const int columns = 16, rows = static_cast<int>(std::lround(H / dx));
  sph::InterfaceParticles F;
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < rows; ++j) {
      const Vec2 x((i + 0.5) * dx, (j + 0.5) * dx);
      F.add(i * rows + j, x, Vec2::Zero(), -rho * 9.81 * (H - x.y()) * Mat2::Identity(),
            rho * dx * dx, rho, h, c0);
    }
  const auto S = block(-0.004, columns * dx + 0.004, 0.003, dx, 1100.0, 0.0);
  sph::InterfaceParticles floor = S;
  for (Vec2& x : floor.x) x.y() -= 0.003;  // below y = 0
  CrossPhaseParameters riemann = kWall;
  riemann.gravity = g;
  riemann.riemann_dissipation = true;
  riemann.rho0 = rho;
  const CrossPhaseForces out = compute_cross_phase_forces(F, floor, riemann);

  // The water's own Riemann density terms, over the water.
  const double inverse_rho0_c0 = 1.0 / (rho * c0);
  double largest = 0.0;
  int checked = 0;
  for (std::size_t f = 0; f < F.size(); ++f) {
    const Vec2 x = F.x[f];
    // The rows the floor reaches (its top row is dx / 2 below y = 0), away
    // from the sides, where the water's own neighbours are missing.
    if (x.x() < 2.0 * h || x.x() > columns * dx - 2.0 * h || x.y() + 0.5 * dx >= 2.0 * h) continue;
    double own = 0.0;
    for (std::size_t j = 0; j < F.size(); ++j) {
      const Vec2 x_fj = x - F.x[j];
      const double r = x_fj.norm();
      if (j == f || r >= 2.0 * h) continue;
      own += sph::riemann_density_dissipation_pair(rho, dx * dx, -F.sigma[f](0, 0),
                                                   -F.sigma[j](0, 0), sph::kernel::dW_dr(r, h) / r,
                                                   x_fj, inverse_rho0_c0);
    }
    ASSERT_LT(own, 0.0) << "water particle " << f;  // the drain the floor must stop
    largest = std::max(largest, -own);
    EXPECT_NEAR(out.fluid_drho[f], -own, 1e-9 * std::abs(own)) << "water particle " << f;
    ++checked;
  }
  EXPECT_GT(checked, 10);
  // The floor at rest passes nothing in the central term: what it gives is all Riemann.
  const double central = compute_cross_phase_forces(F, floor, kWall).fluid_drho[0];
  EXPECT_EQ(central, 0.0);
  EXPECT_GT(largest, 0.0);
}

// With no gravity and the water's pressure rising towards the plate (a flow
// stagnating on it, at rest for an instant), the plate takes no density from
// the water: its side mirrors each water particle, P_s = P_f. Adami's P_w,
// the kernel mean of the water within 2h, lies below the pressure of the
// water beside it: used as the Riemann wall's pressure, that water would
// drain into the plate.
TEST(CrossPhaseForces, RiemannPlatePassesNoDensityToWaterAtRestWithoutGravity) {
  const double rho = 1000.0, c0 = 20.0, dx = 1e-3, L = 0.007, k = 2.0e7;  // Pa/m^2
  sph::InterfaceParticles F;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 12; ++j) {
      const Vec2 x(-(i + 0.5) * dx, (j + 0.5) * dx);
      const double P = k * (x.x() + L) * (x.x() + L);
      F.add(i * 12 + j, x, Vec2::Zero(), -P * Mat2::Identity(), rho * dx * dx, rho, 1.3 * dx, c0);
    }
  const auto S = block(0.0, 0.003, 0.012, dx, 1100.0, 0.0);
  CrossPhaseParameters riemann = kWall;
  riemann.riemann_dissipation = true;
  riemann.rho0 = rho;
  const CrossPhaseForces out = compute_cross_phase_forces(F, S, riemann);
  // The setting: the plate's extrapolated pressure, on the middle row next to
  // the water, lies below that of the water beside it.
  const int water_beside = 6, plate_beside = 6;  // x = -dx/2 and +dx/2, y = 6.5 dx
  ASSERT_EQ(F.x[water_beside].y(), S.x[plate_beside].y());
  ASSERT_LT(out.wall_pressure[plate_beside], -F.sigma[water_beside](0, 0));
  for (std::size_t f = 0; f < F.size(); ++f)
    EXPECT_EQ(out.fluid_drho[f], 0.0) << "water particle " << f;
}

// The coupler takes the water's dissipation from the case, as the fluid reads
// it, for the moving wall only: the stress sum keeps its own viscosity.
TEST(CrossPhaseForces, TheCaseRiemannDissipationReachesTheMovingWall) {
  const std::string plate = std::string(COSPH_SOURCE_DIR) + "/cases/elastic_plate.pbtxt";
  const auto cross_phase = [&](const std::vector<std::string>& settings) {
    return cosph::coupler::read_coupler_settings(sph::load_case(plate, settings)).cross_phase;
  };
  EXPECT_TRUE(cross_phase({}).riemann_dissipation);
  EXPECT_FALSE(cross_phase({"fluid.dissipation=delta_sph"}).riemann_dissipation);
  EXPECT_FALSE(cross_phase({"fluid.dissipation=fourtakas"}).riemann_dissipation);
  const CrossPhaseParameters riemann = cross_phase({"fluid.dissipation=riemann"});
  EXPECT_TRUE(riemann.riemann_dissipation);
  EXPECT_EQ(riemann.rho0, sph::load_case(plate, {}).config.fluid().density());
  EXPECT_FALSE(cross_phase({"fluid.dissipation=riemann", "coupling.interface=stress_sum"})
                   .riemann_dissipation);
}

// fluid.wall_friction on the moving wall, as against the water's own walls:
// water at rest against a still plate slides along it (u in y). With the
// friction the plate is dragged along with the water and the water braked;
// with "none" nothing acts, and with "normal" nothing acts along the plate
// where its normal is the x axis (away from its ends, whose normals tilt).
// Water running into the plate (u in x) meets the same damping there with
// "normal" as with the friction.
TEST(CrossPhaseForces, MovingWallTakesTheWatersWallFriction) {
  using cosph::fluid::WallFriction;
  const double L = 0.03, dx = 1e-3, u = 0.5;
  const auto S = block(0.0, 0.01, L, dx, 1100.0, 0.0);
  const auto with = [&](WallFriction friction, const Vec2& v) {
    auto F = block(-0.02, 0.0, L, dx, 1000.0, 0.0);
    for (Vec2& v_f : F.v) v_f = v;
    CrossPhaseParameters par = kWall;
    par.wall_friction = friction;
    return compute_cross_phase_forces(F, S, par);
  };
  const Vec2 sliding(0.0, u), running_in(u, 0.0);
  const CrossPhaseForces dragged = with(WallFriction::dissipation, sliding);
  const CrossPhaseForces slid = with(WallFriction::normal, sliding);
  EXPECT_GT(dragged.force_on_solid.y(), 0.0);
  EXPECT_EQ(with(WallFriction::none, sliding).force_on_solid.norm(), 0.0);
  const CrossPhaseForces full = with(WallFriction::dissipation, running_in);
  const CrossPhaseForces normal = with(WallFriction::normal, running_in);
  EXPECT_GT(full.force_on_solid.x(), 0.0);
  EXPECT_EQ(with(WallFriction::none, running_in).force_on_solid.norm(), 0.0);

  const double reach = S.h[0] + 1.3 * dx;
  int away_from_the_ends = 0;
  for (std::size_t s = 0; s < S.size(); ++s) {
    if (std::abs(S.x[s].y() - 0.5 * L) > 0.5 * L - 2.0 * reach) continue;
    if (S.x[s].x() < dx) {  // the first column: within reach of the water
      EXPECT_GT(dragged.solid_a[s].y(), 0.0) << "solid " << s;
    }
    EXPECT_NEAR(slid.solid_a[s].y(), 0.0, 1e-9 * std::abs(dragged.solid_a[s].y())) << "solid " << s;
    EXPECT_NEAR(normal.solid_a[s].x(), full.solid_a[s].x(), 1e-9 * std::abs(full.solid_a[s].x()))
        << "solid " << s;
    ++away_from_the_ends;
  }
  EXPECT_GT(away_from_the_ends, 0);
}

// The coupler takes the water's wall friction from the case, for the moving
// wall only.
TEST(CrossPhaseForces, TheCaseWallFrictionReachesTheMovingWall) {
  using cosph::fluid::WallFriction;
  const std::string plate = std::string(COSPH_SOURCE_DIR) + "/cases/elastic_plate.pbtxt";
  const auto friction = [&](const std::vector<std::string>& settings) {
    return cosph::coupler::read_coupler_settings(sph::load_case(plate, settings))
        .cross_phase.wall_friction;
  };
  EXPECT_EQ(friction({}), WallFriction::normal);
  EXPECT_EQ(friction({"fluid.wall_friction=dissipation"}), WallFriction::dissipation);
  EXPECT_EQ(friction({"fluid.wall_friction=none"}), WallFriction::none);
  EXPECT_EQ(friction({"fluid.wall_friction=normal"}), WallFriction::normal);
  EXPECT_EQ(friction({"fluid.wall_friction=normal", "coupling.interface=stress_sum"}),
            WallFriction::dissipation);
}

// A kernel's W(r, h) and dW/dr(r, h), to write the moving wall's terms out.
struct KernelFunctions {
  double (*W)(double, double);
  double (*dW_dr)(double, double);
};
const KernelFunctions kCubicSpline{sph::kernel::W, sph::kernel::dW_dr};
const KernelFunctions kWendlandC2{sph::kernel::wendland_c2::W, sph::kernel::wendland_c2::dW_dr};

// The moving wall's terms for one solid particle at x_s moving at v_s, each
// water particle of F in its reach having that one pair, written out with
// kernel k (Adami's P_w; momentum and continuity; with rho0 c0 > 0 the
// Riemann density term against the wall's side mirroring the water particle).
struct WallTerms {
  double P_w = 0.0;
  std::vector<Vec2> a_f;
  std::vector<double> drho_f;
  long pairs = 0;
};
WallTerms moving_wall_terms(const sph::InterfaceParticles& F, const Vec2& x_s, const Vec2& v_s,
                            double V_s, double h_s, const Vec2& g, const KernelFunctions& k,
                            double rho0_c0) {
  WallTerms out;
  double weight = 0.0, pressure = 0.0;
  Vec2 moment = Vec2::Zero();
  for (std::size_t f = 0; f < F.size(); ++f) {
    const double h = 0.5 * (F.h[f] + h_s), W = k.W((F.x[f] - x_s).norm(), h);
    weight += W;
    pressure += -F.sigma[f](0, 0) * W;
    moment += F.rho[f] * W * (x_s - F.x[f]);
  }
  out.P_w = (pressure + g.dot(moment)) / weight;
  for (std::size_t f = 0; f < F.size(); ++f) {
    const Vec2 x_fs = F.x[f] - x_s;
    const double r = x_fs.norm(), h = 0.5 * (F.h[f] + h_s), rho = F.rho[f];
    const double P_f = -F.sigma[f](0, 0), dW_dr = r < 2.0 * h ? k.dW_dr(r, h) : 0.0;
    out.pairs += r < 2.0 * h ? 1 : 0;
    const Vec2 grad_W = dW_dr * x_fs / r;
    out.a_f.push_back(V_s * (-(P_f + out.P_w) / rho) * grad_W);
    double drho = rho * V_s * (F.v[f] - v_s).dot(grad_W);
    if (rho0_c0 > 0.0) {
      const double P_s = P_f + rho * g.dot(x_s - F.x[f]);
      drho += rho * V_s * (P_f - P_s) / rho0_c0 * dW_dr;
    }
    out.drho_f.push_back(drho);
  }
  return out;
}

// fluid.kernel wendland_c2 with h = 2 dx (the quiet-pressure option): the
// moving wall takes the water's kernel for P_w, the momentum and continuity
// pairs and the Riemann density term, within its support 2 h_fs, h_fs the
// mean of the two sides' h. Water with a pressure gradient across it,
// receding from one solid particle below it (so that neither dissipation's
// Pi acts): the coupler's terms against the same terms written out with the
// Wendland C2, and against the cubic spline's, which differ.
TEST(CrossPhaseForces, WendlandMovingWallTakesTheWatersKernel) {
  const double dx = 2e-3, h_f = 2.0 * dx, h_s = 1.3e-3, c0 = 20.0, rho0 = 1000.0;
  const double m_s = 1.1e-3, rho_s = 1100.0, V_s = m_s / rho_s;
  const Vec2 x_s(0.3e-3, 0.0), v_s(0.05, -0.2), g(0.0, -9.81);
  sph::InterfaceParticles F;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec2 x((i - 2.5) * dx, (j + 0.5) * dx);
      const double P = 800.0 + 3e4 * x.x() - 9810.0 * x.y(), rho = 1000.0 + 2.0 * j;
      F.add(4 * i + j, x, Vec2(0.01 * i, 0.02 * j), -P * Mat2::Identity(), rho * dx * dx, rho, h_f,
            c0);
    }
  sph::InterfaceParticles S;
  S.add(0, x_s, v_s, Mat2::Zero(), m_s, rho_s, h_s, 50.0);
  CrossPhaseParameters wendland = kWall;
  wendland.gravity = g;
  wendland.kernel = sph::kernel::Shape::wendland_c2;
  for (const bool riemann : {false, true}) {
    SCOPED_TRACE(riemann ? "riemann" : "delta_sph");
    CrossPhaseParameters par = wendland;
    par.riemann_dissipation = riemann;
    par.rho0 = rho0;
    const double rho0_c0 = riemann ? rho0 * c0 : 0.0;
    const CrossPhaseForces out = compute_cross_phase_forces(F, S, par);
    const WallTerms expected = moving_wall_terms(F, x_s, v_s, V_s, h_s, g, kWendlandC2, rho0_c0);
    const WallTerms cubic = moving_wall_terms(F, x_s, v_s, V_s, h_s, g, kCubicSpline, rho0_c0);
    ASSERT_GT(expected.pairs, 8);
    ASSERT_LT(expected.pairs, static_cast<long>(F.size()));  // the support is felt
    EXPECT_EQ(out.pairs, expected.pairs);
    EXPECT_NEAR(out.wall_pressure[0], expected.P_w, 1e-12 * expected.P_w);
    EXPECT_GT(std::abs(cubic.P_w - expected.P_w), 1e-4 * expected.P_w);
    for (std::size_t f = 0; f < F.size(); ++f) {
      SCOPED_TRACE("water particle " + std::to_string(f));
      const double a = expected.a_f[f].norm(), drho = std::abs(expected.drho_f[f]);
      EXPECT_LE((out.fluid_a[f] - expected.a_f[f]).norm(), 1e-12 * a);
      EXPECT_NEAR(out.fluid_drho[f], expected.drho_f[f], 1e-12 * drho);
      if (a == 0.0) continue;
      EXPECT_GT((cubic.a_f[f] - expected.a_f[f]).norm(), 1e-3 * a);
      EXPECT_GT(std::abs(cubic.drho_f[f] - expected.drho_f[f]), 1e-3 * drho);
    }
  }
}

// The coupler takes the water's kernel from the case, as the fluid reads it,
// for the moving wall only: the stress sum meets the solid's own (cubic
// spline) pairs.
TEST(CrossPhaseForces, TheCaseKernelReachesTheMovingWall) {
  const std::string plate = std::string(COSPH_SOURCE_DIR) + "/cases/elastic_plate.pbtxt";
  const auto kernel = [&](const std::vector<std::string>& settings) {
    return cosph::coupler::read_coupler_settings(sph::load_case(plate, settings))
        .cross_phase.kernel;
  };
  using sph::kernel::Shape;
  EXPECT_EQ(kernel({}), Shape::wendland_c2);
  EXPECT_EQ(kernel({"fluid.kernel=cubic_spline"}), Shape::cubic_spline);
  EXPECT_EQ(kernel({"fluid.kernel=wendland_c2", "fluid.h_factor=2.0"}), Shape::wendland_c2);
  EXPECT_EQ(
      kernel({"fluid.kernel=wendland_c2", "fluid.h_factor=2.0", "coupling.interface=stress_sum"}),
      Shape::cubic_spline);
  EXPECT_THROW(kernel({"fluid.kernel=quintic"}), sph::ConfigError);
}

// The study's rule has no share in the continuity: nothing is sent.
TEST(CrossPhaseForces, StressSumSendsNoDensityRate) {
  const auto F = random_cloud(50, 0.0, 0.01, 5);
  const auto S = random_cloud(50, 0.005, 0.01, 6);
  EXPECT_TRUE(compute_cross_phase_forces(F, S, kDamped).fluid_drho.empty());
}

}  // namespace

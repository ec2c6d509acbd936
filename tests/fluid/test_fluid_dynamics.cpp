// The fluid's neighbour passes (fluid_dynamics.hpp) on particle sets built by
// hand: the renormalised gradients are exact for linear fields (docs/physics.md,
// "Kernel"), the delta-SPH diffusion vanishes for a linear density field, and
// the pair forces conserve linear momentum to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "equation_of_state.hpp"
#include "fluid_dynamics.hpp"
#include "fluid_test_support.hpp"
#include "sphcore/artificial_viscosity.hpp"
#include "sphcore/momentum_bracket.hpp"
#include "viscous_stress.hpp"

namespace cosph::fluid {
namespace {

using testing::Neighbourhood;
using testing::sort_and_find_neighbours;
using testing::water_parameters;

const Vec2 kGradRho(40.0, -25.0);                                 // kg/m^4
const Mat2 kGradV = (Mat2() << 0.3, -0.2, 0.5, -0.1).finished();  // dv_a/dx_b, 1/s

double linear_density(const Vec2& x) {
  return 1000.0 + kGradRho.dot(x);
}

// A jittered block of water, nx x nx particles of spacing dx from the origin,
// with the linear density and velocity fields above.
FluidParticles linear_block(int nx, double dx, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx);
  FluidParticles P;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nx; ++j) {
      const Vec2 x((i + 0.5) * dx + jitter(random), (j + 0.5) * dx + jitter(random));
      const double rho = linear_density(x);
      P.add(i * nx + j, Kind::water, x, rho, 1000.0 * dx * dx);
      P.v.back() = kGradV * x;
    }
  return P;
}

// Particles whose whole support lies inside the block.
bool well_inside(const Vec2& x, double extent, const FluidParameters& p) {
  const double margin = sph::kernel::kSupport * p.h + 0.2 * p.dx;
  return x.x() > margin && x.y() > margin && x.x() < extent - margin && x.y() < extent - margin;
}

TEST(FluidGradients, RenormalisedGradientsAreExactForLinearFields) {
  const int nx = 24;
  const double dx = 0.01, extent = nx * dx;
  const FluidParameters p = water_parameters(dx);
  FluidParticles P = linear_block(nx, dx, 1);
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  compute_continuity_and_gradients(P, n.pairs, p);

  const Mat2 tau_exact = viscous_stress(p.mu, kGradV);
  int checked = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!well_inside(P.x[i], extent, p)) continue;
    ++checked;
    EXPECT_LT((P.grad_rho[i] - kGradRho).norm(), 1e-10 * kGradRho.norm()) << "particle " << P.id[i];
    EXPECT_LT((P.tau[i] - tau_exact).norm(), 1e-10 * tau_exact.norm()) << "particle " << P.id[i];
  }
  EXPECT_GT(checked, 200);
}

TEST(FluidGradients, DensityDiffusionVanishesForALinearDensityField) {
  // With the exact <grad rho> on every particle, psi_ij . grad_i W_ij is zero
  // pair by pair (docs/physics.md, "Continuity and delta-SPH": the diffusion
  // vanishes for a linear density field), so a still fluid with a linear
  // density gets drho/dt = 0 everywhere, at the free edges too.
  const int nx = 20;
  const double dx = 0.01;
  const FluidParameters p = water_parameters(dx);
  FluidParticles P = linear_block(nx, dx, 2);
  for (Vec2& v : P.v) v.setZero();
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  for (Vec2& g : P.grad_rho) g = kGradRho;
  compute_continuity_and_gradients(P, n.pairs, p);
  // Scale: one pair's share of the diffusion, delta h c0 |grad rho| / h.
  const double scale = p.delta * p.c0 * kGradRho.norm();
  for (std::size_t i = 0; i < P.size(); ++i)
    EXPECT_LT(std::abs(P.drho[i]), 1e-9 * scale) << "particle " << P.id[i];

  // And the term is on: a wrong <grad rho> (zero) makes it non-zero.
  for (Vec2& g : P.grad_rho) g.setZero();
  compute_continuity_and_gradients(P, n.pairs, p);
  double largest = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) largest = std::max(largest, std::abs(P.drho[i]));
  EXPECT_GT(largest, 1e-3 * scale);
}

TEST(FluidMomentum, PairForcesConserveLinearMomentum) {
  // A random cloud of water, no gravity, no walls: every force is a pair force,
  // so sum_i m_i a_i vanishes up to round-off.
  const double dx = 0.01;
  const FluidParameters p = water_parameters(dx);
  const TaitEquationOfState eos(p.rho0, p.c0);
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  FluidParticles P;
  for (int k = 0; k < 600; ++k) {
    const Vec2 x(0.2 * unit(random), 0.2 * unit(random));
    const double rho = 980.0 + 40.0 * unit(random);
    P.add(k, Kind::water, x, rho, rho * dx * dx * (0.8 + 0.4 * unit(random)));
    P.v.back() = Vec2(unit(random) - 0.5, unit(random) - 0.5);
  }
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  compute_continuity_and_gradients(P, n.pairs, p);  // viscous stress tau
  for (std::size_t i = 0; i < P.size(); ++i) P.p[i] = eos.pressure(P.rho[i]);
  compute_accelerations(P, n.pairs, p);

  Vec2 total = Vec2::Zero();
  double magnitude = 0.0;
  double largest_tau = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    total += P.m[i] * P.a[i];
    magnitude += (P.m[i] * P.a[i]).norm();
    largest_tau = std::max(largest_tau, P.tau[i].norm());
  }
  EXPECT_GT(magnitude, 1.0);    // the forces are real (pressures of order 1e5 Pa)
  EXPECT_GT(largest_tau, 0.0);  // and the viscous stress takes part
  EXPECT_LT(total.norm(), 1e-12 * magnitude) << "sum m a = " << total.transpose();
}

// A random cloud of water over a floor of wall particles, a few thousand
// particles: several of sph::OrderedShares' blocks, so shares go both within
// a block and to later ones.
FluidParticles cloud_over_a_floor(const FluidParameters& p, int water) {
  const TaitEquationOfState eos(p.rho0, p.c0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  FluidParticles P;
  const double width = 0.6;
  for (int k = 0; k < water; ++k) {
    const Vec2 x(width * unit(random), 0.3 * unit(random));
    const double rho = 980.0 + 40.0 * unit(random);
    P.add(k, Kind::water, x, rho, rho * p.dx * p.dx * (0.8 + 0.4 * unit(random)));
    P.v.back() = Vec2(unit(random) - 0.5, unit(random) - 0.5);
  }
  for (int k = 0; k * p.dx < width; ++k)
    for (int layer = 1; layer <= 3; ++layer)
      P.add(water + 3 * k + layer, Kind::wall, Vec2(k * p.dx, -layer * p.dx), p.rho0,
            p.rho0 * p.dx * p.dx);
  return P;
}

// sigma = -p I + tau as a matrix, for sph::momentum_pair.
Mat2 stress_matrix(const FluidParticles& P, long i) {
  return -P.p[i] * Mat2::Identity() + P.tau[i];
}

// The pass works each water pair out once and hands the later particle its
// share; the sum it gives is the plain sum of the momentum equation over each
// particle's own neighbours (sph::momentum_pair, the form the coupler uses for
// any two particles), to round-off.
TEST(FluidMomentum, EachPairOnceGivesThePlainSumOverEachParticlesNeighbours) {
  const FluidParameters p = water_parameters(0.01, Vec2(0.0, -9.81));
  const TaitEquationOfState eos(p.rho0, p.c0);
  FluidParticles P = cloud_over_a_floor(p, 3000);
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  compute_continuity_and_gradients(P, n.pairs, p);
  for (std::size_t i = 0; i < P.size(); ++i)
    P.p[i] = P.is_water(i) ? eos.pressure(P.rho[i]) : 1000.0 * (1.0 + std::sin(double(i)));
  compute_accelerations(P, n.pairs, p);

  const sph::UniformArtificialViscosity Pi_of(p.h, p.c0, p.A, p.B);
  double largest = 0.0, worst = 0.0;
  int walls_met = 0;
  for (long i = 0; i < static_cast<long>(P.size()); ++i) {
    if (!P.is_water(i)) {
      EXPECT_EQ(P.a[i], Vec2::Zero());
      continue;
    }
    Vec2 a_i = p.run.gravity;
    const auto neighbours = n.pairs.neighbours(i);
    const auto F = n.pairs.gradient_factors(i);
    for (std::size_t k = 0; k < neighbours.size(); ++k) {
      const int j = neighbours[k];
      walls_met += !P.is_water(j);
      const Vec2 x_ij = P.x[i] - P.x[j];
      const double Pi_ij = Pi_of(x_ij, P.v[i] - P.v[j], 0.5 * (P.rho[i] + P.rho[j]));
      a_i += sph::momentum_pair(P.m[j], stress_matrix(P, i), stress_matrix(P, j), P.rho[i],
                                P.rho[j], Pi_ij, F[k] * x_ij);
    }
    largest = std::max(largest, a_i.norm());
    worst = std::max(worst, (P.a[i] - a_i).norm());
  }
  EXPECT_GT(walls_met, 100);  // the floor takes part
  EXPECT_GT(largest, 1e3);    // the forces are real
  EXPECT_LT(worst, 1e-12 * largest);
}

// The pass finds a particle's later neighbours at the end of its list.
TEST(FluidMomentum, NeighbourListsAreInIndexOrder) {
  const FluidParameters p = water_parameters(0.01);
  FluidParticles P = cloud_over_a_floor(p, 3000);
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  for (long i = 0; i < static_cast<long>(P.size()); ++i) {
    const auto neighbours = n.pairs.neighbours(i);
    ASSERT_TRUE(std::is_sorted(neighbours.begin(), neighbours.end())) << "particle " << i;
  }
}

TEST(FluidMomentum, AnIsolatedParticleFeelsGravityAloneAndIsSpray) {
  const FluidParameters p = water_parameters(0.01, Vec2(0.0, -9.81));
  FluidParticles P;
  P.add(0, Kind::water, Vec2(0.5, 0.5), 1000.0, 0.1);
  Neighbourhood n;
  sort_and_find_neighbours(P, p, n);
  compute_continuity_and_gradients(P, n.pairs, p);
  compute_accelerations(P, n.pairs, p);
  EXPECT_EQ(P.a[0], Vec2(0.0, -9.81));
  EXPECT_EQ(P.drho[0], 0.0);
  EXPECT_TRUE(P.spray[0]);  // nothing around it to renormalise with, no wall
}

}  // namespace
}  // namespace cosph::fluid

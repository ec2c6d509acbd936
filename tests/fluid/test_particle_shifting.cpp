// delta-plus-SPH's particle shifting (particle_shifting.hpp; docs/physics.md,
// "Particle shifting"): no shift on a uniform lattice, a disordered particle
// sent back towards the emptier side, the free-surface rule by lambda, and bad
// names of the new case fields refused naming the field.
#include <gtest/gtest.h>

#include <string>

#include "fluid_dynamics.hpp"
#include "fluid_parameters.hpp"
#include "fluid_test_support.hpp"
#include "particle_shifting.hpp"
#include "sphcore/case_file.hpp"

namespace cosph::fluid {
namespace {

const std::string kDamBreak = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

// A square block of water, n x n particles at spacing dx, at rest and rho0.
FluidParticles water_block(const FluidParameters& par, int n) {
  FluidParticles P;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      P.add(i * n + j, Kind::water, Vec2(i * par.dx, j * par.dx), par.rho0,
            par.rho0 * par.dx * par.dx);
  return P;
}

void shifts_of(FluidParticles& P, const FluidParameters& par) {
  testing::Neighbourhood n;
  testing::sort_and_find_neighbours(P, par, n);
  P.volume.resize(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) P.volume[i] = P.m[i] / P.rho[i];
  compute_particle_shifts(P, n.pairs, par, 0.25 * par.h / par.c0);
}

// A tank: the block's outer three columns and bottom three rows are wall, its
// top is free surface.
FluidParticles lattice_tank(const FluidParameters& par) {
  FluidParticles P = water_block(par, 15);
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.x[i].x() < 0.025 || P.x[i].x() > 0.115 || P.x[i].y() < 0.025) P.kind[i] = Kind::wall;
  return P;
}

TEST(ParticleShifting, VanishesOnAUniformLattice) {
  const FluidParameters par = testing::water_parameters(0.01);
  FluidParticles P = lattice_tank(par);
  shifts_of(P, par);
  for (std::size_t i = 0; i < P.size(); ++i) {
    // Inside, the sums cancel by symmetry; by the surface, the rule forbids
    // shifting along the normal, and along it the lattice gives nothing.
    EXPECT_LT(P.shift[i].norm(), 1e-12 * par.dx) << "at " << P.x[i].transpose();
  }
}

TEST(ParticleShifting, SendsADisplacedParticleBackTowardsItsSite) {
  const FluidParameters par = testing::water_parameters(0.01);
  FluidParticles P = water_block(par, 15);
  const int moved = 7 * 15 + 7;  // the centre particle, at (0.07, 0.07)
  const Vec2 displacement(0.2 * par.dx, 0.1 * par.dx);
  P.x[moved] += displacement;
  shifts_of(P, par);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.id[i] != moved) continue;
    // Away from the neighbours it came close to: back against the displacement.
    EXPECT_LT(P.shift[i].dot(displacement), 0.0) << P.shift[i].transpose();
    // Smaller than the displacement: no overshoot in one step.
    EXPECT_LT(P.shift[i].norm(), 0.5 * displacement.norm());
  }
}

TEST(ParticleShifting, FreeSurfaceRuleByTheSmallestEigenvalue) {
  const double h = 0.013;
  const DeltaPlusShifting shifting(0.25, h, 1.0);
  const double scale = -0.25 * 0.1 * (2.0 * h) * (2.0 * h);
  const auto sums_with = [](double lambda) {
    ShiftingSums sums;
    sums.weighted = Vec2(30.0, 40.0);
    sums.plain = Vec2(0.0, -50.0);  // the water is below: the normal is +y
    sums.M_x = Vec2(1.0, 0.0);
    sums.M_y = Vec2(0.0, lambda);
    return sums;
  };
  // Inside: all of it.
  EXPECT_LT((shifting.shift(sums_with(0.9), false) - scale * Vec2(30.0, 40.0)).norm(), 1e-15);
  // On the surface, or beside water on it: only the part along it.
  EXPECT_LT((shifting.shift(sums_with(0.6), false) - scale * Vec2(30.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((shifting.shift(sums_with(0.9), true) - scale * Vec2(30.0, 0.0)).norm(), 1e-15);
  // Spray, a corner: none.
  EXPECT_EQ(shifting.shift(sums_with(0.3), false), Vec2::Zero());
  EXPECT_DOUBLE_EQ(smallest_eigenvalue((sph::Mat2() << 2.0, 1.0, 1.0, 2.0).finished()), 1.0);
}

TEST(ParticleShifting, WallsFillTheKernelLikeWater) {
  // A particle beside a wall of the same lattice is inside (lambda ~ 1), so
  // the wall does not count as free surface.
  const FluidParameters par = testing::water_parameters(0.01);
  FluidParticles P = water_block(par, 15);
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.x[i].y() < 0.035) P.kind[i] = Kind::wall;
  const int beside_wall = 7 * 15 + 4;  // (0.07, 0.04), displaced up
  P.x[beside_wall] += Vec2(0.0, 0.2 * par.dx);
  shifts_of(P, par);
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.id[i] == beside_wall) {
      EXPECT_LT(P.shift[i].y(), 0.0) << P.shift[i].transpose();
    }
}

TEST(KernelAndShiftingFields, UnknownNamesAreRefusedNamingTheField) {
  for (const auto& [setting, field, name] :
       {std::tuple{"fluid.kernel=wendland", "fluid.kernel", "wendland"},
        std::tuple{"fluid.shifting=delta", "fluid.shifting", "delta"}}) {
    const sph::CaseFile case_file = sph::load_case(kDamBreak, {setting});
    try {
      read_fluid_parameters(case_file);
      ADD_FAILURE() << setting << " was accepted";
    } catch (const sph::ConfigError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find(field), std::string::npos) << what;
      EXPECT_NE(what.find(std::string("'") + name + "'"), std::string::npos) << what;
      EXPECT_NE(what.find(kDamBreak), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace cosph::fluid

// The water's runaway check (FluidSolver::check_state): every way a water
// particle can run away stops the step; a speed between the screen's margin
// and the sound speed does not, and thinned spray leaves the water instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "runaway_spoils.hpp"
#include "sphcore/case_file.hpp"
#include "test_support.hpp"

namespace cosph::fluid {
namespace {

// A tank of water, and a droplet far above it, out of reach of the water and
// of the walls: one particle at this spacing, four at 0.005.
constexpr const char* kTankAndDroplet = R"(
run { end_time: 0.1 gravity { x: 0 y: -9.81 } }
fluid {
  spacing: 0.01
  density: 1000
  water { min { x: 0 y: 0 } max { x: 0.1 y: 0.05 } }
  water { min { x: 0.045 y: 0.15 } max { x: 0.055 y: 0.16 } }
  walls { min { x: -0.03 y: -0.03 } max { x: 0.13 y: 0 } }
  walls { min { x: -0.03 y: 0 } max { x: 0 y: 0.2 } }
  walls { min { x: 0.1 y: 0 } max { x: 0.13 y: 0.2 } }
}
)";

struct TankAndDroplet {
  sph::CaseFile case_file;
  FluidParameters par;
};

TankAndDroplet load_tank_and_droplet(const cosph::testing::ScratchDir& scratch,
                                     const std::vector<std::string>& overrides = {}) {
  cosph::testing::write_text(scratch.file("tank.pbtxt"), kTankAndDroplet);
  sph::CaseFile case_file = sph::load_case(scratch.file("tank.pbtxt"), overrides);
  FluidParameters par = read_fluid_parameters(case_file);
  return {std::move(case_file), par};
}

std::vector<std::size_t> droplet_particles(const FluidParticles& P) {
  std::vector<std::size_t> droplet;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.is_water(i) && P.x[i].y() > 0.1) droplet.push_back(i);
  return droplet;
}

TEST(FluidSolver, EveryKindOfRunawayStopsTheStepAndNothingElseDoes) {
  const cosph::testing::ScratchDir scratch("runaway_check");
  const auto [case_file, par] = load_tank_and_droplet(scratch);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  using Spoil = cosph::testing::Spoil<FluidParticles>;
  const std::vector<Spoil> spoils{
      {"x not finite", [&](FluidParticles& P, std::size_t i) { P.x[i].x() = nan; }, true},
      {"v not finite", [&](FluidParticles& P, std::size_t i) { P.v[i].y() = nan; }, true},
      {"rho below 0.5 rho0", [&](FluidParticles& P, std::size_t i) { P.rho[i] = 0.49 * par.rho0; },
       true},
      {"rho above 2 rho0", [&](FluidParticles& P, std::size_t i) { P.rho[i] = 2.01 * par.rho0; },
       true},
      {"faster than c0",
       [&](FluidParticles& P, std::size_t i) { P.v[i] = Vec2(0.8, -0.6) * 1.001 * par.c0; }, true},
      {"just below c0",
       [&](FluidParticles& P, std::size_t i) { P.v[i] = Vec2(0.8, -0.6) * 0.995 * par.c0; }, false},
  };
  const auto make_solver = [&] { return FluidSolver(case_file, par); };
  std::vector<std::size_t> spoiled;  // in the tank, none of them spray
  {
    const FluidSolver solver = make_solver();
    const FluidParticles& P = solver.particles();
    std::vector<std::size_t> tank;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.is_water(i) && P.x[i].y() < 0.1) tank.push_back(i);
    ASSERT_GT(tank.size(), 2u);
    spoiled = {tank.front(), tank[tank.size() / 2], tank.back()};
    for (const std::size_t i : spoiled) ASSERT_FALSE(P.spray[i]) << i;
  }
  cosph::testing::expect_exactly_the_runaways_stop(make_solver, spoils, spoiled);
}

TEST(FluidSolver, ThinnedSprayLeavesTheWaterAndIsCounted) {
  const cosph::testing::ScratchDir scratch("thinned_spray");
  const auto [case_file, par] = load_tank_and_droplet(scratch, {"fluid.spacing=0.005"});
  FluidSolver solver(case_file, par);
  const long water = solver.gauges().water_particles;
  ASSERT_GE(water, 200);  // so that one particle is under 1 % of the water
  const std::vector<std::size_t> droplet = droplet_particles(solver.particles());
  ASSERT_EQ(droplet.size(), 4u);
  // Only the droplet is spray: the tank's water has walls or dense water in reach.
  for (std::size_t i = 0; i < solver.particles().size(); ++i) {
    if (!solver.particles().is_water(i)) continue;
    EXPECT_EQ(solver.particles().spray[i] == 1, solver.particles().x[i].y() > 0.1) << i;
  }

  FluidParticles& P = solver.particles();
  const int thinned = P.id[droplet[1]];
  P.rho[droplet[1]] = 0.49 * par.rho0;
  ASSERT_NO_THROW(solver.end_step(0.0));
  EXPECT_EQ(solver.spray_removed(), 1);
  EXPECT_EQ(solver.gauges().water_particles, water - 1);
  EXPECT_EQ(std::count(P.id.begin(), P.id.end(), thinned), 0);
  EXPECT_EQ(droplet_particles(P).size(), 3u);
  // The water goes on without it: the grid and the neighbour list are rebuilt.
  ASSERT_NO_THROW(solver.step(0.1 * solver.step_limits().smallest()));
  EXPECT_EQ(solver.gauges().water_particles, water - 1);
}

std::size_t index_of(const FluidParticles& P, int id) {
  return static_cast<std::size_t>(std::find(P.id.begin(), P.id.end(), id) - P.id.begin());
}

TEST(FluidSolver, CouplersAccelerationStaysWithItsParticleThroughAReSort) {
  // It tells which water has the solid in reach, so it must follow the
  // particles when the neighbour grid re-sorts them.
  const cosph::testing::ScratchDir scratch("resort");
  const auto [case_file, par] = load_tank_and_droplet(scratch, {"fluid.spacing=0.005"});
  FluidSolver solver(case_file, par);
  FluidParticles& P = solver.particles();
  const std::vector<std::size_t> droplet = droplet_particles(P);
  const int moved = P.id[droplet.front()], other = P.id[droplet.back()];
  const Vec2 pushed(0.0, 1e-3);
  P.external_a[droplet.front()] = pushed;
  P.x[droplet.front()] += Vec2(0.03, 0.0);  // past the others: the sort must reorder
  const std::size_t before = index_of(P, moved);
  solver.step(1e-6);
  ASSERT_GT(solver.sorts(), 1);
  ASSERT_NE(index_of(P, moved), before);
  EXPECT_EQ(P.external_a[index_of(P, moved)], pushed);
  EXPECT_EQ(P.external_a[index_of(P, other)], Vec2::Zero());
}

TEST(FluidSolver, ThinnedWaterInReachOfTheSolidStops) {
  // The coupler gives an acceleration exactly where a solid particle is in
  // reach: there a low density is the flow's, not spray's.
  const cosph::testing::ScratchDir scratch("spray_at_solid");
  const auto [case_file, par] = load_tank_and_droplet(scratch, {"fluid.spacing=0.005"});
  FluidSolver solver(case_file, par);
  const std::size_t i = droplet_particles(solver.particles()).front();
  solver.particles().external_a[i] = Vec2(0.0, 1e-3);
  solver.particles().rho[i] = 0.49 * par.rho0;
  EXPECT_THROW(solver.end_step(0.0), sph::RunawayError);
  EXPECT_EQ(solver.spray_removed(), 0);
}

TEST(FluidSolver, SprayDenserThanTwiceRho0StillStops) {
  const cosph::testing::ScratchDir scratch("dense_spray");
  const auto [case_file, par] = load_tank_and_droplet(scratch, {"fluid.spacing=0.005"});
  FluidSolver solver(case_file, par);
  solver.particles().rho[droplet_particles(solver.particles()).front()] = 2.01 * par.rho0;
  EXPECT_THROW(solver.end_step(0.0), sph::RunawayError);
}

TEST(FluidSolver, SprayLeavingStepByStepAddsUpPastOnePercent) {
  // A long run's spray adds up; only much water thinning at once is a blow-up.
  const cosph::testing::ScratchDir scratch("spray_adds_up");
  const auto [case_file, par] = load_tank_and_droplet(scratch, {"fluid.spacing=0.005"});
  FluidSolver solver(case_file, par);
  const long water = solver.gauges().water_particles;
  for (int step = 0; step < 3; ++step) {
    FluidParticles& P = solver.particles();
    P.rho[droplet_particles(P).front()] = 0.49 * par.rho0;
    ASSERT_NO_THROW(solver.end_step(0.0)) << step;
  }
  EXPECT_EQ(solver.spray_removed(), 3);
  EXPECT_GT(100 * solver.spray_removed(), water);  // more than 1 % in all
}

TEST(FluidSolver, MoreThanOnePercentOfTheWaterThinnedToSprayStops) {
  // At spacing 0.01 the tank holds 50 water particles: one is 2 % of them,
  // thinned in one step.
  const cosph::testing::ScratchDir scratch("much_spray");
  const auto [case_file, par] = load_tank_and_droplet(scratch);
  FluidSolver solver(case_file, par);
  ASSERT_LT(solver.gauges().water_particles, 100);
  const std::vector<std::size_t> droplet = droplet_particles(solver.particles());
  ASSERT_FALSE(droplet.empty());
  solver.particles().rho[droplet.front()] = 0.49 * par.rho0;
  EXPECT_THROW(solver.end_step(0.0), sph::RunawayError);
}

}  // namespace
}  // namespace cosph::fluid

// The water's runaway check (FluidSolver::check_state): every way a water
// particle can run away stops the step; a speed between the screen's margin
// and the sound speed does not.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "runaway_spoils.hpp"
#include "sphcore/case_file.hpp"
#include "test_support.hpp"

namespace cosph::fluid {
namespace {

constexpr const char* kTank = R"(
run { end_time: 0.1 gravity { x: 0 y: -9.81 } }
fluid {
  spacing: 0.01
  density: 1000
  water { min { x: 0 y: 0 } max { x: 0.1 y: 0.05 } }
  walls { min { x: -0.03 y: -0.03 } max { x: 0.13 y: 0 } }
  walls { min { x: -0.03 y: 0 } max { x: 0 y: 0.08 } }
  walls { min { x: 0.1 y: 0 } max { x: 0.13 y: 0.08 } }
}
)";

TEST(FluidSolver, EveryKindOfRunawayStopsTheStepAndNothingElseDoes) {
  const cosph::testing::ScratchDir scratch("runaway_check");
  cosph::testing::write_text(scratch.file("tank.pbtxt"), kTank);
  const sph::CaseFile case_file = sph::load_case(scratch.file("tank.pbtxt"));
  const FluidParameters par = read_fluid_parameters(case_file);
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
  std::vector<std::size_t> water;
  {
    const FluidSolver solver = make_solver();
    for (std::size_t i = 0; i < solver.particles().size(); ++i)
      if (solver.particles().is_water(i)) water.push_back(i);
  }
  ASSERT_GT(water.size(), 2u);
  cosph::testing::expect_exactly_the_runaways_stop(
      make_solver, spoils, {water.front(), water[water.size() / 2], water.back()});
}

}  // namespace
}  // namespace cosph::fluid

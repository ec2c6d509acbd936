// The water's runaway check (FluidSolver::check_state) screens all particles
// in one vectorised pass before it looks at any one of them. Every way a water
// particle can run away must still stop the step, wherever the particle lies
// in that pass (its first lane, the middle, the loop's remainder); a speed
// between the screen's margin and the sound speed must not.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <vector>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/runaway_error.hpp"
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
  struct Spoil {
    const char* what;
    std::function<void(FluidParticles&, std::size_t)> apply;
    bool stops;
  };
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
  std::vector<std::size_t> water;
  {
    const FluidSolver solver(case_file, par);
    for (std::size_t i = 0; i < solver.particles().size(); ++i)
      if (solver.particles().is_water(i)) water.push_back(i);
  }
  ASSERT_GT(water.size(), 2u);
  for (const std::size_t i : {water.front(), water[water.size() / 2], water.back()})
    for (const Spoil& spoil : spoils) {
      FluidSolver solver(case_file, par);
      spoil.apply(solver.particles(), i);
      if (spoil.stops)
        EXPECT_THROW(solver.end_step(0.0), sph::RunawayError) << spoil.what << ", particle " << i;
      else
        EXPECT_NO_THROW(solver.end_step(0.0)) << spoil.what << ", particle " << i;
    }
}

}  // namespace
}  // namespace cosph::fluid

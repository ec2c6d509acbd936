// A still tank (docs/physics.md, "Walls": the walls must hold the water's
// hydrostatic pressure and let no water through): water 0.4 m wide and H = 0.2 m deep in a
// closed tank, run for half a second from its hydrostatic start.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>

#include "fluid_parameters.hpp"
#include "fluid_solver.hpp"
#include "sphcore/case_file.hpp"
#include "sphcore/gauge.hpp"
#include "test_support.hpp"

namespace cosph::fluid {
namespace {

constexpr double kWidth = 0.4, kDepth = 0.2, kRho0 = 1000.0, kG = 9.81;

constexpr const char* kStillTank = R"(
title: "Still tank"
run {
  end_time: 0.5
  cfl: 0.25
  gravity { x: 0 y: -9.81 }
}
fluid {
  spacing: 0.01
  density: 1000
  viscosity: 1.307e-3
  water { min { x: 0 y: 0 } max { x: 0.4 y: 0.2 } }
  walls { min { x: -0.03 y: -0.03 } max { x: 0.43 y: 0 } }
  walls { min { x: -0.03 y: 0 } max { x: 0 y: 0.3 } }
  walls { min { x: 0.4 y: 0 } max { x: 0.43 y: 0.3 } }
  gauges {
    pressure_probes { x: 0 y: 0.05 }
    pressure_probes { x: 0 y: 0.15 }
    pressure_probes { x: 0.2 y: 0 }
    pressure_probes { x: 0.2 y: 0.27 }
  }
}
)";

struct BandPressure {
  double measured = 0.0, hydrostatic = 0.0;
};

// Mean pressure of the water particles in the bottom band y < 0.05 m, and the
// mean of rho0 g (H - y) at the same particles.
BandPressure bottom_band(const FluidParticles& P) {
  BandPressure band;
  int count = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i) || P.x[i].y() >= 0.05) continue;
    band.measured += P.p[i];
    band.hydrostatic += kRho0 * kG * (kDepth - P.x[i].y());
    ++count;
  }
  band.measured /= count;
  band.hydrostatic /= count;
  return band;
}

TEST(StillTank, HoldsHydrostaticPressureAndKeepsEveryParticle) {
  cosph::testing::ScratchDir dir("still_tank");
  const std::string path = dir.file("still_tank.pbtxt");
  cosph::testing::write_text(path, kStillTank);
  // One thread: the results do not depend on the thread count (each particle
  // sums its own pairs in a fixed order), and on a shared machine OpenMP's
  // busy-waiting barriers make two threads ten times slower, not faster.
  omp_set_num_threads(1);
  const sph::CaseFile case_file = sph::load_case(path);
  const FluidParameters parameters = read_fluid_parameters(case_file);
  FluidSolver solver(case_file, parameters);
  const long water = solver.gauges().water_particles;
  ASSERT_EQ(water, 40 * 20);

  // The pressure still rings with the sound waves of the start (period
  // 4 H / c0 = 0.04 s): average it over the last 0.1 s.
  const double end_time = 0.5, average_from = 0.4;
  BandPressure mean;
  int samples = 0;
  double next_sample = average_from;
  while (solver.time() < end_time - 1e-12) {
    solver.step(std::min(solver.step_limits().smallest(), end_time - solver.time()));
    if (solver.time() >= next_sample) {
      const BandPressure band = bottom_band(solver.particles());
      mean.measured += band.measured;
      mean.hydrostatic += band.hydrostatic;
      ++samples;
      next_sample += 0.005;
    }
  }
  ASSERT_GE(samples, 15);
  mean.measured /= samples;
  mean.hydrostatic /= samples;
  EXPECT_NEAR(mean.measured, mean.hydrostatic, 0.02 * mean.hydrostatic)
      << "mean pressure over y < 0.05 m";

  // Nothing lost, nothing through a wall: every water particle is inside the
  // tank's interior, and the water is (nearly) at rest.
  const FluidParticles& P = solver.particles();
  EXPECT_EQ(solver.gauges().water_particles, water);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!P.is_water(i)) continue;
    EXPECT_TRUE(P.x[i].x() > 0.0 && P.x[i].x() < kWidth && P.x[i].y() > 0.0 &&
                P.x[i].y() < kDepth + 0.05)
        << "water particle " << P.id[i] << " at " << P.x[i].transpose();
  }
  EXPECT_LT(solver.gauges().max_speed, 0.05 * std::sqrt(kG * kDepth));
}

// Runs the still tank to 0.5 s on one thread and calls sample(solver) at
// every step of the last 0.1 s, where the start's sound waves have settled
// enough to average over (as the pressure above).
template <class Sample>
void sample_the_settled_tank(Sample&& sample) {
  cosph::testing::ScratchDir dir("still_tank");
  const std::string path = dir.file("still_tank.pbtxt");
  cosph::testing::write_text(path, kStillTank);
  omp_set_num_threads(1);
  const sph::CaseFile case_file = sph::load_case(path);
  FluidSolver solver(case_file, read_fluid_parameters(case_file));
  const double end_time = 0.5, average_from = 0.4;
  while (solver.time() < end_time - 1e-12) {
    solver.step(std::min(solver.step_limits().smallest(), end_time - solver.time()));
    if (solver.time() >= average_from) sample(solver);
  }
}

// The walls carry the hydrostatic forces: the floor the water's weight
// rho0 g H W, each side wall rho0 g H^2 / 2, outwards (per metre of depth).
TEST(StillTank, WallsCarryTheHydrostaticForces) {
  std::vector<Vec2> mean(3, Vec2::Zero());
  int samples = 0;
  sample_the_settled_tank([&](const FluidSolver& solver) {
    const std::vector<Vec2> forces = solver.wall_forces();
    for (std::size_t k = 0; k < mean.size(); ++k) mean[k] += forces[k];
    ++samples;
  });
  for (Vec2& force : mean) force /= samples;
  const double floor_load = kRho0 * kG * kDepth * kWidth,
               side_load = 0.5 * kRho0 * kG * kDepth * kDepth;
  // fluid.walls: the floor, the left wall, the right wall.
  EXPECT_NEAR(mean[0].y(), -floor_load, 0.01 * floor_load);
  EXPECT_NEAR(mean[1].x(), -side_load, 0.03 * side_load);
  EXPECT_NEAR(mean[2].x(), side_load, 0.03 * side_load);
  // Nothing along the walls: the still water holds no shear.
  EXPECT_NEAR(mean[0].x(), 0.0, 0.01 * side_load);
  EXPECT_NEAR(mean[1].y(), 0.0, 0.01 * side_load);
  EXPECT_NEAR(mean[2].y(), 0.0, 0.01 * side_load);
}

// Sensors on the walls' faces read rho0 g (H - y); one above the water, 0.
TEST(StillTank, PressureProbesReadTheHydrostaticPressure) {
  std::vector<double> mean(4, 0.0);
  int samples = 0;
  sample_the_settled_tank([&](const FluidSolver& solver) {
    std::size_t k = 0;
    for (const sph::Gauge& gauge : solver.gauge_values())
      if (gauge.name.starts_with("probe")) mean.at(k++) += gauge.value;
    ++samples;
  });
  for (double& p : mean) p /= samples;
  // The probes of kStillTank: left wall at y = 0.05 and 0.15, floor at
  // x = 0.2, and in the air.
  for (const auto& [k, y] : {std::pair{0, 0.05}, {1, 0.15}, {2, 0.0}}) {
    const double hydrostatic = kRho0 * kG * (kDepth - y);
    EXPECT_NEAR(mean[k], hydrostatic, 0.01 * kRho0 * kG * kDepth) << "probe " << k;
  }
  EXPECT_EQ(mean[3], 0.0);
}

}  // namespace
}  // namespace cosph::fluid

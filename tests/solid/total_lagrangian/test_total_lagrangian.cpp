// The total-Lagrangian solid (solid/total_lagrangian): the deformation
// gradient of a linear map, objectivity, the stress of a uniaxial stretch,
// momentum conservation, model selection, the oscillating plate's period
// (short mode) and a runaway run.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bending_mode.hpp"
#include "clamp_reach.hpp"
#include "hooke_pressure.hpp"
#include "reference_configuration.hpp"
#include "runaway_spoils.hpp"
#include "solid_test_cases.hpp"
#include "sphcore/gauge.hpp"
#include "st_venant_kirchhoff.hpp"
#include "tl_dynamics.hpp"
#include "tl_solver.hpp"

namespace cosph::solid::tl {
namespace {

using testing::plate_case_path;

// The coarse plate (6 across, default hourglass control alpha = 5) measured
// +8.0 % over the one period of this short mode; with the control off it is
// +15.9 % (docs/results/oscillating_plate_tl.md). The test guards against
// regressions beyond 11 %, which also catches a control that does nothing;
// the 10- and 16-across rows of the table are the accuracy check.
constexpr double kCoarsePeriodTolerance = 0.11;

// A free block, 10 x 6 particles, no gravity: every particle within 2h of a
// surface or a corner.
const char* kBlock = R"(
run { end_time: 0.01 gravity { x: 0 y: 0 } }
solid {
  model: "total_lagrangian"
  spacing: 0.01 density: 1000 youngs_modulus: 1e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.1 y: 0.06 } }
}
)";

TLSolver block_solver() {
  const sph::CaseFile case_file = sph::load_case(testing::write_case("tl_block", kBlock));
  return TLSolver(case_file, read_solid_parameters(case_file));
}

// Moves every particle to x = A X + b and recomputes F and the stress.
void deform(TLSolver& solver, const Mat2& A, const Vec2& b) {
  TLParticles& P = solver.particles();
  for (std::size_t i = 0; i < P.size(); ++i) P.x[i] = A * P.X[i] + b;
  solver.update();
}

TEST(TotalLagrangian, DeformationGradientOfALinearMapIsExactEverywhere) {
  TLSolver solver = block_solver();
  Mat2 A;
  A << 1.3, -0.4, 0.2, 0.8;
  deform(solver, A, Vec2(0.5, -2.0));
  const TLParticles& P = solver.particles();
  ASSERT_EQ(P.size(), 60u);
  for (std::size_t i = 0; i < P.size(); ++i) {
    // Free surfaces and corners included: L0 corrects the one-sided supports.
    EXPECT_LT((P.F[i] - A).norm(), 1e-12) << "particle " << P.id[i] << " at " << P.X[i].transpose();
    EXPECT_NEAR(P.J[i], A.determinant(), 1e-12);
  }
}

TEST(TotalLagrangian, RigidRotationGivesNoStress) {
  TLSolver solver = block_solver();
  const double angle = 1.1;  // rad: far beyond small rotations
  Mat2 R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  deform(solver, R, Vec2(3.0, 1.0));
  const TLParticles& P = solver.particles();
  const double E = solver.parameters().E;
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_LT((P.F[i] - R).norm(), 1e-12) << "particle " << P.id[i];
    EXPECT_LT(P.sigma[i].norm(), 1e-10 * E) << "particle " << P.id[i];
    EXPECT_LT(std::abs(P.sigma_zz[i]), 1e-10 * E);
    EXPECT_LT(P.a[i].norm(), 1e-6) << "particle " << P.id[i];  // m/s^2, against E/(rho dx) = 1e5
  }
}

// Stretch along x, held in y (and z: plane strain): F = diag(1 + e, 1).
TEST(TotalLagrangian, UniaxialStretchGivesTheStVenantKirchhoffStress) {
  TLSolver solver = block_solver();
  const SolidParameters& par = solver.parameters();
  const double lambda = lame_lambda(par.K, par.G), mu = par.G;
  for (const double e : {1e-6, 0.2}) {
    deform(solver, Vec2(1.0 + e, 1.0).asDiagonal(), Vec2::Zero());
    const double E_xx = 0.5 * ((1.0 + e) * (1.0 + e) - 1.0);
    const double S_xx = (lambda + 2.0 * mu) * E_xx, S_yy = lambda * E_xx;
    // sigma = F S F^T / J with J = 1 + e.
    const double sigma_xx = (1.0 + e) * S_xx, sigma_yy = S_yy / (1.0 + e);
    const TLParticles& P = solver.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      EXPECT_NEAR(P.sigma[i](0, 0), sigma_xx, 1e-9 * std::abs(sigma_xx)) << "e = " << e;
      EXPECT_NEAR(P.sigma[i](1, 1), sigma_yy, 1e-9 * std::abs(sigma_xx)) << "e = " << e;
      EXPECT_NEAR(P.sigma[i](0, 1), 0.0, 1e-9 * std::abs(sigma_xx));
    }
    if (e < 1e-3) {
      // Small strain: the plane-strain Hooke law of the Jaumann solid,
      // sigma_xx = (K + 4G/3) e, sigma_yy = (K - 2G/3) e.
      EXPECT_NEAR(P.sigma[0](0, 0), (par.K + 4.0 * par.G / 3.0) * e, 1e-5 * par.E * e);
      EXPECT_NEAR(P.sigma[0](1, 1), (par.K - 2.0 * par.G / 3.0) * e, 1e-5 * par.E * e);
    }
  }
}

// A free block with random velocities and a random distortion: internal
// forces (stress, viscosity, hourglass control) are equal and opposite per
// pair, so total momentum stays what it was to round-off.
TEST(TotalLagrangian, FreeBodyConservesMomentum) {
  TLSolver solver = block_solver();
  TLParticles& P = solver.particles();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.x[i] += 0.05 * 0.01 * Vec2(unit(random), unit(random));
    P.v[i] = Vec2(unit(random), unit(random));  // m/s, against c = 37 m/s
  }
  solver.update();
  const double scale = testing::momentum_scale(P);
  const Vec2 before = testing::total_momentum(P);
  const std::vector<Vec2> v_before = P.v;
  for (int k = 0; k < 200; ++k) solver.step(solver.step_limits().smallest());
  const Vec2 change = testing::total_momentum(P) - before;
  EXPECT_LT(change.norm(), 1e-12 * scale) << change.transpose() << " against " << scale;
  // And the particles did exchange momentum.
  double exchanged = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) exchanged += P.m[i] * (P.v[i] - v_before[i]).norm();
  EXPECT_GT(exchanged, 0.1 * scale);
}

std::string refusal(const std::vector<std::string>& overrides) {
  try {
    const sph::CaseFile case_file = sph::load_case(plate_case_path(), overrides);
    TLSolver solver(case_file, read_solid_parameters(case_file));
  } catch (const sph::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(TotalLagrangianParameters, BadModelsAndOptionsAreRefused) {
  std::string message = refusal({"solid.model=total_lagrangien"});
  EXPECT_NE(message.find("oscillating_plate.pbtxt"), std::string::npos) << message;
  EXPECT_NE(message.find("solid.model"), std::string::npos) << message;
  EXPECT_NE(message.find("total_lagrangien"), std::string::npos) << message;
  // The case's own model is jaumann: this solver is the wrong one for it.
  message = refusal({});
  EXPECT_NE(message.find("solid.model"), std::string::npos) << message;
  EXPECT_NE(message.find("cosph-solid-jaumann "), std::string::npos) << message;
  message = refusal({"solid.model=total_lagrangian", "solid.fracture.enabled=true",
                     "solid.fracture.yield_stress=1e5"});
  EXPECT_NE(message.find("solid.fracture.enabled"), std::string::npos) << message;
  message = refusal({"solid.model=total_lagrangian", "solid.hourglass_control=-1"});
  EXPECT_NE(message.find("solid.hourglass_control"), std::string::npos) << message;
  message = refusal({"solid.hourglass_control=5"});  // jaumann has no such option
  EXPECT_NE(message.find("solid.hourglass_control"), std::string::npos) << message;
  EXPECT_EQ(refusal({"solid.model=total_lagrangian"}), "");
}

struct Exit {
  int code;
  std::string stderr_text;
};

Exit run(const std::string& executable, const std::string& arguments) {
  // One file per process: ctest -j runs this file's tests in parallel processes.
  const std::string err =
      testing::temporary_path("tl_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string command =
      std::string(COSPH_BIN_DIR) + "/" + executable + " " + arguments + " > /dev/null 2> " + err;
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(err).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// Each executable runs one model and refuses the other, naming the file and the field.
TEST(CosphSolidTl, EachExecutableRefusesTheOtherModel) {
  const std::string out = testing::temporary_path("tl_refused");
  const std::string plate = "--case " + plate_case_path() + " --out " + out;
  Exit result = run("cosph-solid-tl", plate);
  EXPECT_EQ(result.code, 2) << result.stderr_text;
  EXPECT_NE(result.stderr_text.find("oscillating_plate.pbtxt"), std::string::npos);
  EXPECT_NE(result.stderr_text.find("solid.model"), std::string::npos) << result.stderr_text;
  result = run("cosph-solid-jaumann", plate + " --set solid.model=total_lagrangian");
  EXPECT_EQ(result.code, 2) << result.stderr_text;
  EXPECT_NE(result.stderr_text.find("solid.model"), std::string::npos) << result.stderr_text;
  EXPECT_NE(result.stderr_text.find("cosph-solid-tl"), std::string::npos) << result.stderr_text;
}

// A plate flung at its sound speed with CFL 1 blows up (J leaves [0.5, 2]
// near the clamp within 0.01 s): the solver stops
// with a clear error (exit 1) and keeps the last good state.
TEST(CosphSolidTl, RunawayStopsWithLastGoodSnapshot) {
  const std::string out = testing::temporary_path("tl_runaway");
  std::filesystem::remove_all(out);
  const Exit result = run("cosph-solid-tl",
                          "--case " + plate_case_path() + " --out " + out +
                              " --set solid.model=total_lagrangian"
                              " --set solid.spacing=0.0033333333333333 --set run.cfl=1"
                              " --set run.end_time=0.05 --set solid.initial_velocity.tip_speed=60");
  EXPECT_EQ(result.code, 1) << result.stderr_text;
  EXPECT_NE(result.stderr_text.find("blown up"), std::string::npos) << result.stderr_text;
  EXPECT_TRUE(std::filesystem::exists(out + "/solid_last_good.h5"));
}

// solid.walls holds the total-Lagrangian solid as it holds the Jaumann one
// (wall_contact.hpp, test_fracture.cpp): a block dropped onto a floor rests
// on it, half a spacing above its face, instead of falling through; and
// solid.broken_part_below_y gives it the broken_x, broken_y columns.
// Every way a particle can run away stops the step; a speed between the
// screen's margin and the sound speed does not.
TEST(TotalLagrangian, EveryKindOfRunawayStopsTheStepAndNothingElseDoes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  using Spoil = cosph::testing::Spoil<TLParticles>;
  const std::vector<Spoil> spoils{
      {"x not finite", [&](TLParticles& P, std::size_t i) { P.x[i].x() = nan; }, true},
      {"v not finite", [&](TLParticles& P, std::size_t i) { P.v[i].y() = nan; }, true},
      {"F not finite", [&](TLParticles& P, std::size_t i) { P.F[i](0, 1) = nan; }, true},
      {"J below 0.5", [](TLParticles& P, std::size_t i) { P.J[i] = 0.49; }, true},
      {"J above 2", [](TLParticles& P, std::size_t i) { P.J[i] = 2.01; }, true},
      {"faster than c",
       [](TLParticles& P, std::size_t i) { P.v[i] = Vec2(0.6, 0.8) * 1.001 * P.c[i]; }, true},
      {"just below c",
       [](TLParticles& P, std::size_t i) { P.v[i] = Vec2(0.6, 0.8) * 0.995 * P.c[i]; }, false},
  };
  const std::size_t n = block_solver().particles().size();
  cosph::testing::expect_exactly_the_runaways_stop(block_solver, spoils, {0, n / 2, n - 1});
}

TEST(TotalLagrangianCaseFields, DroppedBlockRestsOnTheFloorAndIsGauged) {
  const sph::CaseFile case_file = sph::load_case(testing::dropped_block_case(
      "tl_dropped", "  model: \"total_lagrangian\"\n  broken_part_below_y: 0.04"));
  TLSolver solver(case_file, read_solid_parameters(case_file));
  while (solver.time() < 0.2) solver.step(solver.step_limits().smallest());
  const double lowest = testing::lowest_y(solver.particles());
  EXPECT_GE(lowest, 0.005 - 1e-12);  // it fell 20 mm (free fall: 0.2 m in 0.2 s)
  EXPECT_LT(lowest, 0.005 + 0.001);  // and rests on the floor
  // The lower two rows (initial y 0.025, 0.035) now sit near y = 0.005, 0.015.
  std::vector<std::string> names;
  double broken_y = -1.0;
  for (const sph::Gauge& gauge : solver.gauge_values()) {
    names.push_back(gauge.name);
    if (gauge.name == "broken_y") broken_y = gauge.value;
  }
  EXPECT_NE(std::find(names.begin(), names.end(), "broken_x"), names.end());
  EXPECT_NEAR(broken_y, 0.010, 0.002);
}

// The same watch on the water's walls as the Jaumann solid's
// (test_unmet_walls.cpp): 30 mm of free fall into the floor stops the run.
TEST(TotalLagrangianCaseFields, ABlockFallingIntoTheWatersFloorStopsTheRun) {
  const sph::CaseFile case_file =
      sph::load_case(testing::tank_drop_case("tl_tank_drop", "  model: \"total_lagrangian\""));
  TLSolver solver(case_file, read_solid_parameters(case_file));
  const std::string message = testing::runaway_message_before(solver, 0.2);
  ASSERT_FALSE(message.empty()) << "the block went through the floor, t = " << solver.time();
  EXPECT_NEAR(solver.time(), std::sqrt(2.0 * 0.03 / 9.81), 0.002);
  EXPECT_NE(message.find("fluid.walls[1]"), std::string::npos) << message;
}

// Short mode of scripts/validate_oscillating_plate.py --model total_lagrangian:
// the coarse plate (6 particles across) over one period.
TEST(OscillatingPlateTl, CoarsePeriodNearThinPlateTheory) {
  const sph::CaseFile case_file = sph::load_case(
      plate_case_path(),
      {"solid.model=total_lagrangian", "solid.spacing=0.0033333333333333", "run.end_time=0.3"});
  const SolidParameters par = read_solid_parameters(case_file);
  TLSolver solver(case_file, par);
  const double T = testing::tip_period_until(solver, par.run.end_time);
  const double T_theory = testing::thin_plate_period(par);
  EXPECT_NEAR(T / T_theory, 1.0, kCoarsePeriodTolerance) << "T = " << T << " s";
}

// The passes skip clamped particles whose every neighbour is clamped
// (inert: out of every free particle's reach) and stop at the last particle
// in reach. On the coarse Antoci plate, clamped at its top and swinging, each
// keeps the values the deformation pass itself gives it, bit for bit, and
// every particle's acceleration is what it is with all of them visited.
TEST(ElasticPlateTl, ClampOutOfReachKeepsWhatThePassesGiveIt) {
  const sph::CaseFile case_file = sph::load_case(testing::write_case("hanging_plate", R"(
run { end_time: 1 gravity { x: 100 y: 0 } }
solid {
  model: "total_lagrangian"
  spacing: 0.005 density: 1000 youngs_modulus: 2e6 poisson_ratio: 0.3
  body { min { x: 0 y: 0 } max { x: 0.02 y: 0.16 } }
  clamp { min { x: 0 y: 0.06 } max { x: 0.02 y: 0.16 } }
}
)"));
  TLSolver solver(case_file, read_solid_parameters(case_file));
  for (int k = 0; k < 200; ++k) solver.step(solver.step_limits().smallest());
  const TLParticles& P = solver.particles();
  long clamped_at_the_root = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const bool free_neighbour =
        std::any_of(P.neighbours[i].begin(), P.neighbours[i].end(),
                    [&P](const ReferenceNeighbour& neighbour) { return !P.clamped[neighbour.j]; });
    ASSERT_EQ(P.inert[i] != 0, P.clamped[i] && !free_neighbour) << "particle " << P.id[i];
    ASSERT_TRUE(i < in_reach(P) || P.inert[i]) << "particle " << P.id[i];
    clamped_at_the_root += P.clamped[i] && !P.inert[i];
  }
  ASSERT_LT(in_reach(P), P.size());   // the case has particles no pass visits
  ASSERT_GT(clamped_at_the_root, 0);  // clamped next to free ones: in reach, stressed

  TLParticles some = P, all = P;
  std::fill(all.inert.begin(), all.inert.end(), 0);
  all.reach_end = all.size();
  for (TLParticles* Q : {&some, &all}) {
    compute_deformation_and_stress(*Q);
    compute_accelerations(*Q, solver.force_parameters());
  }
  for (std::size_t i = 0; i < P.size(); ++i) {
    ASSERT_EQ(P.F[i], all.F[i]) << "particle " << P.id[i];
    ASSERT_EQ(P.J[i], all.J[i]) << "particle " << P.id[i];
    ASSERT_EQ(P.P_L0[i], all.P_L0[i]) << "particle " << P.id[i];
    ASSERT_EQ(P.sigma[i], all.sigma[i]) << "particle " << P.id[i];
    ASSERT_EQ(P.sigma_zz[i], all.sigma_zz[i]) << "particle " << P.id[i];
    ASSERT_EQ(P.strain_energy[i], all.strain_energy[i]) << "particle " << P.id[i];
    ASSERT_EQ(some.a[i], all.a[i]) << "particle " << P.id[i];
  }
  double root_stress = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.clamped[i] && !P.inert[i]) root_stress = std::max(root_stress, P.sigma[i].norm());
  EXPECT_GT(root_stress, 0.0);
}

}  // namespace
}  // namespace cosph::solid::tl

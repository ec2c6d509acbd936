// The automatic choice of sub-steps (coupler/src/substep_choice.hpp): the
// added-mass ratio of a window against its bound, on both sides and at it,
// bad inputs, and the case's coupling.max_substeps read as set or automatic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common_step.hpp"
#include "sphcore/case_file.hpp"
#include "substep_choice.hpp"

namespace {

using cosph::coupler::AddedMassInputs;
using cosph::coupler::choose_substeps;
using cosph::coupler::read_substep_choice;
using cosph::coupler::window_added_mass_ratio;

// cases/elastic_plate.pbtxt: water 2 mm at c_f = 10 sqrt(2 g 0.14 m) with the
// default Wendland C2 kernel's h = 1.5 dx, rubber 1 mm at
// c_s = sqrt((K + 4G/3) / rho_s) with h = 1.3 dx, the plate 5 mm thick.
AddedMassInputs elastic_plate(double solid_density = 1100.0) {
  const double c_f = 10.0 * std::sqrt(2.0 * 9.81 * 0.14);
  const double E = 12.0e6, nu = 0.4;
  const double K = E / (3.0 * (1.0 - 2.0 * nu)), G = E / (2.0 * (1.0 + nu));
  const double c_s = std::sqrt((K + 4.0 * G / 3.0) / solid_density);
  return {0.25, 1000.0, c_f, 1.5 * 0.002, solid_density, c_s, 1.3 * 0.001, 0.005};
}

sph::CaseFile elastic_plate_case(std::vector<std::string> overrides = {}) {
  return sph::load_case(COSPH_SOURCE_DIR "/cases/elastic_plate.pbtxt", overrides);
}

TEST(SubstepChoice, TheElasticPlateTakesMultiRate) {
  const auto choice = choose_substeps(elastic_plate());
  // The water's step bounds the window: mu_W = cfl rho_f h_f / (rho_s e).
  EXPECT_NEAR(choice.added_mass_ratio, 0.25 * 1000.0 * 0.003 / (1100.0 * 0.005), 1e-12);
  EXPECT_EQ(choice.max_substeps, cosph::coupler::kAutomaticMaxSubsteps);
  EXPECT_NE(choice.reason.find("multi-rate"), std::string::npos) << choice.reason;
}

TEST(SubstepChoice, ALightPlateTakesSynchronisedSteps) {
  // rho_s / rho_f = 0.05: multi-rate stops there in the stability map.
  const auto choice = choose_substeps(elastic_plate(50.0));
  EXPECT_GT(choice.added_mass_ratio, cosph::coupler::kMaxWindowAddedMassRatio);
  EXPECT_EQ(choice.max_substeps, 1);
  EXPECT_EQ(choice.reason.rfind("synchronised", 0), 0u) << choice.reason;
}

TEST(SubstepChoice, TheBoundItselfIsStillMultiRate) {
  // Powers of two, so that mu_W is exactly 1: W = 0.5 max(1/1, 0.5/1) = 0.5.
  AddedMassInputs at_bound{0.5, 1.0, 1.0, 1.0, 0.5, 1.0, 0.5, 1.0};
  ASSERT_EQ(window_added_mass_ratio(at_bound), 1.0);
  EXPECT_GT(choose_substeps(at_bound).max_substeps, 1);
  AddedMassInputs just_lighter = at_bound;
  just_lighter.solid_density = std::nextafter(0.5, 0.0);
  EXPECT_EQ(choose_substeps(just_lighter).max_substeps, 1);
}

TEST(SubstepChoice, TheSlowerSolverSetsTheWindow) {
  // A solid softer than the water proposes the longer step: it bounds W.
  AddedMassInputs soft{0.5, 1.0, 1.0, 1.0, 4.0, 0.25, 1.0, 1.0};
  EXPECT_DOUBLE_EQ(window_added_mass_ratio(soft), 1.0 * 1.0 * (0.5 * 4.0) / (4.0 * 1.0));
}

TEST(SubstepChoice, RefusesInputsThatAreNotPositive) {
  for (double AddedMassInputs::*field :
       {&AddedMassInputs::solid_thickness, &AddedMassInputs::solid_density,
        &AddedMassInputs::fluid_sound_speed, &AddedMassInputs::cfl}) {
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
      AddedMassInputs in = elastic_plate();
      in.*field = bad;
      EXPECT_THROW(choose_substeps(in), std::invalid_argument) << bad;
    }
  }
}

TEST(SubstepChoice, TheCaseIsAutomaticByDefault) {
  const auto choice = read_substep_choice(elastic_plate_case());
  EXPECT_EQ(choice.max_substeps, cosph::coupler::kAutomaticMaxSubsteps);
  EXPECT_NEAR(choice.added_mass_ratio, choose_substeps(elastic_plate()).added_mass_ratio, 1e-9);
  EXPECT_EQ(read_substep_choice(elastic_plate_case({"solid.density=50"})).max_substeps, 1);
}

// A solid that reports modes it does not damp (Hello field undamped_modes)
// turns the automatic multi-rate choice into synchronised steps; the shell is
// judged by that report, not by its name.
TEST(SubstepChoice, TheUndampedShellStepsWithTheWater) {
  using cosph::coupler::account_for_the_solids_damping;
  const auto automatic = read_substep_choice(elastic_plate_case({"solid.model=shell"}));
  ASSERT_GT(automatic.max_substeps, 1) << automatic.reason;  // by the added-mass ratio
  ASSERT_GE(automatic.added_mass_ratio, 0.0);
  // A solid that sends nothing about its damping: the added-mass rule alone.
  const auto silent = account_for_the_solids_damping(automatic, {}, "shell");
  EXPECT_EQ(silent.max_substeps, automatic.max_substeps);
  EXPECT_EQ(silent.reason, automatic.reason);
  EXPECT_TRUE(std::isinf(silent.max_window));
  // Undamped: synchronised, and the log says why.
  const auto undamped = account_for_the_solids_damping(automatic, {true, 39477.0, 0.0}, "shell");
  EXPECT_EQ(undamped.max_substeps, 1);
  EXPECT_NE(undamped.reason.find("does not damp"), std::string::npos) << undamped.reason;
  EXPECT_NE(undamped.reason.find("'shell'"), std::string::npos) << undamped.reason;
  // A fastest mode with no damping is the same statement.
  EXPECT_EQ(account_for_the_solids_damping(automatic, {false, 39477.0, 0.0}, "s").max_substeps, 1);
  // Asked for, multi-rate still means what it says.
  const auto asked =
      read_substep_choice(elastic_plate_case({"solid.model=shell", "coupling.max_substeps=4"}));
  const auto kept = account_for_the_solids_damping(asked, {true, 39477.0, 0.1}, "shell");
  EXPECT_EQ(kept.max_substeps, 4);
  EXPECT_TRUE(std::isinf(kept.max_window));
  // Synchronised already (a light plate): nothing to change.
  const auto light = read_substep_choice(elastic_plate_case({"solid.density=50"}));
  ASSERT_EQ(light.max_substeps, 1);
  EXPECT_EQ(account_for_the_solids_damping(light, {true, 0.0, 0.0}, "shell").reason, light.reason);
}

// The damped shell of the elastic plate (plate 5 mm, E 12 MPa, nu 0.4,
// rho 1100, line 1 mm, h = 1.3 mm): its shear-rotation cut-off omega_r and
// the damping ratio its Kelvin-Voigt rule gives it bound the window at
// 2 zeta / (s omega_r) = min(t, h) / (4 c_G s). With a delta-SPH water s = 1:
// about 5 us, where the added-mass rule alone took the water's whole step,
// about 36 us (32 shell steps). With the default, Riemann water s is the
// measured share, and the bound is 1 / s times longer.
TEST(SubstepChoice, TheDampedShellsFastestModeBoundsTheWindowByTheWatersShare) {
  using cosph::coupler::account_for_the_solids_damping;
  using cosph::coupler::common_step;
  using cosph::coupler::kRiemannCouplingStiffnessShare;
  const double E = 12.0e6, nu = 0.4, rho = 1100.0, t = 0.005, h = 1.3 * 0.001;
  const double G = E / (2.0 * (1.0 + nu)), k = 5.0 / 6.0;
  const double omega_r = std::sqrt(12.0 * k * G / rho) / t;
  const double c_G = std::sqrt(G / rho);
  const double zeta_r = omega_r * std::min(t, h) / (8.0 * c_G);
  const cosph::coupler::SolidDamping damped{false, omega_r, zeta_r};
  // The proposals of a measured run (water 36.5 us, shell 1.5 us).
  const double water = 36.5e-6, shell = 1.5e-6;

  const auto delta_sph =
      read_substep_choice(elastic_plate_case({"solid.model=shell", "fluid.dissipation=delta_sph"}));
  EXPECT_DOUBLE_EQ(delta_sph.coupling_stiffness_share, 1.0);
  const auto bounded = account_for_the_solids_damping(delta_sph, damped, "shell");
  EXPECT_NEAR(bounded.max_window, std::min(t, h) / (4.0 * c_G), 1e-12);
  EXPECT_LT(omega_r * bounded.max_window, 0.25);
  EXPECT_GT(bounded.max_substeps, 1) << bounded.reason;  // still multi-rate
  EXPECT_NE(bounded.reason.find("windows at most"), std::string::npos) << bounded.reason;
  EXPECT_NE(bounded.reason.find("the whole mode's"), std::string::npos) << bounded.reason;
  // The added-mass rule alone took the water's whole step; the bound cuts the
  // window to 2 zeta / omega, and never below the shell's own step.
  EXPECT_DOUBLE_EQ(common_step(water, shell, delta_sph.max_substeps), water);
  EXPECT_DOUBLE_EQ(common_step(water, shell, bounded.max_substeps, bounded.max_window),
                   bounded.max_window);
  EXPECT_LT(common_step(water, shell, bounded.max_substeps, bounded.max_window), 0.3 * water);
  EXPECT_DOUBLE_EQ(common_step(water, 20e-6, bounded.max_substeps, bounded.max_window), 20e-6);

  const auto riemann = read_substep_choice(elastic_plate_case({"solid.model=shell"}));
  EXPECT_DOUBLE_EQ(riemann.coupling_stiffness_share, kRiemannCouplingStiffnessShare);
  const auto relaxed = account_for_the_solids_damping(riemann, damped, "shell");
  EXPECT_NEAR(relaxed.max_window, bounded.max_window / kRiemannCouplingStiffnessShare, 1e-12);
  EXPECT_NE(relaxed.reason.find("the Riemann water's"), std::string::npos) << relaxed.reason;
  EXPECT_DOUBLE_EQ(common_step(water, shell, relaxed.max_substeps, relaxed.max_window),
                   relaxed.max_window);
  EXPECT_GT(relaxed.max_window, 4.0 * bounded.max_window);
  // Undamped, the Riemann water's shell still steps with the water.
  EXPECT_EQ(account_for_the_solids_damping(riemann, {true, omega_r, 0.0}, "shell").max_substeps, 1);
}

TEST(SubstepChoice, AnExplicitValueMeansWhatItSays) {
  for (int set : {1, 5, 64}) {
    const auto choice =
        read_substep_choice(elastic_plate_case({"coupling.max_substeps=" + std::to_string(set)}));
    EXPECT_EQ(choice.max_substeps, set);
    EXPECT_LT(choice.added_mass_ratio, 0.0);
    EXPECT_NE(choice.reason.find("as set"), std::string::npos) << choice.reason;
  }
  // Multi-rate on a plate the rule would keep synchronised, because asked.
  EXPECT_EQ(
      read_substep_choice(elastic_plate_case({"solid.density=50", "coupling.max_substeps=32"}))
          .max_substeps,
      32);
  EXPECT_THROW(read_substep_choice(elastic_plate_case({"coupling.max_substeps=-1"})),
               sph::ConfigError);
}

TEST(SubstepChoice, ACaseWithoutWhatTheRuleNeedsIsSynchronised) {
  // The thickness comes from solid.body; the coupler-with-dummies cases have none.
  const std::string path = ::testing::TempDir() + "no_body.pbtxt";
  {
    std::ofstream file(path);
    file << "run { end_time: 0.01 }\nfluid { spacing: 0.001 }\nsolid { spacing: 0.001 }\n";
  }
  const auto choice = read_substep_choice(sph::load_case(path, {}));
  EXPECT_EQ(choice.max_substeps, 1);
  EXPECT_NE(choice.reason.find("solid.body"), std::string::npos) << choice.reason;
  EXPECT_DOUBLE_EQ(cosph::coupler::solid_thickness(elastic_plate_case()), 0.105 - 0.1);
}

// A band's thickness is the one it gives, not the lattice's reading of its
// outline (up to two lattice spacings less).
TEST(SubstepChoice, ABandsThicknessIsTheOneItGives) {
  sph::CaseFile curved = elastic_plate_case();
  auto* body = curved.config.mutable_solid()->mutable_body(0);
  body->Clear();
  for (const auto& [x, y] : {std::pair{0.1025, 0.16}, {0.1025, 0.079}, {0.11, 0.04}}) {
    auto* point = body->mutable_band()->add_point();
    point->set_x(x);
    point->set_y(y);
  }
  body->mutable_band()->set_thickness(0.005);
  EXPECT_DOUBLE_EQ(cosph::coupler::solid_thickness(curved), 0.005);
}

}  // namespace

// Bad solid parameters are refused with an error naming the file, the field
// and the reason; cosph-solid-jaumann exits 2 for them.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdlib>
#include <string>

#include "solid_parameters.hpp"
#include "solid_scene.hpp"
#include "solid_test_cases.hpp"

namespace cosph::solid {
namespace {

using testing::plate_case_path;

std::string refusal(const std::vector<std::string>& overrides) {
  try {
    read_solid_parameters(sph::load_case(plate_case_path(), overrides));
  } catch (const sph::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(SolidParameters, ThePlateCaseIsValid) {
  const SolidParameters p = read_solid_parameters(sph::load_case(plate_case_path()));
  EXPECT_DOUBLE_EQ(p.dx, 0.00125);
  EXPECT_EQ(p.velocity_gradient, VelocityGradient::quadratic);  // the case's choice
  const std::string elastic_plate = std::string(COSPH_SOURCE_DIR) + "/cases/elastic_plate.pbtxt";
  EXPECT_EQ(read_solid_parameters(sph::load_case(elastic_plate)).velocity_gradient,
            VelocityGradient::linear);  // the solver's default
  EXPECT_TRUE(p.artificial_stress.enabled);
  EXPECT_DOUBLE_EQ(p.artificial_stress.epsilon, 0.3);
  ASSERT_TRUE(p.bending_mode.has_value());
  ASSERT_TRUE(p.tip_gauge.has_value());
}

TEST(SolidParameters, IncompressiblePoissonRatioIsRefused) {
  for (const char* nu : {"0.5", "0.7"}) {
    const std::string message = refusal({std::string("solid.poisson_ratio=") + nu});
    EXPECT_NE(message.find("oscillating_plate.pbtxt"), std::string::npos) << message;
    EXPECT_NE(message.find("solid.poisson_ratio"), std::string::npos) << message;
    EXPECT_NE(message.find("0.5"), std::string::npos) << message;
  }
}

TEST(SolidParameters, NonPositiveYoungsModulusAndDensityAreRefused) {
  std::string message = refusal({"solid.youngs_modulus=-2e6"});
  EXPECT_NE(message.find("oscillating_plate.pbtxt"), std::string::npos) << message;
  EXPECT_NE(message.find("solid.youngs_modulus"), std::string::npos) << message;
  EXPECT_NE(message.find("positive"), std::string::npos) << message;
  EXPECT_NE(refusal({"solid.youngs_modulus=0"}).find("solid.youngs_modulus"), std::string::npos);
  message = refusal({"solid.density=0"});
  EXPECT_NE(message.find("solid.density"), std::string::npos) << message;
}

TEST(SolidParameters, OtherBadFieldsAreNamed) {
  EXPECT_NE(refusal({"solid.spacing=0"}).find("solid.spacing"), std::string::npos);
  EXPECT_NE(refusal({"solid.artificial_stress.epsilon=-1"}).find("artificial_stress.epsilon"),
            std::string::npos);
  EXPECT_NE(refusal({"solid.fracture.enabled=true"}).find("solid.fracture.yield_stress"),
            std::string::npos);
  EXPECT_NE(refusal({"solid.initial_velocity.tip_speed=100"}).find("tip_speed"), std::string::npos);
  const std::string message = refusal({"solid.velocity_gradient=cubic"});
  EXPECT_NE(message.find("solid.velocity_gradient"), std::string::npos) << message;
  EXPECT_NE(message.find("quadratic, linear"), std::string::npos) << message;
}

// The message that building the scene of a tank-drop case with a floor under
// solid.walls refuses it with, or "" if it builds.
std::string scene_refusal(const std::string& name, const std::string& extra, double body_bottom) {
  const std::string floor = "  walls { min { x: -0.35 y: -0.05 } max { x: 0.2 y: 0 } }\n";
  const sph::CaseFile case_file =
      sph::load_case(testing::tank_drop_case(name, floor + extra, body_bottom));
  try {
    build_solid_scene(case_file, read_solid_parameters(case_file));
  } catch (const sph::ConfigError& error) {
    return error.what();
  }
  return "";
}

// A free particle that starts inside one of solid.walls would be thrown onto
// its face at once; a clamped one may sit there (a plate held in the floor).
TEST(SolidScene, AFreeParticleStartingInsideASolidWallIsRefused) {
  const std::string message = scene_refusal("in_floor", "", -0.02);
  EXPECT_NE(message.find("solid.walls[0]: a free particle of solid.body[0] at (0.005, -0.015) m"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("solid.clamp"), std::string::npos) << message;
  EXPECT_EQ(scene_refusal("in_floor_clamped",
                          "  clamp { min { x: 0 y: -0.02 } max { x: 0.1 y: 0 } }\n", -0.02),
            "");
  // Resting on the floor: the lowest row half a spacing above it, on the face
  // of the wall grown by half a spacing.
  EXPECT_EQ(scene_refusal("on_floor", "", 0.0), "");
}

int run_solid(const std::string& arguments) {
  const std::string command = std::string(COSPH_BIN_DIR) + "/cosph-solid-jaumann " + arguments +
                              " > /dev/null 2> " + testing::temporary_path("stderr.txt");
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CosphSolid, ExitsTwoForBadParameters) {
  const std::string out = testing::temporary_path("bad_out");
  EXPECT_EQ(
      run_solid("--case " + plate_case_path() + " --out " + out + " --set solid.poisson_ratio=0.5"),
      2);
  EXPECT_EQ(
      run_solid("--case " + plate_case_path() + " --out " + out + " --set solid.youngs_modulus=-1"),
      2);
}

}  // namespace
}  // namespace cosph::solid

// Whether the moving wall's pressure takes the solid's acceleration
// (coupler/src/wall_acceleration_choice.hpp): the feedback ratio against its
// bound, bad inputs, and the case's coupling.wall_acceleration read as set or
// automatic.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupler_settings.hpp"
#include "sphcore/case_file.hpp"
#include "wall_acceleration_choice.hpp"

namespace {

using cosph::coupler::acceleration_feedback_ratio;
using cosph::coupler::kMaxAccelerationFeedbackRatio;
using cosph::coupler::read_wall_acceleration_choice;

sph::CaseFile elastic_plate_case(std::vector<std::string> overrides = {}) {
  return sph::load_case(COSPH_SOURCE_DIR "/cases/elastic_plate.pbtxt", overrides);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(WallAccelerationChoice, FeedbackRatioIsTheLaggedAddedMassOverThePlates) {
  // The elastic plate: water at h_f = 1.5 x 2 mm, rubber 1100 kg/m^3, 5 mm.
  EXPECT_DOUBLE_EQ(acceleration_feedback_ratio(1000.0, 0.003, 1100.0, 0.005), 3.0 / 5.5);
  // Half the plate's mass per unit of interface, twice the ratio.
  EXPECT_DOUBLE_EQ(acceleration_feedback_ratio(1000.0, 0.003, 550.0, 0.005), 6.0 / 5.5);
  EXPECT_DOUBLE_EQ(acceleration_feedback_ratio(1000.0, 0.003, 1100.0, 0.0025), 6.0 / 5.5);
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(acceleration_feedback_ratio(bad, 0.003, 1100.0, 0.005), std::invalid_argument);
    EXPECT_THROW(acceleration_feedback_ratio(1000.0, 0.003, 1100.0, bad), std::invalid_argument);
  }
}

// Unset, the elastic plate takes the term (mu_a 0.55), and a plate of a
// twentieth of the water's density leaves it out (mu_a 12): with it that
// plate blows up within its first steps. As set, either way, means what it
// says. The coupler's cross-phase parameters follow the choice.
TEST(WallAccelerationChoice, TheCaseTakesItWhereItsFeedbackIsStable) {
  ASSERT_FALSE(elastic_plate_case().config.coupling().has_wall_acceleration());
  const auto rubber = read_wall_acceleration_choice(elastic_plate_case());
  EXPECT_TRUE(rubber.take);
  EXPECT_NEAR(rubber.feedback_ratio, 1000.0 * 0.003 / (1100.0 * 0.005), 1e-9);
  EXPECT_TRUE(contains(rubber.reason, "automatic")) << rubber.reason;

  const auto light = read_wall_acceleration_choice(elastic_plate_case({"solid.density=50"}));
  EXPECT_FALSE(light.take);
  EXPECT_GT(light.feedback_ratio, kMaxAccelerationFeedbackRatio);
  EXPECT_TRUE(contains(light.reason, "left out")) << light.reason;

  EXPECT_TRUE(read_wall_acceleration_choice(
                  elastic_plate_case({"solid.density=50", "coupling.wall_acceleration=true"}))
                  .take);
  const auto off =
      read_wall_acceleration_choice(elastic_plate_case({"coupling.wall_acceleration=false"}));
  EXPECT_FALSE(off.take);
  EXPECT_EQ(off.feedback_ratio, -1.0);
  EXPECT_TRUE(contains(off.reason, "as set")) << off.reason;

  const auto settings = [](std::vector<std::string> overrides) {
    return cosph::coupler::read_coupler_settings(elastic_plate_case(std::move(overrides)));
  };
  EXPECT_TRUE(settings({}).cross_phase.wall_acceleration);
  EXPECT_FALSE(settings({"solid.density=50"}).cross_phase.wall_acceleration);
  EXPECT_FALSE(settings({"coupling.interface=stress_sum"}).cross_phase.wall_acceleration);
}

}  // namespace

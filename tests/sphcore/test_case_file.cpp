// Case files (case_file.hpp): protobuf text with errors that name the file and
// line:column, and --set overrides that name the field they could not set.
#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "sphcore/case_file.hpp"
#include "sphcore/run_parameters.hpp"
#include "test_support.hpp"

namespace {

using cosph::testing::ScratchDir;
using sph::ConfigError;

const std::string kDamBreak = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

// The message of the ConfigError that body throws ("" and a failure if none).
template <class Body>
std::string config_error(Body body) {
  try {
    body();
  } catch (const ConfigError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no ConfigError thrown";
  return "";
}

TEST(CaseFile, LoadsTheDamBreak) {
  const sph::CaseFile c = sph::load_case(kDamBreak);
  EXPECT_EQ(c.path, kDamBreak);
  EXPECT_DOUBLE_EQ(c.config.fluid().spacing(), 0.008);
  ASSERT_EQ(c.config.fluid().water_size(), 1);
  EXPECT_DOUBLE_EQ(c.config.fluid().water(0).max().y(), 0.288);
  EXPECT_EQ(c.config.fluid().walls_size(), 3);
  EXPECT_DOUBLE_EQ(c.config.run().gravity().y(), -9.81);
}

TEST(CaseFile, MisspeltFieldNamesFileLineAndColumn) {
  ScratchDir dir("case_file");
  const std::string path = dir.file("typo.pbtxt");
  cosph::testing::write_text(path,
                             "title: \"typo\"\n"
                             "fluid {\n"
                             "  spacing: 0.01\n"
                             "    spacng: 0.02\n"
                             "}\n");
  const std::string message = config_error([&] { sph::load_case(path); });
  // "FILE:4:COLUMN: ..." (1-based; protobuf points at or just after the name).
  EXPECT_EQ(message.rfind(path + ":4:", 0), 0u) << message;
  const std::size_t column = path.size() + 3;
  ASSERT_GT(message.size(), column);
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(message[column]))) << message;
  EXPECT_NE(message.find("spacng"), std::string::npos) << message;
}

TEST(CaseFile, BadValueNamesFileLineAndColumn) {
  ScratchDir dir("case_file");
  const std::string path = dir.file("bad_value.pbtxt");
  cosph::testing::write_text(path, "run {\n  end_time: soon\n}\n");
  const std::string message = config_error([&] { sph::load_case(path); });
  EXPECT_EQ(message.rfind(path + ":2:", 0), 0u) << message;
}

TEST(CaseFile, MissingFileNamesThePath) {
  const std::string path = "/nonexistent/folder/no_such_case.pbtxt";
  const std::string message = config_error([&] { sph::load_case(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(CaseFileOverride, SetsNestedAndIndexedFields) {
  const sph::CaseFile c = sph::load_case(
      kDamBreak, {"run.end_time=0.06", "fluid.water[0].max.x=0.2", "fluid.walls[2].min.x=0.55",
                  "fluid.spacing=4e-3", "title=\"short\"", "run.gravity=x: 1 y: -2"});
  EXPECT_DOUBLE_EQ(c.config.run().end_time(), 0.06);
  EXPECT_DOUBLE_EQ(c.config.fluid().water(0).max().x(), 0.2);
  EXPECT_DOUBLE_EQ(c.config.fluid().water(0).max().y(), 0.288);  // untouched
  EXPECT_DOUBLE_EQ(c.config.fluid().walls(2).min().x(), 0.55);
  EXPECT_DOUBLE_EQ(c.config.fluid().walls(1).min().x(), -0.04);  // untouched
  EXPECT_DOUBLE_EQ(c.config.fluid().spacing(), 0.004);
  EXPECT_EQ(c.config.title(), "short");
  EXPECT_DOUBLE_EQ(c.config.run().gravity().x(), 1.0);
  EXPECT_DOUBLE_EQ(c.config.run().gravity().y(), -2.0);
}

TEST(CaseFileOverride, StringsNeedNoQuotes) {
  const sph::CaseFile c = sph::load_case(kDamBreak, {"title=short title"});
  EXPECT_EQ(c.config.title(), "short title");
}

TEST(CaseFileOverride, LaterOverrideWins) {
  const sph::CaseFile c = sph::load_case(kDamBreak, {"run.cfl=0.1", "run.cfl=0.2"});
  EXPECT_DOUBLE_EQ(c.config.run().cfl(), 0.2);
}

TEST(CaseFileOverride, UnknownFieldIsNamed) {
  sph::CaseFile c = sph::load_case(kDamBreak);
  const std::string message = config_error([&] { sph::apply_override(c, "fluid.spacingg=0.004"); });
  EXPECT_NE(message.find("spacingg"), std::string::npos) << message;
  EXPECT_NE(message.find(kDamBreak), std::string::npos) << message;
  EXPECT_NE(message.find("spacing,"), std::string::npos) << "lists the known fields: " << message;
  const std::string nested = config_error([&] { sph::apply_override(c, "fluid.water[0].top=1"); });
  EXPECT_NE(nested.find("'top'"), std::string::npos) << nested;
  EXPECT_NE(nested.find("fluid.water[0]"), std::string::npos) << nested;
}

TEST(CaseFileOverride, BadValueIsNamed) {
  sph::CaseFile c = sph::load_case(kDamBreak);
  const std::string message = config_error([&] { sph::apply_override(c, "fluid.spacing=abc"); });
  EXPECT_NE(message.find("fluid.spacing"), std::string::npos) << message;
  EXPECT_NE(message.find("'abc'"), std::string::npos) << message;
  EXPECT_DOUBLE_EQ(c.config.fluid().spacing(), 0.008) << "a failed override changed the case";
  const std::string int_field = config_error([&] { sph::apply_override(c, "run.threads=1.5"); });
  EXPECT_NE(int_field.find("run.threads"), std::string::npos) << int_field;
}

TEST(CaseFileOverride, MissingOrMisusedIndexIsNamed) {
  sph::CaseFile c = sph::load_case(kDamBreak);
  const std::string out_of_range =
      config_error([&] { sph::apply_override(c, "fluid.water[3].max.x=0.2"); });
  EXPECT_NE(out_of_range.find("water"), std::string::npos) << out_of_range;
  EXPECT_NE(out_of_range.find("no index 3"), std::string::npos) << out_of_range;
  const std::string no_index = config_error([&] { sph::apply_override(c, "fluid.water.max.x=1"); });
  EXPECT_NE(no_index.find("water[0]"), std::string::npos) << "suggests an index: " << no_index;
  const std::string extra_index =
      config_error([&] { sph::apply_override(c, "fluid.spacing[0]=0.1"); });
  EXPECT_NE(extra_index.find("spacing"), std::string::npos) << extra_index;
  const std::string malformed =
      config_error([&] { sph::apply_override(c, "fluid.water[x].max.x=1"); });
  EXPECT_NE(malformed.find("water[x]"), std::string::npos) << malformed;
}

TEST(CaseFileOverride, MalformedAssignmentsAreRefused) {
  sph::CaseFile c = sph::load_case(kDamBreak);
  for (const std::string bad : {"fluid.spacing", "=0.1", "fluid.spacing.x=1"}) {
    const std::string message = config_error([&] { sph::apply_override(c, bad); });
    EXPECT_NE(message.find(bad), std::string::npos) << message;
  }
}

TEST(CaseFile, NonFiniteNumbersAnywhereAreRefusedNamingTheField) {
  ScratchDir dir("case_file");
  const std::string path = dir.file("level.pbtxt");
  // In a list of numbers, written in the file, not set on the command line.
  cosph::testing::write_text(path,
                             "run { end_time: 1 }\n"
                             "fluid { gauges { level_probes: 0.1 level_probes: inf } }\n");
  EXPECT_EQ(config_error([&] { sph::load_case(path); }),
            path + ": fluid.gauges.level_probes[1]: must be a finite number, got inf");
  EXPECT_EQ(config_error([&] { sph::load_case(kDamBreak, {"fluid.walls[2].max.y=nan"}); }),
            kDamBreak + ": fluid.walls[2].max.y: must be a finite number, got nan");
}

TEST(CaseFile, RequireNamesFileFieldAndReason) {
  const sph::CaseFile c = sph::load_case(kDamBreak);
  EXPECT_NO_THROW(sph::require(true, c, "fluid.spacing", "unused"));
  const std::string message =
      config_error([&] { sph::require(false, c, "fluid.spacing", "must be positive"); });
  EXPECT_EQ(message, kDamBreak + ": fluid.spacing: must be positive");
}

// Both solvers read their spacing and smoothing length through
// read_resolution: h_factor defaults to 1.3, and each error names its block.
TEST(Resolution, SmoothingLengthIsTheFactorTimesTheSpacing) {
  const sph::CaseFile c = sph::load_case(kDamBreak);
  const sph::Resolution given = sph::read_resolution(c, "solid", 0.002, 1.5);
  EXPECT_EQ(given.dx, 0.002);
  EXPECT_DOUBLE_EQ(given.h, 0.003);
  EXPECT_DOUBLE_EQ(sph::read_resolution(c, "solid", 0.002, 0.0).h, 1.3 * 0.002);
}

TEST(Resolution, BadSpacingOrFactorNamesTheBlocksField) {
  const sph::CaseFile c = sph::load_case(kDamBreak);
  EXPECT_EQ(config_error([&] { sph::read_resolution(c, "solid", 0.0, 1.3); }),
            kDamBreak + ": solid.spacing: must be positive, got 0 m");
  EXPECT_EQ(
      config_error([&] { sph::read_resolution(c, "fluid", 0.01, 2.5); }),
      kDamBreak + ": fluid.h_factor: must lie in [1, 2] (the shipped cases use 1.3 to 2), got 2.5");
  EXPECT_NE(config_error([&] { sph::read_resolution(c, "fluid", 0.01, 0.5); }).find("h_factor"),
            std::string::npos);
}

}  // namespace

// Bad case files through cosph-fluid (STYLE.md habit 8): one line on stderr
// naming the file, the field and the reason, and exit code 2 (bad input, as
// opposed to 1 for a run that failed).
#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

#include "fluid_scene.hpp"
#include "fluid_test_support.hpp"
#include "test_support.hpp"

namespace cosph::fluid {
namespace {

using cosph::testing::read_text;
using cosph::testing::ScratchDir;
using cosph::testing::write_text;
using testing::run_cosph_fluid;

const std::string kDamBreak = std::string(COSPH_SOURCE_DIR) + "/cases/dam_break.pbtxt";

// The dam-break case with one line (which must be there) replaced.
std::string dam_break_with(const std::string& line, const std::string& replacement) {
  std::string text = read_text(kDamBreak);
  const std::size_t at = text.find(line);
  EXPECT_NE(at, std::string::npos) << "the dam-break case no longer has: " << line;
  if (at != std::string::npos) text.replace(at, line.size(), replacement);
  return text;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// What cosph-fluid says on stderr as it refuses the case at `path` with
// `overrides`; the refusal must be bad input, exit code 2.
std::string refusal(const std::string& path, const std::vector<std::string>& overrides = {}) {
  ScratchDir dir("bad_input");
  const auto run = run_cosph_fluid(path, dir.file("out"), overrides);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  return run.err;
}

// A case with one line of the dam break replaced, written to `dir`.
std::string written_dam_break(const ScratchDir& dir, const std::string& name,
                              const std::string& line, const std::string& replacement) {
  const std::string path = dir.file(name);
  write_text(path, dam_break_with(line, replacement));
  return path;
}

TEST(BadInput, UnknownFieldGivesFileLineAndColumn) {
  ScratchDir dir("bad_input");
  const std::string path =
      written_dam_break(dir, "typo.pbtxt", "  density: 1000", "  densty: 1000");
  const std::string err = refusal(path);
  // "cosph-fluid: error: FILE:LINE:COLUMN: ... "densty"", the line the case
  // has it on.
  const std::string text = read_text(kDamBreak);
  const auto line = 1 + std::count(text.begin(), text.begin() + text.find("  density: 1000"), '\n');
  EXPECT_TRUE(contains(err, "cosph-fluid: error: " + path + ":" + std::to_string(line) + ":"))
      << err;
  EXPECT_TRUE(contains(err, "densty")) << err;
}

TEST(BadInput, NegativeSpacingNamesTheField) {
  const std::string err = refusal(kDamBreak, {"fluid.spacing=-0.008"});
  EXPECT_TRUE(contains(err, kDamBreak + ": fluid.spacing: must be positive")) << err;
}

TEST(BadInput, MissingCaseFileNamesThePath) {
  ScratchDir dir("bad_input");
  const std::string path = dir.file("no_such_case.pbtxt");
  const std::string err = refusal(path);
  EXPECT_TRUE(contains(err, path)) << err;
}

TEST(BadInput, UnknownOverrideNamesTheField) {
  const std::string err = refusal(kDamBreak, {"fluid.spasing=0.004"});
  EXPECT_TRUE(contains(err, "spasing")) << err;
}

TEST(BadInput, WallsThatDoNotCloseAreRefused) {
  ScratchDir dir("bad_input");
  const std::string path = written_dam_break(
      dir, "no_right_wall.pbtxt", "  walls { min { x: 0.576 y: 0 } max { x: 0.616 y: 0.4 } }", "");
  const std::string err = refusal(path);
  EXPECT_TRUE(contains(err, path + ": fluid.walls: do not close fluid.water[0]")) << err;
  EXPECT_TRUE(contains(err, "to the right")) << err;
}

TEST(BadInput, WallOverlappingTheWaterIsRefused) {
  const std::string err = refusal(kDamBreak, {"fluid.walls[1].max.x=0.05"});
  EXPECT_TRUE(contains(err, "fluid.walls[1]: overlaps fluid.water[0]")) << err;
}

// A coupled case: the fluid alone refuses it, so the check is called as
// cosph-case calls it before the launcher starts anything.
TEST(BadInput, WaterOverlappingTheSolidIsRefused) {
  const std::string elastic_plate = std::string(COSPH_SOURCE_DIR) + "/cases/elastic_plate.pbtxt";
  const auto refusal = [&](const std::string& water_right_edge) -> std::string {
    const sph::CaseFile case_file =
        sph::load_case(elastic_plate, {"fluid.water[0].max.x=" + water_right_edge});
    try {
      check_walls_close(case_file, read_fluid_parameters(case_file));
    } catch (const sph::ConfigError& error) {
      return error.what();
    }
    return "";
  };
  // The water column made to reach 2 mm into the plate, and up to it.
  EXPECT_TRUE(
      contains(refusal("0.102"), elastic_plate + ": solid.body[0]: overlaps fluid.water[0]"))
      << refusal("0.102");
  EXPECT_EQ(refusal("0.1"), "");
}

TEST(BadInput, WallThinnerThanTheSupportIsRefused) {
  // The right wall cut to 10 mm, less than 2h = 20.8 mm.
  const std::string err = refusal(kDamBreak, {"fluid.walls[2].min.x=0.606"});
  EXPECT_TRUE(contains(err, kDamBreak + ": fluid.walls[2]: is 0.01 m thick")) << err;
  EXPECT_TRUE(contains(err, "2h")) << err;
}

TEST(BadInput, MalformedCommandLine) {
  const std::string binary = std::string(COSPH_BIN_DIR) + "/cosph-fluid";
  EXPECT_EQ(WEXITSTATUS(std::system(("'" + binary + "' --case 2>/dev/null").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system(("'" + binary + "' --bogus x 2>/dev/null").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system(("'" + binary + "' --help >/dev/null").c_str())), 0);
}

}  // namespace
}  // namespace cosph::fluid

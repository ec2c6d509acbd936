// A case's regions read as shapes (sphcore/region_reader.hpp): every bad
// outline is refused naming the file, the field and the reason.
#include "sphcore/region_reader.hpp"

#include <google/protobuf/text_format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_support.hpp"

namespace {

using cosph::testing::ScratchDir;

struct Reading {
  sph::CaseFile case_file;
  cosph::config::Region region;
};

Reading reading(const std::string& case_path, const std::string& region_text) {
  Reading r;
  r.case_file.path = case_path;
  EXPECT_TRUE(google::protobuf::TextFormat::ParseFromString(region_text, &r.region)) << region_text;
  return r;
}

std::string refusal(const Reading& r, const std::string& field) {
  try {
    sph::read_region(r.region, r.case_file, field);
  } catch (const sph::ConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(RegionReader, EachKindOfOutlineIsRead) {
  ScratchDir dir("regions");
  const std::string case_path = dir.file("tank.pbtxt");
  cosph::testing::write_text(dir.file("gate.csv"),
                             "# a gate\n0,0\n0.01, 0\n\n0.01,0.08 # top\n0,0.08\n");
  const auto box = reading(case_path, "min { x: 0 y: 0 } max { x: 1 y: 0.5 }");
  EXPECT_EQ(sph::read_region(box.region, box.case_file, "w").kind(), sph::Shape::Kind::box);
  const auto file = reading(case_path, "polygon_file: \"gate.csv\"");
  const sph::Shape gate = sph::read_region(file.region, file.case_file, "solid.body[0]");
  EXPECT_EQ(gate.kind(), sph::Shape::Kind::polygon);
  EXPECT_TRUE(gate.contains(sph::Vec2(0.005, 0.04)));
  EXPECT_FALSE(gate.contains(sph::Vec2(0.015, 0.04)));
  const auto holed =
      reading(case_path,
              "polygon { point { x: 0 y: 0 } point { x: 0.4 y: 0 } point { x: 0.6 y: 0.1 }"
              " point { x: 0 y: 0.2 } }"
              " subtract { circle { center { x: 0.2 y: 0.08 } radius: 0.04 } }");
  const sph::Shape water = sph::read_region(holed.region, holed.case_file, "fluid.water[0]");
  EXPECT_FALSE(water.contains(sph::Vec2(0.2, 0.08)));
  EXPECT_TRUE(water.contains(sph::Vec2(0.1, 0.15)));
}

// A band keeps its thickness through a corner: the line (0, 0)-(1, 0)-(2, 1)
// turns by 45 degrees at (1, 0), where the outline meets at the mitre,
// (t / 2) / cos(22.5 deg) from the corner along the mean normal.
TEST(RegionReader, ABandIsItsLineThickenedEvenly) {
  ScratchDir dir("regions");
  const auto kinked = reading(dir.file("gate.pbtxt"),
                              "band { point { x: 0 y: 0 } point { x: 1 y: 0 }"
                              " point { x: 2 y: 1 } thickness: 0.1 }");
  const sph::Shape band = sph::read_region(kinked.region, kinked.case_file, "solid.body[0]");
  ASSERT_EQ(band.kind(), sph::Shape::Kind::polygon);
  for (const sph::Vec2& inside : {sph::Vec2(0.5, 0.049), sph::Vec2(0.5, -0.049),
                                  sph::Vec2(1.5, 0.5), sph::Vec2(1.5 - 0.035, 0.5 + 0.035)})
    EXPECT_TRUE(band.contains(inside)) << inside.transpose();
  for (const sph::Vec2& outside : {sph::Vec2(0.5, 0.051), sph::Vec2(0.5, -0.051),
                                   sph::Vec2(1.5 - 0.036, 0.5 + 0.036), sph::Vec2(2.1, 1.0)})
    EXPECT_FALSE(band.contains(outside)) << outside.transpose();
  const double mitre = 0.05 / std::cos(std::numbers::pi / 8);
  const sph::Vec2 normal(-std::sin(std::numbers::pi / 8), std::cos(std::numbers::pi / 8));
  for (const double side : {1.0, -1.0}) {
    EXPECT_TRUE(band.contains(sph::Vec2(1.0, 0.0) + side * 0.999 * mitre * normal)) << side;
    EXPECT_FALSE(band.contains(sph::Vec2(1.0, 0.0) + side * 1.001 * mitre * normal)) << side;
  }
  // Straight, it is the rectangle.
  const auto straight = reading(dir.file("gate.pbtxt"),
                                "band { point { x: 0 y: 0 } point { x: 1 y: 0 } thickness: 0.1 }");
  const sph::Bounds b =
      sph::read_region(straight.region, straight.case_file, "solid.body[0]").bounds();
  EXPECT_NEAR((b.min - sph::Vec2(0.0, -0.05)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((b.max - sph::Vec2(1.0, 0.05)).norm(), 0.0, 1e-15);
}

TEST(RegionReader, BadOutlinesAreRefusedNamingFileFieldAndReason) {
  ScratchDir dir("regions");
  const std::string case_path = dir.file("tank.pbtxt");
  const auto expect = [&](const std::string& text, const std::string& field,
                          const std::string& message) {
    const std::string got = refusal(reading(case_path, text), field);
    EXPECT_EQ(got.rfind(case_path + ": ", 0), 0u) << got;
    EXPECT_NE(got.find(message), std::string::npos) << "expected: " << message << "\ngot: " << got;
  };
  expect("polygon { point { x: 0 y: 0 } point { x: 1 y: 0 } }", "fluid.water[0]",
         "fluid.water[0].polygon: a polygon needs at least 3 points, got 2");
  expect(
      "polygon { point { x: 0 y: 0 } point { x: 1 y: 1 } point { x: 1 y: 0 } point { x: 0 y: 1 } }",
      "fluid.walls[1]", "fluid.walls[1].polygon: the polygon intersects itself");
  expect("circle { center { x: 0 y: 0 } radius: 0 }", "fluid.walls[2]",
         "fluid.walls[2].circle.radius: must be positive, got 0 m");
  expect("circle { center { x: 0 y: 0 } radius: -0.1 }", "solid.body[0]",
         "solid.body[0].circle.radius: must be positive, got -0.1 m");
  expect("", "solid.clamp[0]", "solid.clamp[0]: needs an outline");
  expect("min { x: 0 y: 0 } max { x: 1 y: 1 } circle { radius: 1 }", "fluid.water[0]",
         "fluid.water[0]: has more than one outline");
  expect("min { x: 1 y: 0 } max { x: 0 y: 1 }", "fluid.water[0]",
         "fluid.water[0]: max (0, 1) m must lie above and to the right of min (1, 0) m");
  expect("min { x: 0 y: 0 } max { x: 1 y: 1 } subtract { circle { radius: 0 } }", "fluid.water[0]",
         "fluid.water[0].subtract[0].circle.radius: must be positive");
  expect(
      "polygon_file: \"missing.csv\"", "solid.body[0]",
      "solid.body[0].polygon_file: " + dir.file("missing.csv") + ": cannot read the outline file");
  cosph::testing::write_text(dir.file("bad.csv"), "0,0\n1,0\n1;1\n");
  expect("polygon_file: \"bad.csv\"", "solid.body[0]",
         dir.file("bad.csv") + ":3: expected \"x,y\" in metres, got \"1;1\"");
  expect("band { point { x: 0 y: 0 } thickness: 0.1 }", "solid.body[0]",
         "solid.body[0].band: a band needs at least 2 points, got 1");
  expect("band { point { x: 0 y: 0 } point { x: 1 y: 0 } }", "solid.body[0]",
         "solid.body[0].band: the thickness must be positive, got 0 m");
  expect("band { point { x: 0 y: 0 } point { x: 1 y: 0 } point { x: 0.5 y: 0.1 } thickness: 0.01 }",
         "solid.body[0]", "solid.body[0].band: the line turns by");
  expect("band { point { x: 0 y: 0 } point { x: 0 y: 0 } point { x: 1 y: 0 } thickness: 0.01 }",
         "solid.body[0]", "solid.body[0].band: points 1 and 2 coincide");
  // A bend tighter than half the thickness: the inner side crosses itself.
  expect(
      "band { point { x: 0 y: 0 } point { x: 0.1 y: 0 } point { x: 0.15 y: 0.05 }"
      " point { x: 0.15 y: 0.1 } point { x: 0.1 y: 0.15 } point { x: 0 y: 0.15 } thickness: 0.2 }",
      "solid.body[0]",
      "solid.body[0].band: the line crosses itself or bends more tightly than half the "
      "thickness: its outline, the line offset by 0.1 m to either side, is not a simple polygon "
      "(the polygon intersects itself");
  cosph::testing::write_text(dir.file("short.csv"), "0,0\n1,0\n");
  expect("polygon_file: \"short.csv\"", "solid.body[0]",
         "solid.body[0].polygon_file: " + dir.file("short.csv") +
             ": a polygon needs at least 3 points, got 2");
}

}  // namespace

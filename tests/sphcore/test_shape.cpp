// Regions of a scene (sphcore/shape.hpp): what they hold, how deep a point
// lies, their surface, and the particle lattice that fills them.
#include "sphcore/shape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using sph::Shape;
using sph::Vec2;

// The box fill every case used before regions had other shapes, as its
// build rounded it (x in one fused multiply-add, y's product rounded on its
// own): the reference a box's fill must equal bit for bit.
std::vector<Vec2> box_lattice(const Vec2& min, const Vec2& max, double spacing) {
  const long nx = std::lround((max.x() - min.x()) / spacing);
  const long ny = std::lround((max.y() - min.y()) / spacing);
  std::vector<Vec2> points;
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const volatile double row_offset = (static_cast<double>(j) + 0.5) * spacing;
      points.emplace_back(std::fma(static_cast<double>(i) + 0.5, spacing, min.x()),
                          min.y() + row_offset);
    }
  return points;
}

// A box fills exactly as the boxes of every case always have, bit for bit,
// also where its width is a whole number of spacings only up to round-off.
// The oscillating plate's box is one whose lattice rounds differently when
// its y is fused too.
TEST(Shape, ABoxFillsExactlyAsBefore) {
  struct Box {
    Vec2 min, max;
    double dx;
  };
  for (const Box& box :
       {Box{{-0.024, 0.0}, {0.144, 0.288}, 0.008},
        Box{{-0.024, 0.0}, {0.1439999, 0.2880001}, 0.008}, Box{{-0.024, 0.0}, {0.6, 0.024}, 0.008},
        Box{{-0.02, -0.01}, {0.2, 0.01}, 0.00125}}) {
    const auto expected = box_lattice(box.min, box.max, box.dx);
    const auto points = sph::fill(Shape::box(box.min, box.max), box.dx);
    ASSERT_EQ(points.size(), expected.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(points[i].x(), expected[i].x());
      EXPECT_EQ(points[i].y(), expected[i].y());
    }
  }
}

TEST(Shape, APolygonOfTheBoxOutlineFillsTheSameCells) {
  const double dx = 0.01;
  const std::vector<Vec2> square{{0, 0}, {0.2, 0}, {0.2, 0.1}, {0, 0.1}};
  const auto from_box = sph::fill(Shape::box(Vec2(0, 0), Vec2(0.2, 0.1)), dx);
  for (bool clockwise : {false, true}) {
    auto outline = square;
    if (clockwise) std::reverse(outline.begin(), outline.end());
    const auto from_polygon = sph::fill(Shape::polygon(outline), dx);
    ASSERT_EQ(from_polygon.size(), from_box.size()) << "clockwise " << clockwise;
    for (std::size_t i = 0; i < from_box.size(); ++i)
      EXPECT_NEAR((from_polygon[i] - from_box[i]).norm(), 0.0, 1e-15);
  }
}

// A circle's lattice holds its area: pi r^2 / dx^2 cells to within the cells
// its rim cuts (about 2 pi r / dx of them, half in and half out).
TEST(Shape, ACircleFillsItsArea) {
  const double r = 0.05, dx = 0.001;
  const auto points = sph::fill(Shape::circle(Vec2(0.3, 0.2), r), dx);
  const double cells = std::numbers::pi * r * r / (dx * dx);
  EXPECT_NEAR(static_cast<double>(points.size()), cells, 2.0 * std::numbers::pi * r / dx * 0.1);
  for (const Vec2& x : points) EXPECT_LE((x - Vec2(0.3, 0.2)).norm(), r);
}

TEST(Shape, ASubtractedCircleLeavesItsHoleEmpty) {
  Shape water = Shape::polygon({{0, 0}, {0.4, 0}, {0.6, 0.1}, {0, 0.2}});
  water.subtract(Shape::circle(Vec2(0.2, 0.08), 0.04));
  const double dx = 0.005;
  const auto points = sph::fill(water, dx);
  const auto outline = sph::fill(Shape::polygon({{0, 0}, {0.4, 0}, {0.6, 0.1}, {0, 0.2}}), dx);
  for (const Vec2& x : points) EXPECT_GT((x - Vec2(0.2, 0.08)).norm(), 0.04);
  const double removed = static_cast<double>(outline.size() - points.size());
  EXPECT_NEAR(removed, std::numbers::pi * 0.04 * 0.04 / (dx * dx),
              2.0 * std::numbers::pi * 0.04 / dx);
  EXPECT_FALSE(water.contains(Vec2(0.2, 0.08)));
  EXPECT_TRUE(water.contains(Vec2(0.2, 0.15)));
  EXPECT_FALSE(water.contains(Vec2(0.5, 0.15)));  // above the sloped edge
}

TEST(Shape, AConcavePolygonHoldsOnlyItsOwnPoints) {
  const Shape ell = Shape::polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_TRUE(ell.contains(Vec2(0.5, 1.5)));
  EXPECT_TRUE(ell.contains(Vec2(1.5, 0.5)));
  EXPECT_FALSE(ell.contains(Vec2(1.5, 1.5)));
  EXPECT_TRUE(ell.contains(Vec2(1.0, 1.5)));  // on an edge
  EXPECT_FALSE(ell.contains(Vec2(-0.1, 0.5)));
}

TEST(Shape, DepthAndNearestSurface) {
  const Shape box = Shape::box(Vec2(0, 0), Vec2(1, 0.5));
  EXPECT_DOUBLE_EQ(box.depth(Vec2(0.5, 0.4)), 0.1);
  EXPECT_EQ(box.nearest_surface(Vec2(0.5, 0.4)).outward, Vec2(0, 1));
  EXPECT_EQ(box.depth(Vec2(2, 2)), 0.0);

  // A triangle: a sloped beach rising to the right, 45 degrees.
  const Shape beach = Shape::polygon({{0, 0}, {1, 0}, {1, 1}});
  EXPECT_NEAR(beach.nearest_surface(Vec2(0.7, 0.2)).distance, 0.2, 1e-15);  // the floor
  const auto s = beach.nearest_surface(Vec2(0.6, 0.5));
  EXPECT_NEAR(s.distance, 0.1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(s.outward.x(), -1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(s.outward.y(), 1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(beach.top_at(0.25), 0.25, 1e-15);

  const Shape disc = Shape::circle(Vec2(0, 0), 1);
  EXPECT_NEAR(disc.depth(Vec2(0.6, 0)), 0.4, 1e-15);
  EXPECT_NEAR(disc.nearest_surface(Vec2(0, 2)).outward.y(), 1.0, 1e-15);
  EXPECT_NEAR(disc.top_at(0.6), 0.8, 1e-15);

  // Inside a hole's rim the nearest surface is the hole's, facing into it.
  Shape ring = Shape::circle(Vec2(0, 0), 1);
  ring.subtract(Shape::circle(Vec2(0, 0), 0.5));
  const auto inner = ring.nearest_surface(Vec2(0.6, 0));
  EXPECT_NEAR(inner.distance, 0.1, 1e-15);
  EXPECT_NEAR(inner.outward.x(), -1.0, 1e-15);
}

TEST(Shape, UnusablePolygonsAreNamed) {
  EXPECT_EQ(*sph::polygon_defect({{0, 0}, {1, 0}}), "a polygon needs at least 3 points, got 2");
  EXPECT_EQ(*sph::polygon_defect({{0, 0}, {1, 0}, {2, 0}}), "edges 1 and 3 overlap");
  EXPECT_EQ(*sph::polygon_defect({{0, 0}, {2, 0}, {1, 1e-14}}), "the polygon has no area");
  const auto bow_tie = sph::polygon_defect({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  ASSERT_TRUE(bow_tie);
  EXPECT_NE(bow_tie->find("intersects itself: edge 1 (points 1-2) meets edge 3"), std::string::npos)
      << *bow_tie;
  EXPECT_TRUE(sph::polygon_defect({{0, 0}, {1, 0}, {1, 0}, {0, 1}}));
  EXPECT_FALSE(sph::polygon_defect({{0, 0}, {0.4, 0}, {0.6, 0.1}, {0, 0.2}}));
  EXPECT_FALSE(sph::polygon_defect({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}));
}

}  // namespace

namespace {

// A segment meets a region where it has a point in it: an end inside, or a
// crossing of the outline outside every hole, however thin the region.
TEST(Shape, ASegmentMeetsTheRegionItTouches) {
  const Shape sheet = Shape::box(Vec2(0.5, -1.0), Vec2(0.5001, 1.0));  // thinner than the step
  EXPECT_TRUE(sheet.meets(Vec2(0.45, 0.0), Vec2(0.55, 0.0)));
  EXPECT_FALSE(sheet.meets(Vec2(0.45, 1.5), Vec2(0.55, 1.5)));  // above it
  EXPECT_TRUE(sheet.meets(Vec2(0.45, 1.0), Vec2(0.55, 1.0)));   // along its top edge
  const Shape disc = Shape::circle(Vec2(0.0, 0.0), 1.0);
  EXPECT_TRUE(disc.meets(Vec2(-2.0, 0.5), Vec2(2.0, 0.5)));
  EXPECT_FALSE(disc.meets(Vec2(-2.0, 1.01), Vec2(2.0, 1.01)));
  const Shape wedge = Shape::polygon({{0, 0}, {1, 0}, {1, 1}});
  EXPECT_TRUE(wedge.meets(Vec2(0.2, 0.5), Vec2(0.9, 0.5)));   // crosses the slope
  EXPECT_FALSE(wedge.meets(Vec2(0.1, 0.5), Vec2(0.4, 0.5)));  // stays above it
  // A ring (a disc less a smaller one): a segment inside the hole meets
  // nothing; one from the hole out crosses the ring.
  Shape ring = Shape::circle(Vec2(0.0, 0.0), 1.0);
  ring.subtract(Shape::circle(Vec2(0.0, 0.0), 0.8));
  EXPECT_FALSE(ring.meets(Vec2(-0.5, 0.0), Vec2(0.5, 0.0)));
  EXPECT_TRUE(ring.meets(Vec2(0.5, 0.0), Vec2(1.5, 0.0)));
  // A tank (a box less its inside) with a drain cut through its floor: a
  // step down through the drain meets nothing, one beside it the floor.
  Shape tank = Shape::box(Vec2(-0.1, -0.1), Vec2(1.1, 1.0));
  tank.subtract(Shape::box(Vec2(0.0, 0.0), Vec2(1.0, 2.0)));
  tank.subtract(Shape::box(Vec2(0.4, -0.5), Vec2(0.6, 0.5)));
  EXPECT_FALSE(tank.meets(Vec2(0.5, 0.05), Vec2(0.5, -0.05)));
  EXPECT_TRUE(tank.meets(Vec2(0.3, 0.05), Vec2(0.3, -0.05)));
}

TEST(Shape, ThicknessIsTheLargestInscribedCircle) {
  EXPECT_EQ(sph::thickness(Shape::box(Vec2(0, 0), Vec2(0.3, 0.024)), 1.0), 0.024);  // exact
  EXPECT_NEAR(sph::thickness(Shape::circle(Vec2(1, 2), 0.05), 0.001), 0.1, 0.002);
  // A right triangle with legs a, b: inradius (a + b - c) / 2.
  const double a = 0.4, b = 0.2, c = std::hypot(a, b);
  EXPECT_NEAR(sph::thickness(Shape::polygon({{0, 0}, {a, 0}, {a, b}}), 0.001), a + b - c, 0.002);
}

}  // namespace

"""Bad regions are refused by the real `cosph-case plan`, before any process
starts, with one line naming the case file, the field and the reason
(proto/case.proto Region; docs/scenes.md): a self-intersecting polygon, too
few points, a radius that is not positive, a band bent too sharply for its
thickness, a missing or malformed outline
file, water overlapping a wall or a solid body, and a tank that leaks.

COSPH_TEST_BIN is the folder of the built cosph-case (ctest sets it; default
build/bin).
"""
import os
import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
REAL_BIN = Path(os.environ.get("COSPH_TEST_BIN", REPO / "build" / "bin"))

# A tank 0.4 m wide of one polygon wall (a U, 0.03 m thick, 2h = 0.026 m,
# its left side 0.3 m high, its right 0.25 m), water 0.1 m deep in it.
TANK = """
run {{ end_time: 0.01 gravity {{ x: 0 y: -9.81 }} }}
fluid {{
  spacing: 0.01
  density: 1000
  water {{ {water} }}
  walls {{ polygon {{
    point {{ x: -0.03 y: 0.3 }} point {{ x: -0.03 y: -0.03 }} point {{ x: 0.43 y: -0.03 }}
    point {{ x: 0.43 y: 0.25 }} point {{ x: 0.4 y: 0.25 }} point {{ x: 0.4 y: 0 }}
    point {{ x: 0 y: 0 }} point {{ x: 0 y: 0.3 }} }} }}
  {walls}
}}
{solid}
"""
WATER = "min { x: 0 y: 0 } max { x: 0.4 y: 0.1 }"
SOLID_BLOCK = """solid {{
  spacing: 0.005 density: 1100 youngs_modulus: 1e6 poisson_ratio: 0.3
  body {{ {body} }}
}}"""


class BadShapes(unittest.TestCase):
    def setUp(self):
        self.case_exe = REAL_BIN / "cosph-case"
        if not os.access(self.case_exe, os.X_OK):
            if os.environ.get("COSPH_TEST_BIN"):
                self.fail(f"{self.case_exe} is missing (COSPH_TEST_BIN={REAL_BIN})")
            self.skipTest(f"no built {self.case_exe}; set COSPH_TEST_BIN")
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph-shapes-"))
        self.case = self.tmp / "tank.pbtxt"

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def plan(self, water=WATER, walls="", body=None):
        solid = SOLID_BLOCK.format(body=body) if body is not None else ""
        self.case.write_text(TANK.format(water=water, walls=walls, solid=solid))
        return subprocess.run([str(self.case_exe), "plan", str(self.case)], capture_output=True,
                              text=True, timeout=60, stdin=subprocess.DEVNULL)

    def assertRefused(self, proc, field, reason):
        self.assertEqual(proc.returncode, 2, proc.stderr + proc.stdout)
        self.assertIn(f"{self.case}: {field}: {reason}", proc.stderr)
        self.assertEqual(proc.stderr.count("\n"), 1, proc.stderr)

    def test_the_polygon_tank_itself_is_accepted(self):
        proc = self.plan()
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout.split(), ["cosph-fluid"])

    def test_a_self_intersecting_polygon(self):
        bow_tie = ("polygon { point { x: 0 y: 0 } point { x: 0.4 y: 0.1 } "
                   "point { x: 0.4 y: 0 } point { x: 0 y: 0.1 } }")
        self.assertRefused(self.plan(water=bow_tie), "fluid.water[0].polygon",
                           "the polygon intersects itself: edge 1 (points 1-2) meets edge 3 "
                           "(points 3-4)")

    def test_fewer_than_three_points(self):
        self.assertRefused(
            self.plan(walls="walls { polygon { point { x: 0 y: 0.3 } point { x: 0.4 y: 0.3 } } }"),
            "fluid.walls[1].polygon", "a polygon needs at least 3 points, got 2")

    def test_a_radius_that_is_not_positive(self):
        for radius in ("0", "-0.02"):
            with self.subTest(radius=radius):
                self.assertRefused(
                    self.plan(body=f"circle {{ center {{ x: 0.2 y: 0.2 }} radius: {radius} }}"),
                    "solid.body[0].circle.radius", f"must be positive, got {radius} m")
        hole = "subtract { circle { center { x: 0.2 y: 0.05 } radius: -1 } }"
        self.assertRefused(self.plan(water=WATER + " " + hole),
                           "fluid.water[0].subtract[0].circle.radius", "must be positive")

    def test_a_band_bent_too_sharply(self):
        # Above the water, so that only the band's own outline is at fault.
        corner = ("band { point { x: 0.1 y: 0.15 } point { x: 0.3 y: 0.15 } "
                  "point { x: 0.2 y: 0.17 } thickness: 0.01 }")
        self.assertRefused(self.plan(body=corner), "solid.body[0].band",
                           "the line turns by 168.69 degrees at point 2: a corner must turn by "
                           "less than 90")
        tight = ("band { point { x: 0.1 y: 0.2 } point { x: 0.2 y: 0.2 } "
                 "point { x: 0.25 y: 0.25 } point { x: 0.25 y: 0.3 } point { x: 0.2 y: 0.35 } "
                 "point { x: 0.1 y: 0.35 } thickness: 0.18 }")
        self.assertRefused(self.plan(body=tight), "solid.body[0].band",
                           "the line crosses itself or bends more tightly than half the "
                           "thickness: its outline, the line offset by 0.09 m to either side, is "
                           "not a simple polygon (the polygon intersects itself")
        # The same line, thin enough for its bends, is accepted.
        self.assertEqual(self.plan(body=tight.replace("0.18 }", "0.01 }")).returncode, 0)

    def test_a_missing_outline_file(self):
        proc = self.plan(walls='walls { polygon_file: "no_such_gate.csv" }')
        self.assertRefused(proc, "fluid.walls[1].polygon_file",
                           f"{self.tmp / 'no_such_gate.csv'}: cannot read the outline file")

    def test_a_malformed_outline_file_names_its_line(self):
        (self.tmp / "block.csv").write_text("# a block\n0.1,0.2\n0.2;0.2\n0.2,0.3\n")
        proc = self.plan(walls='walls { polygon_file: "block.csv" }')
        self.assertRefused(proc, "fluid.walls[1].polygon_file",
                           f"{self.tmp / 'block.csv'}:3: expected \"x,y\" in metres, "
                           "got \"0.2;0.2\"")

    def test_water_overlapping_a_wall(self):
        stone = "walls { circle { center { x: 0.2 y: 0.03 } radius: 0.02 } }"
        self.assertRefused(self.plan(walls=stone), "fluid.walls[1]",
                           "overlaps fluid.water[0]: water at (")
        # The same stone cut out of the water is no overlap.
        hole = "subtract { circle { center { x: 0.2 y: 0.03 } radius: 0.02 } }"
        proc = self.plan(water=WATER + " " + hole, walls=stone)
        self.assertEqual(proc.returncode, 0, proc.stderr)

    def test_water_overlapping_a_solid_body(self):
        wedge = ("polygon { point { x: 0.1 y: 0.08 } point { x: 0.2 y: 0.08 } "
                 "point { x: 0.15 y: 0.2 } }")
        self.assertRefused(self.plan(body=wedge), "solid.body[0]",
                           "overlaps fluid.water[0]: water at (")
        # Lifted 2 cm clear of the water surface, it is accepted.
        lifted = wedge.replace("0.08", "0.12")
        self.assertEqual(self.plan(body=lifted).returncode, 0)

    def test_a_tank_that_leaks(self):
        # Water higher than the U's lower right side runs over it: the
        # water nearest the opening is the right column's just above the rim.
        tall = "min { x: 0 y: 0 } max { x: 0.4 y: 0.28 }"
        self.assertRefused(self.plan(water=tall), "fluid.walls",
                           "do not close fluid.water[0]: water at (0.395, 0.255) m can flow out "
                           "to the right")

    def test_a_tank_with_a_hole_in_its_floor_leaks_through_the_bottom(self):
        # The same tank as a box less its inside and less a 2 cm drain.
        walls_cut = ("walls { min { x: 0.5 y: -0.03 } max { x: 0.96 y: 0.3 } "
                     "subtract { min { x: 0.53 y: 0 } max { x: 0.93 y: 0.4 } } "
                     "subtract { min { x: 0.72 y: -0.1 } max { x: 0.74 y: 0.1 } } }")
        water = "min { x: 0.53 y: 0 } max { x: 0.93 y: 0.1 }"
        proc = self.plan(water=WATER + " } water { " + water, walls=walls_cut)
        self.assertRefused(proc, "fluid.walls", "do not close fluid.water[1]: water at (0.725, ")
        self.assertIn("can flow out through the bottom", proc.stderr)


if __name__ == "__main__":
    unittest.main()

"""The snapshot series (NAME.xdmf + NAME_NNNNNN.h5) read by an XDMF reader that
is not ours: meshio's TimeSeriesReader (Debian's python3-meshio). Short runs
of the dam break (the water solver) and of the oscillating plate alone (both
solid models) must give, at every snapshot, the times, the points, one vertex
cell per particle (ParaView's default Xdmf3 reader shows no particle without
the topology's connectivity) and every array with the values and the type
h5py reads: integers for ids, kind codes and flags.

Run by ctest; by hand: COSPH_BIN=build/bin /usr/bin/python3 -m unittest discover -s tests/snapshots
"""
import glob
import os
import sys
import unittest
import xml.etree.ElementTree as ET

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "case_runs"))
import case_runs  # noqa: E402

try:
    from meshio.xdmf import TimeSeriesReader
except ImportError as error:  # a missing reader must fail the test, not skip it
    raise ImportError("meshio is missing: run scripts/install_deps.sh (python3-meshio)") from error

# The fields the solvers write as integers (Snapshot::add_scalar of int).
INTEGER_FIELDS = {"id", "kind", "spray", "failed", "clamped"}
# What each XDMF DataItem must declare for the dataset it names.
DECLARED = {np.dtype("int32"): ("Int", "4"), np.dtype("float64"): ("Float", "8")}


class SnapshotSeriesChecks:
    """Mixed into a case_runs.CaseRunTest: NAME.xdmf of its run must read back
    through meshio as the .h5 files hold it. EXPECTED_INTEGERS: the integer
    fields that series has."""
    NAME = None
    EXPECTED_INTEGERS = set()

    def setUp(self):
        super().setUp()
        self.index = os.path.join(self.out, f"{self.NAME}.xdmf")
        self.files = sorted(glob.glob(os.path.join(self.out, f"{self.NAME}_[0-9]*.h5")))
        self.assertGreaterEqual(len(self.files), 3, self.log)

    def read_h5(self, path):
        with h5py.File(path, "r") as f:
            return float(f.attrs["time"]), {key: f[key][()] for key in f.keys()}

    def test_times_follow_the_snapshot_files(self):
        with TimeSeriesReader(self.index) as reader:
            self.assertEqual(reader.num_steps, len(self.files))
            reader.read_points_cells()
            times = [reader.read_data(k)[0] for k in range(reader.num_steps)]
        expected = [self.read_h5(path)[0] for path in self.files]
        np.testing.assert_allclose(times, expected, rtol=1e-11, atol=1e-15)
        self.assertEqual(times[0], 0.0)
        self.assertTrue(np.all(np.diff(times) > 0), times)

    def test_every_snapshot_has_one_vertex_cell_per_particle(self):
        with TimeSeriesReader(self.index) as reader:
            for k, path in enumerate(self.files):
                # meshio reads the mesh of one grid (it expects a fixed mesh);
                # particles move, so each grid is read as the mesh in turn.
                reader.mesh_grid = reader.collection[k]
                points, cells = reader.read_points_cells()
                _, stored = self.read_h5(path)
                n = len(stored["position"])
                self.assertGreater(n, 0)
                np.testing.assert_array_equal(points, stored["position"], path)
                self.assertEqual([block.type for block in cells], ["vertex"], path)
                self.assertEqual(cells[0].data.shape, (n, 1), path)
                np.testing.assert_array_equal(cells[0].data[:, 0], np.arange(n), path)

    def test_arrays_read_back_with_their_values_and_integer_types(self):
        with TimeSeriesReader(self.index) as reader:
            reader.read_points_cells()
            for k, path in enumerate(self.files):
                _, point_data, _ = reader.read_data(k)
                _, stored = self.read_h5(path)
                fields = set(stored) - {"position", "connectivity"}
                self.assertEqual(set(point_data), fields, path)
                self.assertEqual(fields & INTEGER_FIELDS, self.EXPECTED_INTEGERS, path)
                for name in fields:
                    expected_type = "int32" if name in INTEGER_FIELDS else "float64"
                    self.assertEqual(point_data[name].dtype, np.dtype(expected_type), name)
                    self.assertEqual(len(point_data[name]), len(stored["position"]), name)
                    np.testing.assert_array_equal(point_data[name], stored[name], name)
                self.assertEqual(len(np.unique(point_data["id"])), len(point_data["id"]))

    def test_index_declares_each_datasets_type(self):
        # ParaView's readers convert to the declared type, not the stored one.
        root = ET.parse(self.index).getroot()
        self.assertEqual(root.get("Version"), "3.0")
        checked = 0
        for item in root.iter("DataItem"):
            path, dataset = item.text.strip().split(":")
            with h5py.File(os.path.join(self.out, path), "r") as f:
                stored = f[dataset]
                self.assertEqual(DECLARED[stored.dtype],
                                 (item.get("NumberType"), item.get("Precision")), item.text)
                self.assertEqual([int(d) for d in item.get("Dimensions").split()],
                                 list(stored.shape), item.text)
            checked += 1
        self.assertGreater(checked, 0)


class DamBreakSeries(SnapshotSeriesChecks, case_runs.CaseRunTest):
    CASE = "dam_break"
    NAME = "fluid"
    SETTINGS = ["run.end_time=0.004", "run.snapshot_interval=0.001", "run.threads=1"]
    EXPECTED_INTEGERS = {"id", "kind", "spray"}

    def test_water_and_walls_have_their_kind_codes(self):
        with TimeSeriesReader(self.index) as reader:
            reader.read_points_cells()
            kind = reader.read_data(0)[1]["kind"]
        # Kind::water = 0, Kind::wall = 1 (fluid/src/fluid_particles.hpp).
        self.assertEqual(set(np.unique(kind)), {0, 1})


class OscillatingPlateSeries(SnapshotSeriesChecks, case_runs.CaseRunTest):
    CASE = "oscillating_plate"
    NAME = "solid"
    SETTINGS = ["run.end_time=0.004", "run.snapshot_interval=0.001"]
    EXPECTED_INTEGERS = {"id", "failed", "clamped"}

    def test_clamp_is_flagged(self):
        with TimeSeriesReader(self.index) as reader:
            reader.read_points_cells()
            clamped = reader.read_data(0)[1]["clamped"]
        self.assertEqual(set(np.unique(clamped)), {0, 1})


class TotalLagrangianPlateSeries(OscillatingPlateSeries):
    SETTINGS = OscillatingPlateSeries.SETTINGS + ["solid.model=total_lagrangian"]


if __name__ == "__main__":
    unittest.main()

"""scripts/regenerate_results.py reruns every script that writes a results
table: a table whose script is not one of its steps would be left stale by a
change of a default, unseen."""
import glob
import os
import re
import sys
import unittest
from types import SimpleNamespace

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "scripts"))
import regenerate_results as rr  # noqa: E402

# Not a step: it runs the user's own build of the peer (its --peer-command).
NOT_STEPS = {"peer/compare_elastic_gate.py"}


def arguments(**given):
    return SimpleNamespace(**{"only": [], "start": None, "accuracy": False, **given})


class RegenerateResults(unittest.TestCase):
    def test_every_results_table_has_its_script_among_the_steps(self):
        scripts = {command[0] for _, command, _ in rr.STEPS}
        tables = sorted(glob.glob(os.path.join(REPO, "docs", "results", "*.md")))
        self.assertGreater(len(tables), 20)
        for table in tables:
            with open(table) as text:
                named = re.search(r"scripts/([\w/]+\.py)", text.read())
            self.assertIsNotNone(named, f"{table} names no script that wrote it")
            if named.group(1) in NOT_STEPS:
                continue
            self.assertIn(named.group(1), scripts, f"{os.path.basename(table)}: no step runs it")

    def test_every_step_names_a_script_of_the_repository(self):
        for name, command, kind in rr.STEPS:
            self.assertTrue(os.path.exists(os.path.join(REPO, "scripts", command[0])), name)
            self.assertIn(kind, ("accuracy", "timing"), name)
        self.assertEqual(len(set(rr.step_names())), len(rr.STEPS), "a step name twice")

    def test_readers_come_after_the_runs_they_read(self):
        order = rr.step_names()
        for reader in ("sensor_support", "far_wall_profile"):
            self.assertLess(order.index("pressure_noise"), order.index(reader))
        self.assertEqual(order[-1], "speed_accuracy")  # reads the validation tables' points

    def test_a_selection_keeps_the_order_and_refuses_unknown_steps(self):
        self.assertEqual([s[0] for s in rr.chosen_steps(arguments(start="speed_accuracy"))],
                         ["speed_accuracy"])
        chosen = rr.chosen_steps(arguments(only=["speed_accuracy", "dam_break"]))
        self.assertEqual([s[0] for s in chosen], ["dam_break", "speed_accuracy"])
        self.assertTrue(all(s[2] == "accuracy" for s in rr.chosen_steps(arguments(accuracy=True))))
        with self.assertRaises(SystemExit) as refused:
            rr.chosen_steps(arguments(only=["no_such_step"]))
        self.assertIn("no_such_step", str(refused.exception))


if __name__ == "__main__":
    unittest.main()

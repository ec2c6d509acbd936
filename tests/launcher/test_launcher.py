"""Tests of the cosph launcher (coupler/cosph) against fake executables.

Run from the repository root:
    /usr/bin/python3 -m unittest discover -s tests/launcher -v

Each test copies the launcher into a temporary repository layout
(tmp/repo/coupler/cosph, tmp/repo/cases/*.pbtxt), so the case lookup is
tested against known cases, and points COSPH_BIN at fake_bin/, whose
programs are steered by FAKE_* variables (see fake_bin/fake_solver.py) and
record their pids and arguments in FAKE_DIR.
"""
import json
import os
import pty
import re
import shutil
import signal
import subprocess
import tempfile
import time
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCRIPT = HERE.parent.parent / "coupler" / "cosph"
FAKE_BIN = HERE / "fake_bin"
THREE = "cosph-coupler cosph-fluid cosph-solid-jaumann"
ALL = "cosph-coupler,cosph-fluid,cosph-solid-jaumann"


def alive(pid):
    """True while the process exists and is not a zombie (a killed orphan may
    stay a zombie if this container's init does not reap it)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError, IndexError):
        return False
    return state not in ("Z", "X")


class LauncherTest(unittest.TestCase):
    def setUp(self):
        # Short temp path: the default endpoint is a unix socket inside --out.
        self.tmp = Path(tempfile.mkdtemp(prefix="cosph-"))
        repo = self.tmp / "repo"
        (repo / "coupler").mkdir(parents=True)
        shutil.copy2(SCRIPT, repo / "coupler" / "cosph")
        shutil.copytree(SCRIPT.parent / "cosph_launcher", repo / "coupler" / "cosph_launcher")
        self.script = repo / "coupler" / "cosph"
        cases = repo / "cases"
        cases.mkdir()
        (cases / "dam_break.pbtxt").write_text("name: 'dam_break'\n")
        (cases / "sloshing.pbtxt").write_text("name: 'sloshing'\n")
        (cases / "README.md").write_text("not a case\n")
        self.state = self.tmp / "state"
        self.state.mkdir()
        self.out = self.tmp / "out"
        self.env = {k: v for k, v in os.environ.items()
                    if not k.startswith(("COSPH_", "FAKE_"))}
        self.env.update(COSPH_BIN=str(FAKE_BIN), FAKE_DIR=str(self.state))

    def tearDown(self):
        # Safety net only: a leftover here means a test has already failed.
        for pid in self.recorded_pids().values():
            if alive(pid):
                os.kill(pid, signal.SIGKILL)
        shutil.rmtree(self.tmp, ignore_errors=True)

    # -- helpers

    def launch(self, *args, **env):
        return subprocess.Popen([str(self.script), *args], env={**self.env, **env},
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True,
                                start_new_session=True)

    def cosph(self, *args, timeout=15, **env):
        proc = self.launch(*args, **env)
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, err = proc.communicate()
            self.fail(f"launcher did not finish in {timeout} s\n{out}\n{err}")
        return proc.returncode, out, err

    def run_case(self, *extra, **env):
        return self.cosph("run", "dam_break", "--out", str(self.out), *extra, **env)

    def recorded_pids(self):
        """{file stem: pid} for every process (and grandchild) the fakes started."""
        return {p.name[:-len(".pid")]: int(p.read_text())
                for p in self.state.glob("*.pid")}

    def fake_args(self, name):
        return json.loads((self.state / f"{name}.args").read_text())

    def bin_with_real_keys(self):
        """COSPH_BIN for a tcp run: the fakes, and the built cosph-keys that
        makes the run's keys (skips without a build, fails if
        COSPH_TEST_BIN names one without it)."""
        real = Path(os.environ.get("COSPH_TEST_BIN", HERE.parent.parent / "build" / "bin"))
        if not os.access(real / "cosph-keys", os.X_OK):
            if os.environ.get("COSPH_TEST_BIN"):
                self.fail(f"{real / 'cosph-keys'} is missing")
            self.skipTest(f"no built {real / 'cosph-keys'}; set COSPH_TEST_BIN")
        folder = self.tmp / "bin"
        if not folder.exists():
            shutil.copytree(FAKE_BIN, folder, symlinks=True)
            (folder / "cosph-keys").symlink_to((real / "cosph-keys").resolve())
        return str(folder)

    def wait_for_pids(self, names, timeout=5.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if all((self.state / f"{n}.pid").exists() for n in names):
                return
            time.sleep(0.02)
        self.fail(f"fakes {names} did not start; have {sorted(self.recorded_pids())}")

    def assert_all_gone(self, expected_count):
        pids = self.recorded_pids()
        self.assertEqual(len(pids), expected_count, pids)
        deadline = time.monotonic() + 1.0   # a SIGKILLed orphan needs a moment
        while time.monotonic() < deadline and any(alive(p) for p in pids.values()):
            time.sleep(0.02)
        self.assertEqual({n: p for n, p in pids.items() if alive(p)}, {},
                         "processes left running")

    # -- the script itself

    def test_script_is_executable_python3(self):
        self.assertTrue(os.access(SCRIPT, os.X_OK))
        self.assertEqual(SCRIPT.read_text().splitlines()[0], "#!/usr/bin/python3")

    def test_help(self):
        rc, out, _ = self.cosph("--help")
        self.assertEqual(rc, 0)
        self.assertIn("run", out)
        rc, out, _ = self.cosph("run", "--help")
        self.assertEqual(rc, 0)
        for text in ("--out", "--set", "--endpoint", "--quiet", "dam_break, sloshing"):
            self.assertIn(text, out)

    # -- successful runs

    def test_single_process_success(self):
        rc, out, err = self.run_case("--set", "fluid.spacing=0.01")
        self.assertEqual(rc, 0, err)
        # Passed-through lines carry the prefix; progress lines are parsed, not echoed.
        self.assertIn("[fluid] starting, case ", out)
        self.assertIn("[fluid] warning: this is a fake solver", err)
        self.assertNotIn("progress t=", out + err)
        self.assertRegex(err, r"cosph: progress: t = 0\.\d+ / 1 s, \d+\.\d%")
        # Summary names the outputs.
        self.assertIn("simulated 1 s", out)
        self.assertIn("timeseries.csv", out)
        self.assertIn("fluid.xdmf", out)
        # Reproducibility files.
        self.assertEqual((self.out / "case.pbtxt").read_text(), "name: 'dam_break'\n")
        command = (self.out / "command.txt").read_text()
        self.assertIn("cosph-case plan ", command)
        self.assertIn(f"cosph-fluid --case {self.tmp}/repo/cases/dam_break.pbtxt "
                      f"--out {self.out} --set fluid.spacing=0.01", command)
        # One process: no endpoint.
        self.assertEqual(self.fake_args("cosph-fluid"),
                         ["--case", str(self.tmp / "repo/cases/dam_break.pbtxt"),
                          "--out", str(self.out), "--set", "fluid.spacing=0.01"])
        self.assert_all_gone(1)

    def test_three_processes_get_endpoint_and_sets(self):
        rc, _, err = self.run_case("--set", "a=1", "--set", "b.c=x y",
                                   FAKE_PLAN=THREE, FAKE_STEPS="4")
        self.assertEqual(rc, 0, err)
        for name in THREE.split():
            args = self.fake_args(name)
            self.assertEqual(args[args.index("--endpoint") + 1],
                             f"ipc://{self.out}/private/coupler.sock")
            self.assertEqual(args[4:8], ["--set", "a=1", "--set", "b.c=x y"])
        self.assertEqual(json.loads((self.state / "plan.args").read_text())[2:],
                         ["--set", "a=1", "--set", "b.c=x y"])
        # The socket's folder is the user's alone, whatever the umask.
        self.assertEqual((self.out / "private").stat().st_mode & 0o777, 0o700)
        self.assert_all_gone(3)

    def test_summary_gives_each_process_its_cpu_time(self):
        # The solid computes for 10 x 0.05 s; the others sleep as long.
        rc, out, err = self.run_case(FAKE_PLAN=THREE, FAKE_BUSY="cosph-solid-jaumann")
        self.assertEqual(rc, 0, err)
        match = re.search(r"cosph: CPU time: coupler ([\d.]+) s, fluid ([\d.]+) s, "
                          r"solid-jaumann ([\d.]+) s", out)
        self.assertIsNotNone(match, out)
        coupler, fluid, solid = map(float, match.groups())
        self.assertGreaterEqual(solid, 0.45)
        self.assertLess(max(coupler, fluid), solid - 0.3)

    def test_spinning_openmp_threads_are_warned_of_when_processes_share_cores(self):
        warning = "cosph: warning: OMP_WAIT_POLICY=active: 3 processes share"
        rc, _, err = self.run_case("--overwrite", FAKE_PLAN=THREE, FAKE_STEPS="2",
                                   OMP_WAIT_POLICY="active")
        self.assertEqual(rc, 0, err)
        self.assertIn(warning, err)
        rc, _, err = self.run_case("--overwrite", FAKE_PLAN=THREE, FAKE_STEPS="2",
                                   OMP_WAIT_POLICY="passive")
        self.assertEqual(rc, 0, err)
        self.assertNotIn("OMP_WAIT_POLICY", err)
        # One process has the cores to itself: spinning is its own business.
        rc, _, err = self.run_case("--overwrite", OMP_WAIT_POLICY="active")
        self.assertEqual(rc, 0, err)
        self.assertNotIn("OMP_WAIT_POLICY", err)

    def fake_cores(self, name):
        return json.loads((self.state / f"{name}.cores").read_text())

    @unittest.skipIf(len(os.sched_getaffinity(0)) < 2, "needs two cores")
    def test_multi_rate_run_gives_each_solver_cores_of_its_own(self):
        allowed = sorted(os.sched_getaffinity(0))
        rc, _, err = self.run_case("--overwrite", FAKE_PLAN=THREE + " separate-cores",
                                   FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        fluid, solid = self.fake_cores("cosph-fluid"), self.fake_cores("cosph-solid-jaumann")
        self.assertEqual(sorted(fluid + solid), allowed)   # disjoint, and all of them
        self.assertGreaterEqual(len(fluid), len(solid))
        self.assertEqual(self.fake_cores("cosph-coupler"), allowed)
        self.assertIn("cosph: multi-rate run: cosph-fluid on core", err)
        command = (self.out / "command.txt").read_text()
        self.assertIn(f"taskset -c {','.join(map(str, solid))} ", command)
        # Asked not to, or synchronised: every process may run anywhere.
        for extra, plan in (("--no-pin", THREE + " separate-cores"), (None, THREE)):
            rc, _, err = self.run_case("--overwrite", *([extra] if extra else []), FAKE_PLAN=plan,
                                       FAKE_STEPS="2")
            self.assertEqual(rc, 0, err)
            for name in THREE.split():
                self.assertEqual(self.fake_cores(name), allowed, (extra, plan, name))
            self.assertNotIn("multi-rate run", err)
            self.assertNotIn("taskset", (self.out / "command.txt").read_text())

    def test_endpoint_option(self):
        rc, _, err = self.run_case("--overwrite", "--endpoint", "tcp://127.0.0.1:5555",
                                   FAKE_PLAN="cosph-fluid cosph-solid-jaumann", FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        self.assertEqual(self.fake_args("cosph-solid-jaumann")[-2:],
                         ["--endpoint", "tcp://127.0.0.1:5555"])

    def test_tcp_run_gets_fresh_keys_only_the_user_can_read(self):
        keys = self.out / "private"
        seen = set()
        for _ in range(2):
            rc, _, err = self.run_case("--endpoint", "tcp://127.0.0.1:5555", "--overwrite",
                                       FAKE_PLAN=THREE, FAKE_STEPS="2",
                                       COSPH_BIN=self.bin_with_real_keys())
            self.assertEqual(rc, 0, err)
            coupler = self.fake_args("cosph-coupler")
            self.assertEqual(coupler[coupler.index("--keys"):],
                             ["--keys", f"{keys}/coupler.key", "--allow-key", f"{keys}/fluid.pub",
                              "--allow-key", f"{keys}/solid.pub"])
            solid = self.fake_args("cosph-solid-jaumann")
            self.assertEqual(solid[solid.index("--keys"):],
                             ["--keys", f"{keys}/solid.key", "--coupler-key", f"{keys}/coupler.pub"])
            self.assertEqual(keys.stat().st_mode & 0o777, 0o700)
            for name in ("coupler", "fluid", "solid"):
                for suffix in (".key", ".pub"):
                    self.assertEqual((keys / (name + suffix)).stat().st_mode & 0o777, 0o600)
            seen.add((keys / "coupler.pub").read_text())
        self.assertEqual(len(seen), 2, "a run reused the keys of the one before")

    def test_wildcard_address_needs_bind_any(self):
        rc, _, err = self.run_case("--endpoint", "tcp://0.0.0.0:5555", FAKE_PLAN=THREE)
        self.assertEqual(rc, 2, err)
        self.assertIn("--endpoint tcp://0.0.0.0:5555 listens on every network interface", err)
        self.assertIn("--bind-any", err)
        self.assertFalse((self.state / "cosph-coupler.args").exists())
        rc, _, err = self.run_case("--endpoint", "tcp://0.0.0.0:5555", "--bind-any",
                                   FAKE_PLAN=THREE, FAKE_STEPS="2",
                                   COSPH_BIN=self.bin_with_real_keys())
        self.assertEqual(rc, 0, err)
        self.assertEqual(self.fake_args("cosph-coupler")[-1], "--bind-any")

    def test_quiet_shows_no_progress(self):
        rc, _, err = self.run_case("--quiet", FAKE_STEPS="4")
        self.assertEqual(rc, 0, err)
        self.assertNotIn("progress", err)
        self.assertIn("[fluid] warning", err)   # other output still passes

    def test_terminal_gets_updating_status_line(self):
        master, slave = pty.openpty()
        proc = subprocess.Popen([str(self.script), "run", "dam_break", "--out", str(self.out)],
                                env={**self.env, "FAKE_STEPS": "8", "FAKE_INTERVAL": "0.08"},
                                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                stderr=slave, start_new_session=True)
        os.close(slave)
        chunks = []
        while True:   # read until the launcher closes the terminal (EIO)
            try:
                data = os.read(master, 4096)
            except OSError:
                break
            if not data:
                break
            chunks.append(data)
        os.close(master)
        self.assertEqual(proc.wait(timeout=10), 0)
        text = b"".join(chunks).decode()
        self.assertRegex(text, r"\r\x1b\[Kt = [\d.]+ / 1 s, \d+\.\d%, .*steps/s")
        self.assertNotIn("cosph: progress:", text)   # that is the non-terminal form

    # -- case and argument errors

    def test_case_by_name_with_extension_and_by_path(self):
        rc, _, err = self.cosph("run", "sloshing.pbtxt", "--out", str(self.out))
        self.assertEqual(rc, 0, err)
        self.assertEqual((self.out / "case.pbtxt").read_text(), "name: 'sloshing'\n")
        elsewhere = self.tmp / "my_case.pbtxt"
        elsewhere.write_text("name: 'mine'\n")
        rc, _, err = self.cosph("run", str(elsewhere), "--out", str(self.out), "--overwrite")
        self.assertEqual(rc, 0, err)
        self.assertEqual((self.out / "case.pbtxt").read_text(), "name: 'mine'\n")

    def test_unknown_case_lists_available(self):
        rc, _, err = self.cosph("run", "dam_brake", "--out", str(self.out))
        self.assertEqual(rc, 2)
        self.assertIn("unknown case 'dam_brake'", err)
        self.assertIn("available cases: dam_break, sloshing", err)
        self.assertNotIn("README", err)
        self.assertFalse((self.state / "plan.args").exists())
        self.assertFalse(self.out.exists())

    def test_bad_set_is_refused(self):
        for bad in ("fluid.spacing", "=3", "fluid.spacing=", "two words=1"):
            with self.subTest(bad=bad):
                rc, _, err = self.run_case("--set", "ok=1", "--set", bad)
                self.assertEqual(rc, 2)
                self.assertIn(f"bad --set '{bad}'", err)
                self.assertIn("FIELD=VALUE", err)
        self.assertFalse((self.state / "plan.args").exists())

    def test_missing_bin_folder(self):
        rc, _, err = self.run_case(COSPH_BIN=str(self.tmp / "nowhere"))
        self.assertEqual(rc, 2)
        self.assertIn(str(self.tmp / "nowhere"), err)
        self.assertIn("cmake --preset release && cmake --build --preset release -j2", err)
        env_without = {k: v for k, v in self.env.items() if k != "COSPH_BIN"}
        proc = subprocess.run([str(self.script), "run", "dam_break", "--out", str(self.out)],
                              env=env_without, capture_output=True, text=True, timeout=10)
        self.assertEqual(proc.returncode, 2)
        self.assertIn(str(self.tmp / "repo/build/bin"), proc.stderr)

    def test_planned_executable_missing(self):
        rc, _, err = self.run_case(FAKE_PLAN="cosph-coupler cosph-magic")
        self.assertEqual(rc, 2)
        self.assertIn("cosph-magic not found", err)
        self.assertEqual(self.recorded_pids(), {})

    def test_plan_error_passes_through(self):
        message = "dam_break.pbtxt: field fluid.spacing: must be positive, got -1"
        rc, out, err = self.run_case(FAKE_PLAN_ERROR=message, FAKE_PLAN_CODE="4")
        self.assertEqual(rc, 4)
        self.assertEqual(err, message + "\n")   # verbatim, nothing added
        self.assertEqual(out, "")
        self.assertTrue((self.state / "plan.args").exists())
        self.assertEqual(self.recorded_pids(), {})   # nothing started

    # -- the output folder: locked while a run writes, an earlier run's not mixed in

    def test_a_second_run_into_a_running_folder_is_refused_naming_the_first(self):
        first = self.launch("run", "dam_break", "--out", str(self.out), FAKE_HANG="cosph-fluid")
        self.wait_for_pids(["cosph-fluid"])
        rc, _, err = self.run_case("--overwrite")
        os.killpg(first.pid, signal.SIGINT)
        first.communicate(timeout=15)
        self.assertEqual(rc, 2, err)
        self.assertIn(f"{self.out} is in use by another run (pid {first.pid}, started ", err)
        self.assertIn(f"run dam_break --out {self.out})", err)
        # Nothing of the first run was touched, and nothing of the second started.
        self.assertEqual(sorted(self.recorded_pids()), ["cosph-fluid"])
        self.assertTrue((self.out / "case.pbtxt").is_file())
        # The lock goes with the run: now the folder may be reused.
        rc, _, err = self.run_case("--overwrite", FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)

    def test_a_resume_into_a_running_folder_is_refused(self):
        first = self.launch("run", "dam_break", "--out", str(self.out), FAKE_HANG="cosph-fluid")
        self.wait_for_pids(["cosph-fluid"])
        rc, _, err = self.cosph("resume", str(self.out))
        os.killpg(first.pid, signal.SIGINT)
        first.communicate(timeout=15)
        self.assertEqual(rc, 2, err)
        self.assertIn(f"{self.out} is in use by another run (pid {first.pid}, started ", err)

    def test_a_folder_with_an_earlier_run_is_refused_without_overwrite(self):
        rc, _, err = self.run_case(FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        # A longer earlier run's later snapshot, checkpoint and plot, and a file of the user's.
        for name in ("fluid_000041.h5", "fluid.xdmf", "timeseries.csv.partial",
                     "checkpoints/fluid_000000100.h5", "plots/front.png", "notes.txt"):
            (self.out / name).parent.mkdir(exist_ok=True)
            (self.out / name).write_text("earlier\n")
        (self.state / "cosph-fluid.pid").unlink()
        rc, _, err = self.run_case(FAKE_STEPS="2")
        self.assertEqual(rc, 2, err)
        self.assertIn(f"{self.out} holds the output of an earlier run (", err)
        self.assertIn("give --overwrite to replace it", err)
        self.assertEqual(self.recorded_pids(), {}, "a process started in a refused folder")
        self.assertTrue((self.out / "fluid_000041.h5").exists(), "refused, yet removed")

        rc, _, err = self.run_case("--overwrite", FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        # The earlier run's files are gone, the user's stays, and this run wrote its own.
        left = sorted(str(p.relative_to(self.out)) for p in self.out.rglob("*") if p.is_file())
        self.assertEqual(left, [".cosph.lock", "case.pbtxt", "command.txt", "fluid.xdmf",
                                "notes.txt", "timeseries.csv"])
        self.assertNotEqual((self.out / "fluid.xdmf").read_text(), "earlier\n")

    def test_rerunning_a_folders_own_case_keeps_it(self):
        rc, _, err = self.run_case(FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        own = self.out / "case.pbtxt"
        rc, _, err = self.cosph("run", str(own), "--out", str(self.out), "--overwrite",
                                FAKE_STEPS="2")
        self.assertEqual(rc, 0, err)
        self.assertEqual(own.read_text(), "name: 'dam_break'\n")

    # -- failures

    def test_one_of_three_fails_others_are_stopped(self):
        start = time.monotonic()
        rc, _, err = self.run_case(FAKE_PLAN=THREE, FAKE_FAIL="cosph-solid-jaumann",
                                   FAKE_HANG="cosph-coupler,cosph-fluid",
                                   FAKE_GRANDCHILD=ALL)
        self.assertLess(time.monotonic() - start, 4.0)
        self.assertEqual(rc, 3)
        self.assertIn("cosph: cosph-solid-jaumann failed (exit code 3): error: solid-jaumann diverged", err)
        self.assertNotIn("cosph-fluid failed", err)   # stopped by us, not a failure
        # The others' lines on stopping come after the cause's; the last names it again.
        self.assertEqual(err.strip().splitlines()[-1],
                         "cosph: the run stopped because cosph-solid-jaumann failed (exit code 3): "
                         "see its error above")
        self.assert_all_gone(6)   # three fakes and the sleep each one started

    def test_killed_by_signal(self):
        rc, _, err = self.run_case(FAKE_FAIL="cosph-fluid", FAKE_FAIL_SIGNAL="9")
        self.assertEqual(rc, 1)
        self.assertIn("cosph: cosph-fluid failed (killed by signal 9 (SIGKILL)): "
                      "error: fluid diverged", err)

    def test_sigterm_ignored_escalates_to_sigkill(self):
        start = time.monotonic()
        rc, _, err = self.run_case(FAKE_PLAN="cosph-fluid cosph-solid-jaumann",
                                   FAKE_FAIL="cosph-solid-jaumann", FAKE_HANG="cosph-fluid",
                                   FAKE_IGNORE_TERM="cosph-fluid", COSPH_TERM_GRACE_S="0.5")
        self.assertEqual(rc, 3)
        self.assertIn("cosph-fluid did not stop, killing it", err)
        self.assertLess(time.monotonic() - start, 4.0)
        self.assert_all_gone(2)

    def test_straggler_is_stopped(self):
        rc, _, err = self.run_case(FAKE_PLAN="cosph-fluid cosph-solid-jaumann", FAKE_STEPS="3",
                                   FAKE_HANG="cosph-solid-jaumann", COSPH_STRAGGLER_S="0.5")
        self.assertEqual(rc, 1)
        self.assertIn("cosph-solid-jaumann failed (still running 0.5 s after cosph-fluid finished)",
                      err)
        self.assert_all_gone(2)

    # -- signals to the launcher

    def interrupt(self, sig, **env):
        proc = self.launch("run", "dam_break", "--out", str(self.out), FAKE_PLAN=THREE,
                           FAKE_HANG=ALL, FAKE_GRANDCHILD=ALL, **env)
        try:
            self.wait_for_pids(THREE.split())
            time.sleep(0.2)
            start = time.monotonic()
            os.kill(proc.pid, sig)   # the launcher only, as a terminal's Ctrl-C would
            out, err = proc.communicate(timeout=8)
        finally:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.communicate()
        return proc.returncode, time.monotonic() - start, out, err

    def test_sigint_stops_all_children(self):
        rc, elapsed, out, err = self.interrupt(signal.SIGINT)
        self.assertEqual(rc, 130, err)
        self.assertLess(elapsed, 3.0)
        for name in THREE.split():
            # SIGINT (not SIGTERM/SIGKILL) reached each, so it wrote its snapshot.
            self.assertTrue((self.state / f"{name}.sigint").exists(), name)
        self.assertIn("[fluid] writing final snapshot", out)
        self.assert_all_gone(6)

    def test_sigterm_to_launcher_forwards_sigint(self):
        rc, _, _, err = self.interrupt(signal.SIGTERM)
        self.assertEqual(rc, 130, err)
        self.assertTrue((self.state / "cosph-solid-jaumann.sigint").exists())
        self.assert_all_gone(6)

    def test_child_ignoring_sigint_is_killed(self):
        rc, elapsed, _, err = self.interrupt(signal.SIGINT, FAKE_IGNORE_INT="cosph-coupler",
                                             COSPH_INT_GRACE_S="0.5")
        self.assertEqual(rc, 130, err)
        self.assertIn("cosph-coupler did not stop, killing it", err)
        self.assertLess(elapsed, 3.0)
        self.assert_all_gone(6)

    def test_launcher_killed_hard_leaves_no_children(self):
        # SIGKILL cannot be handled; the kernel's parent-death signal stops the
        # children instead of leaving them orphaned. The fakes stay silent
        # (FAKE_INTERVAL), so a write to the dead launcher's pipe cannot be
        # what stops them.
        proc = self.launch("run", "dam_break", "--out", str(self.out), FAKE_PLAN=THREE,
                           FAKE_HANG=ALL, FAKE_INTERVAL="30")
        try:
            self.wait_for_pids(THREE.split())
            os.kill(proc.pid, signal.SIGKILL)
            proc.communicate(timeout=5)
        finally:
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.communicate()
        self.assert_all_gone(3)


if __name__ == "__main__":
    unittest.main()

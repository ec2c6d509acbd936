#!/usr/bin/python3
"""The Antoci plate in vacuum with the continuum solids, against the same
exact reference as the shell (scripts/validate_shell.py): the first-mode
period of the Timoshenko beam in plane strain.

The plate (L = 0.079 m, t = 5 mm, E = 12 MPa, nu = 0.4, rho = 1100 kg/m^3)
is cases/oscillating_plate.pbtxt reshaped with --set, as issue 39 measured
it: the oscillating plate's numerical settings (artificial viscosity and
stress) and its clamp rule, a clamp as long as the plate is thick, with the
shell case's first-mode start (tip speed 1.1 m/s). Each solid and option
runs at 5 particles across (the elastic plate case's spacing, 1 mm) and 10:
  Jaumann, linear velocity gradient (the elastic plate case's),
  Jaumann, quadratic velocity gradient (the oscillating plate case's),
  total-Lagrangian, its default hourglass control.
Then the same solids at 10 across on SPHinXsys's nearly incompressible
rubber (E = 7.8 MPa, nu = 0.47), against that rubber's own beam periods.
Writes docs/results/continuum_plate_in_vacuum.md and, with each run's wall
and CPU time, docs/results/plate_in_vacuum_continuum_points.json for
scripts/speed_accuracy.py.

usage: /usr/bin/python3 scripts/continuum_plate_in_vacuum.py [--out DIR] [--reuse] [--bin DIR]
"""
import pathlib

import cosph_results as cr
import validate_oscillating_plate as oscillating_plate
import validate_shell as shell

ROOT = pathlib.Path(cr.REPO)
CASE = ROOT / "cases" / "oscillating_plate.pbtxt"
ACROSS = [5, 10]
TIP_SPEED = 1.1  # m/s, as cases/shell_plate.pbtxt
END_TIME = 0.25  # s: three downward crossings of the free end, as the shell's runs
# (label, executable, settings)
SOLIDS = [
    ("Jaumann, linear gradient", "cosph-solid-jaumann",
     ["solid.model=jaumann", "solid.velocity_gradient=linear"]),
    ("Jaumann, quadratic gradient", "cosph-solid-jaumann",
     ["solid.model=jaumann", "solid.velocity_gradient=quadratic"]),
    (f"total-Lagrangian, alpha {oscillating_plate.default_hourglass():g}", "cosph-solid-tl",
     ["solid.model=total_lagrangian"]),
]


# SPHinXsys's rubber (its elastic gate: docs/validation.md, "The peer on its own
# scene"): nearly incompressible, where a continuum SPH solid may stiffen.
PEER_RUBBER = (7.8e6, 0.47)  # E (Pa), nu
PEER_RUBBER_ACROSS = 10


def plate_settings(across, youngs_modulus=None, poisson_ratio=None):
    """The oscillating plate's case reshaped into the Antoci plate (its rubber
    unless another modulus and Poisson ratio are given)."""
    youngs_modulus = shell.E if youngs_modulus is None else youngs_modulus
    poisson_ratio = shell.NU if poisson_ratio is None else poisson_ratio
    dx, half, clamp = shell.T_THICK / across, shell.T_THICK / 2, -shell.T_THICK
    return [f"solid.spacing={dx!r}",
            f"solid.body[0].min.x={clamp!r}", f"solid.body[0].min.y={-half!r}",
            f"solid.body[0].max.x={shell.L!r}", f"solid.body[0].max.y={half!r}",
            f"solid.clamp[0].min.x={clamp!r}", f"solid.clamp[0].min.y={-half!r}",
            f"solid.clamp[0].max.y={half!r}",
            f"solid.density={shell.RHO!r}", f"solid.youngs_modulus={youngs_modulus!r}",
            f"solid.poisson_ratio={poisson_ratio!r}",
            f"solid.initial_velocity.tip_speed={TIP_SPEED!r}",
            f"solid.initial_velocity.length={shell.L!r}", f"solid.tip_gauge.x={shell.L!r}",
            f"run.end_time={END_TIME!r}", "run.output_interval=0.0002",
            "run.snapshot_interval=1"]


def run(binary, settings, out, reuse):
    """(wall s, CPU s) of one run, or those recorded by its earlier run with --reuse."""
    command = [binary, "--case", CASE, "--out", out]
    for setting in settings:
        command += ["--set", setting]
    return cr.timed_run(command, str(out), reuse)


def main():
    parser = cr.script_arguments(__doc__, "validation/continuum_plate_in_vacuum")
    parser.add_argument("--bin", default=str(ROOT / "build" / "bin"))
    args = parser.parse_args()
    T_eb, T_timoshenko = shell.euler_bernoulli_period(), shell.timoshenko_period()
    E_peer, nu_peer = PEER_RUBBER
    T_eb_peer, T_timoshenko_peer = shell.beam_periods_of(E_peer, nu_peer)

    def measured(label, executable, settings, across, name, rubber=(None, None),
                 references=(T_eb, T_timoshenko)):
        """One run's table row and its period, wall and CPU time."""
        out = pathlib.Path(args.out) / name
        wall, cpu = run(pathlib.Path(args.bin) / executable,
                        plate_settings(across, *rubber) + settings, out, args.reuse)
        period, _, _ = shell.tip_period(out / "timeseries.csv", f"{label}, {across} across")
        row = [label, across, f"{1e3 * shell.T_THICK / across:g}", f"{period:.5f}"] + \
            [f"{100 * (period / T - 1):+.2f} %" for T in references] + \
            [f"{wall:.1f}", f"{cpu:.1f}"]
        return row, period, wall, cpu

    rows, points = [], []
    for label, executable, settings in SOLIDS:
        option = settings[-1].split("=")[1]
        for across in ACROSS:
            row, period, wall, cpu = measured(label, executable, settings, across,
                                              f"{option}_{across}")
            rows.append(row)
            points.append(shell.period_point(label, f"{across} across", period, T_timoshenko,
                                             wall, cpu))
    # The same solids on the peer's rubber, at the finer spacing.
    for label, executable, settings in SOLIDS:
        option = settings[-1].split("=")[1]
        rows.append(measured(f"{label}, SPHinXsys's rubber (E {E_peer / 1e6:g} MPa, "
                             f"nu {nu_peer:g})", executable, settings, PEER_RUBBER_ACROSS,
                             f"peer_rubber_{option}_{PEER_RUBBER_ACROSS}", PEER_RUBBER,
                             (T_eb_peer, T_timoshenko_peer))[0])
    preamble = (
        "Written by `scripts/continuum_plate_in_vacuum.py`. The Antoci plate alone, first "
        "bending mode, with the continuum solids (`cases/oscillating_plate.pbtxt` reshaped: "
        "its artificial viscosity and stress, a clamp as long as the plate is thick); the "
        f"period of the free end against Euler-Bernoulli in plane strain, T = {T_eb:.5f} s, "
        f"and the Timoshenko beam, T = {T_timoshenko:.5f} s, the shell's table's references. "
        "A continuum's exact limit is plane-strain elasticity, which the Timoshenko beam "
        "approximates: its shear correction (5/6) and its clamp are idealisations, and "
        "their effect may reach the order of the gap between the two references, so errors "
        "below that gap do not rank the solids. The total-Lagrangian solid runs its default "
        "hourglass control (`solid.hourglass_control`, alpha). The last rows run the "
        f"same solids on SPHinXsys's rubber (E = {E_peer / 1e6:g} MPa, nu = {nu_peer:g}), "
        f"against that rubber's own references, T = {T_eb_peer:.5f} s (Euler-Bernoulli) "
        f"and {T_timoshenko_peer:.5f} s (Timoshenko). Wall and CPU times "
        "are for one thread each on a shared two-core machine; other jobs running at the same "
        "time inflate the wall time more than the CPU time.")
    cr.write_table("continuum_plate_in_vacuum",
                   ["solid", "particles across t", "dx [mm]", "period [s]",
                    "vs Euler-Bernoulli", "vs Timoshenko", "wall time [s]", "CPU time [s]"],
                   rows, preamble)
    cr.write_points("plate_in_vacuum_continuum", points)
    print(open(ROOT / "docs" / "results" / "continuum_plate_in_vacuum.md").read())


if __name__ == "__main__":
    main()

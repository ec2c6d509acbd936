"""The static deflection of a plate clamped at both ends under a uniform load,
and how a cosph run's mid-span deflection is read against it: shared by
scripts/validate_hydrostatic_plate.py and the short test
(tests/case_runs/test_hydrostatic_plate_short.py).

Theory (plane strain, the plate a beam of unit width):
  q    = rho g H + rho_s g e            the water's weight and the plate's own
  D    = E e^3 / (12 (1 - nu^2))        bending stiffness of plane strain
  w_EB = q L^4 / (384 D)                Euler-Bernoulli, clamped-clamped
  w_T  = w_EB + q L^2 / (8 kappa G e)   Timoshenko: plus the shear deflection,
                                        G = E / (2 (1 + nu)), kappa = 5/6
The target is w_T: the 2-D solid deforms in shear as an elastic continuum
does, and the shell (the case's model) is a Timoshenko beam with the same
kappa; shear adds 8 e^2 / ((1 - nu) kappa L^2) = 3.6 % to w_EB at e / L = 1/20.
w_EB, the value Fourey et al. 2017 compare with, is shown beside it.

The static value is read from a run as the mean of the mid-span deflection
over the last two periods of the water column's slowest acoustic mode,
T = 4 H / c0 (a quarter-wave column: closed at the plate, open at the
surface). The plate's own oscillation radiates into the water within the
first period, but the column's acoustic mode, which the sudden load starts,
decays only through the water's small artificial viscosity and density
diffusion, so the deflection still swings about its static value at the end.
Averaging over whole periods of that mode takes the swing out, without any
damping added to the physics or chosen for this scene.
"""
import math
import os

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PARAMETERS = os.path.join(REPO, "validation", "reference", "hydrostatic_plate_fourey2017.csv")


def parameters(path=PARAMETERS):
    """The published scene's parameters by name (SI)."""
    values = {}
    with open(path) as f:
        rows = [line.strip().split(",") for line in f
                if line.strip() and not line.startswith("#")]
    for name, value, _unit in rows[1:]:
        values[name] = float(value)
    return values


def static_deflection(p=None):
    """(w_EB, w_T), m, both positive downward."""
    p = p or parameters()
    L, e, E, nu = p["span_L"], p["thickness_e"], p["youngs_modulus_E"], p["poisson_ratio_nu"]
    g = p["gravity_g"]
    q = p["water_density_rho"] * g * p["water_depth_H"] + p["solid_density_rho_s"] * g * e
    D = E * e ** 3 / (12.0 * (1.0 - nu ** 2))
    w_eb = q * L ** 4 / (384.0 * D)
    G, kappa = E / (2.0 * (1.0 + nu)), 5.0 / 6.0
    return w_eb, w_eb + q * L ** 2 / (8.0 * kappa * G * e)


def column_period(p=None):
    """s: 4 H / c0 with the cases' default c0 = 10 sqrt(2 g H)."""
    p = p or parameters()
    H = p["water_depth_H"]
    return 4.0 * H / (10.0 * math.sqrt(2.0 * p["gravity_g"] * H))


def settled_mean(t, values, periods=2):
    """The mean of VALUES over the run's last PERIODS column periods (the
    samples evenly spaced); nan if the run is shorter."""
    t, values = np.asarray(t), np.asarray(values)
    start = t[-1] - periods * column_period()
    if start < 0.0:
        return float("nan")
    return float(np.mean(values[t >= start]))


def settled_deflection(t, tip_dy, periods=2):
    """m, positive downward: -tip_dy averaged over the run's last PERIODS
    column periods; nan if the run is shorter."""
    return -settled_mean(t, tip_dy, periods)


def water_load(p=None):
    """N/m: the water's weight on the span, rho g H L, what the pressure on
    the plate's upper face adds up to at rest."""
    p = p or parameters()
    return p["water_density_rho"] * p["gravity_g"] * p["water_depth_H"] * p["span_L"]

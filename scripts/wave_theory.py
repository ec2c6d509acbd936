"""Linear water-wave theory for the wave flume (cases/wave_flume.pbtxt):
the dispersion relation, the group velocity, Biesel's transfer function of a
piston wave maker (Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers
and Scientists", ch. 6; validation/reference/README.md), the gauge window
before a reflection can return, and the first-harmonic height of a gauge
record. Shared by scripts/validate_wave_flume.py and the short test.
"""
import numpy as np

G = 9.81


def wavenumber(period, depth, g=G):
    """k of omega^2 = g k tanh(k d), by Newton's method from the deep-water k."""
    omega2 = (2 * np.pi / period) ** 2
    k = max(omega2 / g, np.sqrt(omega2 / (g * depth)))
    for _ in range(50):
        f = g * k * np.tanh(k * depth) - omega2
        df = g * np.tanh(k * depth) + g * k * depth / np.cosh(k * depth) ** 2
        k -= f / df
    return k


def group_velocity(period, depth, g=G):
    k = wavenumber(period, depth, g)
    kd = k * depth
    return 0.5 * (1 + 2 * kd / np.sinh(2 * kd)) * (2 * np.pi / period) / k


def biesel_height_over_stroke(period, depth, g=G):
    """H/S of a piston: 2 (cosh 2kd - 1) / (sinh 2kd + 2kd) (Dean & Dalrymple eq. 6.21)."""
    kd = wavenumber(period, depth, g) * depth
    return 2 * (np.cosh(2 * kd) - 1) / (np.sinh(2 * kd) + 2 * kd)


def gauge_window(period, depth, ramp_time, gauge_x, flume_length, g=G):
    """(t_from, t_to) of a gauge's steady waves, in whole periods.

    From: the ramp's end, the travel to the gauge at the group velocity, and
    one period more for the front of the wave train to pass. To: the first
    time a reflection from the far end could be back, at the fastest speed
    of linear waves sqrt(g d), counted from the piston's first motion."""
    t_from = ramp_time + gauge_x / group_velocity(period, depth, g) + period
    t_back = (2 * flume_length - gauge_x) / np.sqrt(g * depth)
    periods = np.floor((t_back - t_from) / period)
    return t_from, t_from + periods * period


def first_harmonic_height(t, level, period, t_from, t_to):
    """2 |a_1| of the least-squares fit of a0 + sum_{n=1,2} a_n exp(i n omega t)
    over the window: the first-order wave height (the second harmonic and the
    mean set-down fitted alongside so that they do not leak into it)."""
    w = (t >= t_from) & (t <= t_to)
    omega = 2 * np.pi / period
    tw = t[w]
    columns = [np.ones_like(tw)]
    for n in (1, 2):
        columns += [np.cos(n * omega * tw), np.sin(n * omega * tw)]
    coefficients, *_ = np.linalg.lstsq(np.array(columns).T, level[w], rcond=None)
    return 2 * np.hypot(coefficients[1], coefficients[2]), coefficients[0]

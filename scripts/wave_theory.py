"""Linear water-wave theory for the wave flume (cases/wave_flume.pbtxt):
the dispersion relation, the group velocity, Biesel's transfer function of a
piston wave maker (Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers
and Scientists", ch. 6; validation/reference/README.md), travel times over a
flume that ends in a plane beach, the gauge windows they give, the
first-harmonic height of a gauge record, and the separation of incident and
reflected waves from two gauges (Goda & Suzuki 1976). Shared by
scripts/validate_wave_flume.py and the short test.
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


def surf_similarity(slope, period, height, g=G):
    """Iribarren's number xi = s / sqrt(H / L0), L0 = g T^2 / (2 pi)."""
    return slope / np.sqrt(height / (g * period**2 / (2 * np.pi)))


def beach_reflection(slope, period, height, g=G):
    """The reflection coefficient of a plane impermeable slope, Kr = 0.1 xi^2
    (Battjes 1974, Proc. 14th Coastal Eng. Conf., 466), for xi up to about 2.5."""
    return 0.1 * surf_similarity(slope, period, height, g) ** 2


class Beach:
    """A flume of still depth d, flat from the piston (x = 0) to the toe of a
    plane beach of slope s, which rises to the shoreline at toe + d / s."""

    def __init__(self, depth, toe_x, slope):
        self.depth, self.toe_x, self.slope = depth, toe_x, slope
        self.shore_x = toe_x + depth / slope

    def time_to_shore(self, x, speed, samples=4001):
        """The time from x to the shoreline at speed(h), h the local depth:
        the flat part in closed form, the slope by x = shore - u^2, in which
        a shallow-water speed sqrt(g s) u leaves nothing singular."""
        flat = max(self.toe_x - x, 0.0) / speed(self.depth)
        u_top = np.sqrt(min(self.shore_x - x, self.shore_x - self.toe_x))
        u = np.linspace(0.0, u_top, samples)
        u[0] = 1e-9 * max(u_top, 1.0)
        integrand = [2 * ui / speed(self.slope * ui * ui) for ui in u]
        return flat + np.trapz(integrand, u)


def front_speed(height, g=G):
    """An upper bound on how fast a disturbance of height H travels in depth
    h: a bore's sqrt(g (h + H)), above the linear long-wave speed sqrt(g h)."""
    return lambda h: np.sqrt(g * (h + height))


def group_speed(period, g=G):
    """The linear group velocity at depth h, sqrt(g h) in the shallow limit."""
    return lambda h: group_velocity(period, h, g) if h > 1e-6 else np.sqrt(g * h)


def gauge_window(period, ramp_time, gauge_x, beach, height, g=G):
    """(t_from, t_to) of a gauge's incident waves, in whole periods.

    From: the ramp's end, the travel to the gauge at the group velocity, and
    one period more for the front of the wave train to pass. To: the first
    time a reflection from the shoreline could be back, its front at
    front_speed all the way, counted from the piston's first motion (the
    beach reflects mostly where the waves break and run up; its toe, a mild
    change of slope, reflects little, and that is in the gauge from the
    start)."""
    t_from = ramp_time + gauge_x / group_velocity(period, beach.depth, g) + period
    fast = front_speed(height, g)
    t_back = beach.time_to_shore(0.0, fast) + beach.time_to_shore(gauge_x, fast)
    periods = np.floor((t_back - t_from) / period)
    return t_from, t_from + periods * period


def reflection_start(period, ramp_time, gauge_x, beach, g=G):
    """When the beach's reflected waves are steady at a gauge: the ramp's end
    carried to the shoreline and back at the linear group velocity (slower
    than the breaking waves' run-up, so late enough), and one period more."""
    slow = group_speed(period, g)
    return (ramp_time + beach.time_to_shore(0.0, slow) + beach.time_to_shore(gauge_x, slow)
            + period)


def first_harmonic(t, level, period, t_from, t_to):
    """The complex first-harmonic amplitude A, level ~ Re(A exp(i omega t)),
    and the mean, of the least-squares fit of a0 + sum_{n=1,2} (a_n cos n
    omega t + b_n sin n omega t) over the window (the second harmonic and the
    mean set-down fitted alongside so that they do not leak into it)."""
    w = (t >= t_from) & (t <= t_to)
    omega = 2 * np.pi / period
    tw = t[w]
    columns = [np.ones_like(tw)]
    for n in (1, 2):
        columns += [np.cos(n * omega * tw), np.sin(n * omega * tw)]
    coefficients, *_ = np.linalg.lstsq(np.array(columns).T, level[w], rcond=None)
    return coefficients[1] - 1j * coefficients[2], coefficients[0]


def first_harmonic_height(t, level, period, t_from, t_to):
    """The first-order wave height 2 |A| over the window, and the mean."""
    amplitude, mean = first_harmonic(t, level, period, t_from, t_to)
    return 2 * abs(amplitude), mean


def incident_and_reflected(t, level_a, level_b, x_a, x_b, period, depth, t_from, t_to):
    """Incident and reflected first-order heights at gauge a, from two gauges
    (Goda & Suzuki 1976, Proc. 15th Coastal Eng. Conf., 828): the first
    harmonics A(x) = A_I exp(-i k x) + A_R exp(i k x), two equations for the
    two waves. Needs sin(k (x_b - x_a)) away from 0 (spacing not near a
    multiple of half a wavelength). Returns (H_I, H_R) at x_a."""
    k = wavenumber(period, depth)
    a = first_harmonic(t, level_a, period, t_from, t_to)[0]
    b = first_harmonic(t, level_b, period, t_from, t_to)[0]
    # Relative to x_a: a = I + R, b = I exp(-i k dx) + R exp(i k dx).
    shift = np.exp(1j * k * (x_b - x_a))
    incident = (a * shift - b) / (shift - 1 / shift)
    reflected = a - incident
    return 2 * abs(incident), 2 * abs(reflected)

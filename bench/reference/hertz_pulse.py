"""The Hertz force history of an elastic impact, for plots over a run's contact force:
F = F_max (d/d_max)^(3/2), with t(d) from the energy equation d' = v sqrt(1 - (d/d_max)^(5/2)).
The pulse is symmetric and its shape depends only on the contact time, so the peak force and
the contact time fix it."""
import math


def hertz_pulse(peak_force, contact_time, start, samples=400):
    """[(t, F)] from start to start + contact_time."""
    # t(d) = d_max/v * int_0^{d/d_max} ds / sqrt(1 - s^(5/2)), by the midpoint rule (the
    # singularity at the peak is integrable and the rule never evaluates it)
    n = samples // 2
    xs = [i / n for i in range(n + 1)]
    integral, ts = 0.0, [0.0]
    for a, b in zip(xs[:-1], xs[1:]):
        integral += (b - a) / math.sqrt(max(1 - (0.5 * (a + b)) ** 2.5, 1e-12))
        ts.append(integral)
    scale = 0.5 * contact_time / ts[-1]
    rise = [(start + t * scale, peak_force * x ** 1.5) for t, x in zip(ts, xs)]
    return rise + [(2 * start + contact_time - t, f) for t, f in reversed(rise[:-1])]

#!/usr/bin/env python3
"""Independent reference for the first impact of wave propagation (D, docs/references.md): a
steel sphere (r = 10 mm) at 0.1 m/s on the flat end of a resting aluminium rod (r = 10 mm,
l = 1 m), modelled as a rigid mass on a Hertz contact F = K d^(3/2) (K = 4/3 E* sqrt(r), E* of
both materials) and a 1D elastic rod of impedance Z = rho c A: the end moves at F(t) / Z while
no reflection has come back (2 l / c = 391 us, long after the contact), so the sphere's velocity
v and the approach d obey v' = -F(d) / m, d' = v - F(d) / Z (Goldsmith, Impact, ch. 4). It
leaves out the sphere's own vibration and the rod end's 3D field near the contact (a half-space
for Hertz, a plane wave at once for the rod).

Usage: sphere_on_rod.py [--check SCENE]  (prints JSON; --check compares with the scene's
[reference] peak_force_n and contact_time_s and exits 1 if either differs by more than 0.1 %)."""
import json
import math
import sys

E_S, NU_S, RHO_S = 2.1e11, 0.3, 7850.0      # steel sphere
E_R, NU_R, RHO_R = 7.28e10, 0.33, 2789.0    # aluminium rod
R, V0 = 0.01, 0.1


def simulate(dt=1e-9):
    e_star = 1 / ((1 - NU_S ** 2) / E_S + (1 - NU_R ** 2) / E_R)
    K = 4.0 / 3.0 * e_star * math.sqrt(R)
    m = RHO_S * 4.0 / 3.0 * math.pi * R ** 3
    Z = RHO_R * math.sqrt(E_R / RHO_R) * math.pi * R ** 2
    force = lambda d: K * d ** 1.5 if d > 0 else 0.0
    # classical RK4 on (v_sphere, d)
    t, v, d, peak = 0.0, V0, 0.0, 0.0
    f = lambda v, d: (-force(d) / m, v - force(d) / Z)
    while True:
        k1 = f(v, d)
        k2 = f(v + dt / 2 * k1[0], d + dt / 2 * k1[1])
        k3 = f(v + dt / 2 * k2[0], d + dt / 2 * k2[1])
        k4 = f(v + dt * k3[0], d + dt * k3[1])
        v_new = v + dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        d_new = d + dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        if t > 0 and d_new <= 0:  # the contact opens within this step
            t += dt * d / (d - d_new)
            break
        t, v, d = t + dt, v_new, d_new
        peak = max(peak, force(d))
    return {"peak_force_n": peak, "contact_time_s": t, "rebound_velocity_m_s": v}


def main():
    result = simulate()
    coarse = simulate(2e-9)
    result["discretization_error"] = {k: abs(result[k] - coarse[k]) for k in ("peak_force_n", "contact_time_s")}
    print(json.dumps(result, indent=2))
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        import tomllib
        with open(sys.argv[2], "rb") as f:
            stored = tomllib.load(f)["reference"]
        worst = 0.0
        for key in ("peak_force_n", "contact_time_s"):
            error = abs(stored[key] - result[key]) / result[key]
            print(f"{key}: scene reference {stored[key]:.6g}, model {result[key]:.6g}, difference {100 * error:.3f} %")
            worst = max(worst, error)
        sys.exit(0 if worst <= 1e-3 else 1)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Scene E's start (two double pendulums, E; [R2] Sect. 6 in docs/references.md): the left
double pendulum is released from rest at alpha0 = -20 degrees (rod) and the ball's angle beta0
is chosen so that the rod and the ball reach the vertical together (alpha = beta = 0), where the
right pendulum's ball hangs: the first impact is head-on. The pendulums as rigid bodies (the
rods' elastic sag under gravity moves the touch by nanometres):

  rod: uniform cylinder r = 4 mm, l = 0.4 m, hinged at its top; ball: r = 10 mm, hinged at
  its top to the rod's lower end; steel rho = 7850, g = 9.81. alpha, beta: angles of the
  rod and of the ball's hinge-to-centre line from the downward vertical.

Lagrange's equations of the two angles are integrated with classical Runge-Kutta (step
1e-5 s: the error of the touch time is below 1e-9 s, checked by halving) and beta0 is found
by bisection.

The balls' frames (models/pendulum_ball.model.toml): each ball is in spherical coordinates
about its model's y axis, and R0 turns that axis to the hinges' z, so the swing plane cuts the
ball along its equator, which the parametrization leaves regular all round. The hinge is on the
equator at longitude 0 (the seam, +x of the model) and the first impact at longitude 90 deg
(+z): R0 takes the first impact's direction to +x and the hinge's to +y; the left ball is
turned by Rz(beta0) R0, the right one by Ry(180 deg) R0 (facing -x). Prints beta0, the touch,
the bodies' positions and x-y-z angles, and the hinge node. Usage: double_pendulum_start.py [--check SCENE MODEL]
(compares with the scene's and the ball model's numbers; exit 1 if they differ).
"""
import math
import sys

import numpy as np

RHO, G = 7850.0, 9.81
L, R_ROD, R = 0.4, 0.004, 0.01
M_ROD = RHO * math.pi * R_ROD**2 * L
I_ROD = M_ROD * (3 * R_ROD**2 + L**2) / 12  # about its centre
M_BALL = RHO * 4 / 3 * math.pi * R**3
I_BALL = 0.4 * M_BALL * R**2


def accelerations(a, b, da, db):
    c, s = math.cos(a - b), math.sin(a - b)
    m11 = I_ROD + M_ROD * L**2 / 4 + M_BALL * L**2
    m12 = M_BALL * L * R * c
    m22 = M_BALL * R**2 + I_BALL
    f1 = -M_BALL * L * R * s * db**2 - (M_ROD * L / 2 + M_BALL * L) * G * math.sin(a)
    f2 = M_BALL * L * R * s * da**2 - M_BALL * G * R * math.sin(b)
    det = m11 * m22 - m12 * m12
    return (m22 * f1 - m12 * f2) / det, (m11 * f2 - m12 * f1) / det


def until_vertical(alpha0, beta0, h=1e-5):
    """Integrates from rest until the rod passes the vertical; returns (t, beta, ball speed) there."""
    y, t = [alpha0, beta0, 0.0, 0.0], 0.0

    def f(y):
        aa, ab = accelerations(*y)
        return [y[2], y[3], aa, ab]

    while True:
        k1 = f(y)
        k2 = f([y[i] + h / 2 * k1[i] for i in range(4)])
        k3 = f([y[i] + h / 2 * k2[i] for i in range(4)])
        k4 = f([y[i] + h * k3[i] for i in range(4)])
        n = [y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(4)]
        if n[0] >= 0 > y[0] or n[0] <= 0 < y[0]:
            s = y[0] / (y[0] - n[0])  # linear in the last step: enough for beta (it moves < 1e-4 rad)
            beta = y[1] + s * (n[1] - y[1])
            da, db = y[2] + s * (n[2] - y[2]), y[3] + s * (n[3] - y[3])
            return t + s * h, beta, abs(L * da + R * db)
        y, t = n, t + h


def beta0_for(alpha0):
    lo, hi = alpha0 - 0.2, alpha0 + 0.2
    f_lo = until_vertical(alpha0, lo)[1]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        f_mid = until_vertical(alpha0, mid)[1]
        if (f_mid > 0) == (f_lo > 0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
        if hi - lo < 1e-12:
            break
    return 0.5 * (lo + hi)


def rotation(axis, angle):
    c, s = math.cos(angle), math.sin(angle)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m = np.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def tait_bryan(a):
    """x-y-z angles of A = Rx(a) Ry(b) Rz(c) (isosid-run's orientation)."""
    b = math.asin(max(-1.0, min(1.0, a[0, 2])))
    return [math.atan2(-a[1, 2], a[2, 2]), b, math.atan2(-a[0, 1], a[0, 0])]


def ball_frames():
    """R0 and the hinge's direction in the ball's model frame: the first impact on the equator
    at longitude 90 deg (+z of the model), the hinge at longitude 0 (+x)."""
    impact, hinge = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    return np.vstack([impact, hinge, np.cross(impact, hinge)]), hinge


def start():
    alpha0 = math.radians(-20.0)
    beta0 = beta0_for(alpha0)
    r0, hinge = ball_frames()
    left_hinge = np.array([-R, 0.0, 0.0])
    rod_bottom = left_hinge + L * np.array([math.sin(alpha0), -math.cos(alpha0), 0.0])
    return {
        "alpha0": alpha0, "beta0": beta0,
        "left_rod": (rod_bottom, [0.0, 0.0, alpha0]),
        "left_ball": (rod_bottom + R * np.array([math.sin(beta0), -math.cos(beta0), 0.0]), tait_bryan(rotation(2, beta0) @ r0)),
        "right_rod": (np.array([R, -L, 0.0]), [0.0, 0.0, 0.0]),
        "right_ball": (np.array([R, -L - R, 0.0]), tait_bryan(rotation(1, math.pi) @ r0)),
        "hinge_node": R * hinge,
    }


def check(scene_file, model_file):
    import tomllib
    with open(scene_file, "rb") as f:
        scene = tomllib.load(f)
    with open(model_file, "rb") as f:
        model = tomllib.load(f)
    s, worst = start(), 0.0
    for body in scene["flexible_body"]:
        position, angles = s[body["name"]]
        worst = max(worst, np.abs(np.array(body.get("position", [0, 0, 0])) - position).max(),
                    np.abs(np.array(body.get("orientation", [0, 0, 0])) - angles).max())
    node = next(n for n in model["node"] if n["name"] == "hinge")
    worst = max(worst, np.abs(np.array(node["point"]) - s["hinge_node"]).max())
    print(f"largest difference from the scene's and the model's numbers: {worst:.3g}")
    return worst <= 1e-12


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--check":
        sys.exit(0 if check(sys.argv[2], sys.argv[3]) else 1)
    s = start()
    t, beta, speed = until_vertical(s["alpha0"], s["beta0"])
    print(f"rod {M_ROD:.6f} kg, ball {M_BALL:.6f} kg")
    print(f"alpha0 = {math.degrees(s['alpha0']):.4f} deg, beta0 = {math.degrees(s['beta0']):.6f} deg ({s['beta0']:.12f} rad)")
    print(f"vertical at t = {t:.9f} s, beta there {beta:.2e} rad, ball speed {speed:.6f} m/s")
    for name in ("left_rod", "left_ball", "right_rod", "right_ball"):
        position, angles = s[name]
        print(f"{name}: position {[float(f'{v:.17g}') for v in position]}, orientation {[float(f'{v:.17g}') for v in angles]}")
    print(f"hinge node (ball model frame): {[float(f'{v:.17g}') for v in s['hinge_node']]}")

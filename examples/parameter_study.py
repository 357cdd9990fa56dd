#!/usr/bin/python3
"""A small parameter study in pure Python: scene A at five impact speeds, each run with its
velocity set over the scene file, and the peak force and contact time against Hertz's power
laws (F ~ v^(6/5), T ~ v^(-1/5)) from the 0.1 m/s case of the scene.

    python3 examples/parameter_study.py
"""
import os

import isosid

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "models", "sphere_hertz.scene.toml")
HERTZ_PEAK, HERTZ_TIME, V_REF = 51.70, 83.1e-6, 0.1  # the scene's Hertz values at 0.1 m/s

print(f"{'v [m/s]':>8} {'peak [N]':>10} {'vs Hertz':>9} {'T [us]':>8} {'vs Hertz':>9}")
for v in (0.025, 0.05, 0.1, 0.2, 0.4):
    # the model sizes its contact elements from the expected contact radius ([contact_resolution]),
    # so each speed gets its own SID, built once and reused
    r = isosid.run(SCENE, output=f"out/example_study/v{v}", set={"flexible_body.0.velocity": [0.0, -v, 0.0],
                                                                 "simulation.end_time": 1.3 * HERTZ_TIME * (v / V_REF) ** -0.2},
                   progress=False)
    c = r.contacts["impact"]
    peak, time = HERTZ_PEAK * (v / V_REF) ** 1.2, HERTZ_TIME * (v / V_REF) ** -0.2
    print(f"{v:8.3f} {c.peak_force_n:10.3f} {100 * (c.peak_force_n / peak - 1):+8.2f}% {1e6 * c.duration_s:8.2f} "
          f"{100 * (c.duration_s / time - 1):+8.2f}%")

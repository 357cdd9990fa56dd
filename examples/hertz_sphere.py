#!/usr/bin/python3
"""Scene A from Python: an aluminium sphere (r = 10 mm) at 0.1 m/s on its plane of symmetry,
against Hertz's closed form for the impact of two such spheres.

    python3 examples/hertz_sphere.py          (from the repository, after scripts/build)
"""
import math
import os

import isosid

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

r = isosid.run(os.path.join(ROOT, "models", "sphere_hertz.scene.toml"), output="out/example_hertz_sphere", progress=False)
impact = r.contacts["impact"]

# Hertz (Johnson, ch. 11): two equal spheres meeting at 2 v0; the scene's sphere hits the plane
# of symmetry between them
R, E, nu, rho, v0 = 0.01, 7.28e10, 0.33, 2789.0, 0.1   # models/sphere_axisym.model.toml
E_star = E / (2 * (1 - nu * nu))       # two equal bodies
R_star = R / 2
m_star = rho * 4 / 3 * math.pi * R ** 3 / 2
v = 2 * v0
approach = (15 * m_star * v * v / (16 * E_star * math.sqrt(R_star))) ** 0.4
peak = 4 / 3 * E_star * math.sqrt(R_star) * approach ** 1.5
duration = 2.9432 * approach / v

print(f"peak force    {impact.peak_force_n:8.3f} N   Hertz {peak:8.3f} N   {100 * (impact.peak_force_n / peak - 1):+.2f} %")
print(f"contact time  {1e6 * impact.duration_s:8.3f} us  Hertz {1e6 * duration:8.3f} us  {100 * (impact.duration_s / duration - 1):+.2f} %")
print(f"largest force sample {impact.force[:, 1].max():.3f} N of {len(r.time)} samples; status {r.status}")

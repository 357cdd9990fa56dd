#!/usr/bin/python3
"""The sphere on the free-free beam (case F, docs/references.md [R3]): a steel sphere drops at
1.1 m/s on the middle of a free-free steel beam. How much of its energy goes into each bending
mode of the beam is what an impact absorber is designed from: this example prints the impact's
figures and each labelled bending mode's share E_k/E_0 and restitution r_k, and plots the shares.

    python3 examples/sphere_on_beam_modal_energy.py     (from the repository, after scripts/build)

The first run builds both bodies' SIDs in models/ (about a minute and a half on two cores).
"""
import os

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import isosid  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = "out/example_sphere_on_beam"

r = isosid.run(os.path.join(ROOT, "models", "sphere_on_beam_free.scene.toml"), output=OUT, progress=False)
impact = r.contacts["impact"]
modes = impact.impact_modes  # summary.json's modal view of the impact, per integrated mode of the beam

print(f"peak force {impact.peak_force_n:.1f} N, contact time {1e6 * impact.duration_s:.2f} us, "
      f"the sphere approaches at {modes['approach_speed_m_s']:.4f} m/s and leaves at {-modes['separation_velocity_m_s']:.4f} m/s")
print(f"energy into the beam's modes: {100 * modes['energy_ratio_total']:.2f} % of the sphere's {1e3 * modes['kinetic_energy_j']:.3f} mJ")
bending = [m for m in modes["modes"] if m["label"]]  # 1F, 2F, ...: bending in the impact direction
print(" mode   f [Hz]    E_k/E_0    r_k")
for m in bending:
    print(f" {m['label']:>4} {m['frequency_hz']:9.1f} {m['energy_ratio']:9.4f} {m['restitution']:+8.4f}")
# a centric impact (the middle of the beam) excites the odd bending modes only
odd = sum(m["energy_ratio"] for m in bending if int(m["label"][:-1]) % 2 == 1)
even = sum(m["energy_ratio"] for m in bending if int(m["label"][:-1]) % 2 == 0)
print(f"odd bending modes {100 * odd:.2f} %, even {100 * even:.4f} % of E_0")

fig, (ax_force, ax_modes) = plt.subplots(1, 2, figsize=(10, 3.8))
ax_force.plot(1e6 * r.time, np.linalg.norm(impact.force, axis=1))
ax_force.set_xlim(1e6 * impact.start_s - 5, 1e6 * impact.end_s + 5)
ax_force.set_xlabel("time [us]")
ax_force.set_ylabel("contact force [N]")
ax_modes.bar([m["label"] for m in bending], [m["energy_ratio"] for m in bending])
ax_modes.set_xlabel("bending mode")
ax_modes.set_ylabel("E_k / E_0")
fig.tight_layout()
fig.savefig(os.path.join(OUT, "modal_energy.png"), dpi=120)
print(f"plot: {os.path.join(OUT, 'modal_energy.png')}")

#!/usr/bin/python3
"""Results as a pandas table: runs scene A (or reads a results folder given as argument),
turns every sampled series into one DataFrame indexed by time, and writes it as CSV.

    python3 examples/results_to_pandas.py [RESULTS_FOLDER]
"""
import os
import sys

import isosid

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

if len(sys.argv) > 1:
    r = isosid.read_results(sys.argv[1])
else:
    r = isosid.run(os.path.join(ROOT, "models", "sphere_hertz.scene.toml"), output="out/example_pandas", progress=False)

df = r.to_dataframe()
force = df["contacts/impact/force_y"]
print(f"{len(df)} samples x {len(df.columns)} columns; units of the force: {df.attrs['units']['contacts/impact/force_y']}")
print(f"peak force {force.max():.3f} N at t = {1e6 * force.idxmax():.2f} us")
print(df[["contacts/impact/force_y", "energy/kinetic", "energy/elastic", "energy/total"]].describe().T[["min", "max"]])
csv = os.path.join(r.folder, "series.csv")
df.to_csv(csv)
print(f"-> {csv}")

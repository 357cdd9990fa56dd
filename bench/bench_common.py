"""Shared helpers of the benchmark scripts: machine facts, running isosid programs, and
replacing one named section of bench/RESULTS.md."""
import datetime
import json
import os
import platform
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("ISOSID_BUILD", os.path.join(ROOT, "build"))  # ctest points this at its build
RESULTS = os.path.join(ROOT, "bench", "RESULTS.md")


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    return {
        "date": datetime.date.today().isoformat(),
        "machine": f"{os.cpu_count()} cores, {cpu}, {platform.system()} {platform.release()}",
        "commit": commit or "uncommitted",
    }


def run_json(args, env=None):
    """Runs a program that prints JSON on stdout; returns the parsed object."""
    out = subprocess.run(args, capture_output=True, text=True, env=env)
    if out.returncode != 0:
        raise SystemExit(f"{' '.join(args)} failed ({out.returncode}): {out.stderr.strip()}")
    return json.loads(out.stdout)


def run_scene(scene, out):
    """Runs isosid-run on a scene file into the folder `out`, with the same build's isosid-prep
    for the models it prepares; returns the run's summary."""
    return run_json([os.path.join(BUILD, "runtime", "isosid-run"), "-q", "--json", scene, "-o", out],
                    env=dict(os.environ, ISOSID_PREP=os.path.join(BUILD, "preprocess", "isosid-prep")))


def update_section(name, body):
    """Replaces the text between <!-- name --> markers in RESULTS.md (appends if missing)."""
    text = open(RESULTS).read() if os.path.exists(RESULTS) else "# Benchmark results\n"
    begin, end = f"<!-- {name} -->", f"<!-- /{name} -->"
    block = f"{begin}\n{body.rstrip()}\n{end}"
    if begin in text:
        text = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: block, text, flags=re.S)
    else:
        text = text.rstrip() + "\n\n" + block + "\n"
    with open(RESULTS, "w") as f:
        f.write(text)

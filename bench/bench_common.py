"""Shared helpers of the benchmark scripts: machine facts, running isosid programs, and
replacing one named section of bench/RESULTS.md."""
import datetime
import json
import math
import os
import platform
import re
import selectors
import subprocess
import tempfile
import time

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


def run_scene_measured(scene, out):
    """As run_scene, for a scene whose SIDs are prepared: returns its summary and the run's
    peak RSS in MiB."""
    with tempfile.TemporaryFile("w+") as out_file, tempfile.TemporaryFile("w+") as err_file:
        proc = subprocess.Popen([os.path.join(BUILD, "runtime", "isosid-run"), "-q", "--json", scene, "-o", out],
                                stdout=out_file, stderr=err_file, text=True)
        _, status, rusage = os.wait4(proc.pid, 0)
        out_file.seek(0), err_file.seek(0)
        if os.waitstatus_to_exitcode(status) != 0:
            raise SystemExit(f"isosid-run {scene} failed ({os.waitstatus_to_exitcode(status)}): {err_file.read().strip()}")
        return json.loads(out_file.read()), rusage.ru_maxrss / 1024.0


def run_prep(build, model, sid, timeout=math.inf):
    """Runs the build's isosid-prep on a model file into `sid`, stopped after `timeout` seconds.
    Returns a dict: 'lines' (stderr's lines, each with its time since the start), 'status' (as
    os.wait4 gives it), 'timed_out', 'wall', 'cpu' (user + system), 'rss' (peak, MiB), 'stages'
    (the seconds of each stage isosid-prep reports), 'dofs', 'nq' (low, high)."""
    # stdout into a file and stderr read to its end before waiting: the child's own rusage
    # (os.wait4) needs the wait, and a full pipe would block the child
    with tempfile.TemporaryFile("w+") as out_file:
        start = time.perf_counter()
        proc = subprocess.Popen([os.path.join(build, "preprocess", "isosid-prep"), model, "-o", sid],
                                stdout=out_file, stderr=subprocess.PIPE, text=True, bufsize=1)
        lines, timed_out = [], False
        selector = selectors.DefaultSelector()
        selector.register(proc.stderr, selectors.EVENT_READ)
        while True:
            left = timeout - (time.perf_counter() - start)
            if left <= 0:
                timed_out = True
                proc.kill()
                break
            if not selector.select(timeout=min(left, 5.0)):
                continue
            line = proc.stderr.readline()
            if not line:
                break
            lines.append((time.perf_counter() - start, line.rstrip("\n")))
        _, status, rusage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        out_file.seek(0)
        out = out_file.read()
    err = "\n".join(text for _, text in lines)
    dofs = re.search(r"(\d+) free DOFs", out + err)
    nq = re.search(r"nq = (\d+) \((\d+) low \+ (\d+) high\)", out)
    return {
        "lines": lines, "status": status, "timed_out": timed_out, "wall": wall,
        "cpu": rusage.ru_utime + rusage.ru_stime, "rss": rusage.ru_maxrss / 1024.0,
        "stages": {m.group(1): float(m.group(2)) for m in re.finditer(r"isosid-prep: (\w+) done in ([0-9.]+) s", err)},
        "dofs": int(dofs.group(1)) if dofs else 0, "nq": (int(nq.group(2)), int(nq.group(3))) if nq else (0, 0),
    }


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

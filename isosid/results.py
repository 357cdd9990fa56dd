"""A run's results: summary.json's figures and results.h5's sampled series, as Python objects,
numpy arrays and a pandas table."""
import json
import os


class Entry:
    """One body, contact or monitor: its summary.json figures as attributes (peak_force_n,
    duration_s, ...) and its series in results.h5 as numpy arrays (force, q, ...), read when
    first asked for. `units` names each series' unit."""

    def __init__(self, result, group, figures):
        self._result, self._group, self._figures = result, group, figures

    def __getattr__(self, name):
        figures = self.__dict__.get("_figures", {})
        if name in figures:
            return figures[name]
        series = self._result.series(f"{self._group}/{name}")
        if series is not None:
            return series
        raise AttributeError(f"{self._group} has no figure or series '{name}' "
                             f"(figures: {', '.join(sorted(figures))}; series: {', '.join(self.series_names)})")

    @property
    def series_names(self):
        return self._result.series_names(self._group)

    @property
    def units(self):
        return {name: self._result.unit(f"{self._group}/{name}") for name in self.series_names}

    @property
    def figures(self):
        """The summary.json entry, as a dict."""
        return dict(self._figures)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._figures) | set(self.series_names))

    def __repr__(self):
        return f"<isosid {self._group}>"


class Result:
    """The results folder of one run: `summary` (summary.json as a dict), `status`, `time`
    (s), `bodies`, `contacts` and `monitors` by name, `energy`, and `to_dataframe()`."""

    def __init__(self, folder, summary=None):
        self.folder = os.fspath(folder)
        if summary is None or not summary:
            with open(os.path.join(self.folder, "summary.json")) as f:
                summary = json.load(f)
        self.summary = summary
        self.status = summary.get("status")
        self.warnings = summary.get("warnings", [])
        self.bodies = {b["name"]: Entry(self, f"bodies/{b['name']}", b) for b in summary.get("bodies", [])}
        self.contacts = {c["name"]: Entry(self, f"contacts/{c['name']}", c) for c in summary.get("contacts", [])}
        self.monitors = {m["name"]: Entry(self, f"monitors/{m['name']}", m) for m in summary.get("monitors", [])}
        self.energy = Entry(self, "energy", summary.get("energy", {}))
        self._series = {}

    @property
    def results_file(self):
        return os.path.join(self.folder, "results.h5")

    def _read(self, path):
        import h5py
        if not os.path.isfile(self.results_file):
            return None
        with h5py.File(self.results_file, "r") as f:
            if path not in f or not isinstance(f[path], h5py.Dataset):
                return None
            data = f[path]
            unit = data.attrs.get("units", b"")
            return data[()], unit.decode() if isinstance(unit, bytes) else str(unit)

    def series(self, path):
        """The dataset at `path` in results.h5 (e.g. "contacts/impact/force") as an array, or None."""
        if path not in self._series:
            self._series[path] = self._read(path)
        found = self._series[path]
        return None if found is None else found[0]

    def unit(self, path):
        self.series(path)
        found = self._series.get(path)
        return None if found is None else found[1]

    def series_names(self, group):
        import h5py
        if not os.path.isfile(self.results_file):
            return []
        with h5py.File(self.results_file, "r") as f:
            if group not in f:
                return []
            return sorted(k for k, v in f[group].items() if isinstance(v, h5py.Dataset))

    @property
    def time(self):
        return self.series("time")

    def to_dataframe(self):
        """Every series sampled at results.h5's times, as a pandas DataFrame indexed by time (s).
        Columns are "<group>/<name>/<series>" with a component suffix for vectors (_x, _y, _z,
        or the column index); their units are in `df.attrs["units"]`."""
        import h5py
        import numpy as np
        import pandas as pd
        columns, units = {}, {}
        with h5py.File(self.results_file, "r") as f:
            t = np.asarray(f["time"][()])

            def visit(name, obj):
                if not isinstance(obj, h5py.Dataset) or name == "time" or name.startswith("provenance"):
                    return
                data = np.asarray(obj[()])
                if data.ndim == 0 or data.shape[0] != len(t) or not np.issubdtype(data.dtype, np.number):
                    return
                unit = obj.attrs.get("units", b"")
                unit = unit.decode() if isinstance(unit, bytes) else str(unit)
                if data.ndim == 1:
                    columns[name], units[name] = data, unit
                    return
                flat = data.reshape(len(t), -1)
                suffixes = ["x", "y", "z"] if flat.shape[1] == 3 else [str(j) for j in range(flat.shape[1])]
                for j, suffix in enumerate(suffixes):
                    columns[f"{name}_{suffix}"], units[f"{name}_{suffix}"] = flat[:, j], unit

            f.visititems(visit)
        frame = pd.DataFrame(columns, index=pd.Index(t, name="time_s"))
        frame.attrs["units"] = units
        return frame

    def __repr__(self):
        return f"<isosid Result {self.folder}: {self.status}, contacts {list(self.contacts)}>"


def read_results(folder):
    """The Result of a results folder written earlier (isosid-run or isosid.run)."""
    return Result(folder)

"""A study's folder (isosid-sweep): its table as rows and a pandas DataFrame, and each case's
results as a Result."""
import os

from .results import Result


class Study:
    """`folder` of isosid-sweep: `columns` (the table's column names, in order), `rows` (one
    dict per case), `to_dataframe()`, and `case(i)`, the Result of case i."""

    def __init__(self, folder):
        import h5py
        self.folder = os.fspath(folder)
        with h5py.File(os.path.join(self.folder, "study.h5"), "r") as f:
            self.columns = [c.decode() if isinstance(c, bytes) else str(c) for c in f["column_order"][()]]
            data = {}
            for name in self.columns:
                values = f["columns"][name][()]
                data[name] = [v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, "item") else v for v in values]
        self._data = data
        n = len(next(iter(data.values()))) if data else 0
        self.rows = [{name: data[name][i] for name in self.columns} for i in range(n)]

    def to_dataframe(self):
        import pandas as pd
        return pd.DataFrame({name: self._data[name] for name in self.columns}).set_index("case")

    def case(self, index):
        """The Result of case `index` (its results folder under cases/)."""
        return Result(os.path.join(self.folder, "cases", f"{int(index):06d}"))

    def __repr__(self):
        return f"<isosid Study {self.folder}: {len(self.rows)} cases>"


def read_study(folder):
    """The Study of an isosid-sweep folder."""
    return Study(folder)

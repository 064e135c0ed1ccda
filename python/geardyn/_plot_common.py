"""What the plotting modules share: the non-interactive matplotlib backend, atomic PNG writing
and the readers of result tables."""

import csv
import os
import pathlib
import tempfile

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402


def _save_atomically(figure, path):
    path = pathlib.Path(path)
    handle, temporary = tempfile.mkstemp(prefix="." + path.name + ".tmp-", dir=path.parent)
    os.close(handle)
    try:
        figure.savefig(temporary, format="png", dpi=130)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # mkstemp makes 0600; results are ordinary files
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    plt.close(figure)
    return path


def _read_columns(path):
    """A CSV table as {column: [floats or strings]}."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    columns = {}
    for name in rows[0].keys() if rows else []:
        values = [row[name] for row in rows]
        try:
            columns[name] = [float(v) for v in values]
        except ValueError:
            columns[name] = values
    return columns


def _long_table(path, key_columns):
    """A long CSV table grouped by its key columns: {(k1, ...): {column: [values]}}."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    groups = {}
    for row in rows:
        key = tuple(row[k] for k in key_columns)
        group = groups.setdefault(key, {})
        for name, value in row.items():
            if name in key_columns:
                continue
            try:
                value = float(value)
            except ValueError:
                pass
            group.setdefault(name, []).append(value)
    return groups

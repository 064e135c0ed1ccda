"""Readers of geardyn result tables, shared by the PNG plots (matplotlib) and the HTML report
(plotly.js): plain Python, no plotting library needed."""

import csv
import json
import math
import pathlib
import re

# Column names end with their unit, and a gear pair's line-of-action quantities name their plane
# ("p2p_transverse_m", "frequency_hz"); short_name drops both for the plotting code ("p2p").
_UNIT_SUFFIX = re.compile(r"(_transverse|_normal)?_(hz|m|n|n_m|rad|s|n_per_m|m_per_s|m_per_s2|rad_per_s|rad_per_s2|nondim)$",
                          re.IGNORECASE)


def short_name(name):
    """``name`` without its unit and plane: "p2p_transverse_m" -> "p2p", "t_s" -> "t"."""
    return _UNIT_SUFFIX.sub("", name)


def read_rows(path):
    """A CSV table as a list of rows {short column name: text} (see short_name)."""
    with open(path, newline="") as handle:
        return [{short_name(k): v for k, v in row.items()} for row in csv.DictReader(handle)]


def _read_columns(path, short=False):
    """A CSV table as {column: [floats or strings]} (short=True: short column names)."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    columns = {}
    for name in rows[0].keys() if rows else []:
        values = [row[name] for row in rows]
        key = short_name(name) if short else name
        try:
            columns[key] = [float(v) for v in values]
        except ValueError:
            columns[key] = values
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


def read_summary(folder):
    return json.loads((pathlib.Path(folder) / "summary.json").read_text())


def stability_runs(xs, ys, stable):
    """A branch split where its stability changes: a list of (xs, ys, is_stable) runs, each run
    ending on the first point of the next so that the drawn branch has no gap. The segment from
    point i to i + 1 belongs to the run of point i."""
    runs = []
    start = 0
    for i in range(1, len(xs) + 1):
        if i == len(xs) or bool(stable[i]) != bool(stable[start]):
            end = min(i + 1, len(xs))
            runs.append((list(xs[start:end]), list(ys[start:end]), bool(stable[start])))
            start = i
    return runs


def log_floor(values, dynamic_range=1e-6):
    """The lower limit of a log axis showing `values`: `dynamic_range` times the largest
    positive value, or the smallest positive value if that is higher (so numerical zeros, 1e-20
    of the peak, do not stretch the axis over 14 decades)."""
    positive = [v for v in values if v > 0 and math.isfinite(v)]
    if not positive:
        return None
    return max(min(positive), max(positive) * dynamic_range)


def mesh_frequency_per_rpm(summary):
    """Mesh frequency per pinion rpm [Hz/rpm] = z1 / 60 when the run knows the pinion's teeth,
    else None (a dimensionless model, or one given by inertias and radii only)."""
    config = summary.get("config", {})
    for path in (("pinion", "teeth"), ("model", "pinion_teeth"), ("geometry", "pinion", "teeth")):
        node = config
        for key in path:
            node = node.get(key) if isinstance(node, dict) else None
        if isinstance(node, (int, float)) and node > 0:
            return node / 60.0
    return None


def keyphasor_points(t, xs, ys, frequency, t0):
    """(x, y) where the shaft angle (t - t0) * frequency passes a whole revolution, linearly
    interpolated between samples."""
    points = []
    for i in range(1, len(t)):
        a, b = (t[i - 1] - t0) * frequency, (t[i] - t0) * frequency
        if math.floor(b) > math.floor(a) and b > 0:
            s = (math.floor(b) - a) / (b - a)
            points.append((xs[i - 1] + s * (xs[i] - xs[i - 1]), ys[i - 1] + s * (ys[i] - ys[i - 1])))
    return points

"""Figures of parameter studies: histograms of Monte Carlo outputs and the sweep overview."""

import csv
import json
import pathlib

from ._plot_common import _save_atomically, finish, plt


def parameter_units(command):
    """{section.key: unit} of a command's configuration keys, from its reference (the schema
    the command validates with); {} when the compiled module is not importable."""
    try:
        from ._geardyn import config_reference

        text = config_reference(command)
    except Exception:  # noqa: BLE001  (plots still work without units)
        return {}
    units, section = {}, ""
    for row in text.splitlines():
        if row.startswith("## ["):
            section = row[4:].rstrip("]") + "."
        elif row.startswith("## "):
            section = ""
        elif row.startswith("| `"):
            cells = [c.strip() for c in row.strip("|").split("|")]
            if len(cells) >= 3 and cells[2]:
                units[section + cells[0].strip("`")] = cells[2]
    return units


def output_unit(pointer):
    """The unit of a sweep output from the name of what its JSON pointer reads, or None when the
    name does not tell (the axis then says where the value comes from)."""
    name = pointer.rstrip("/").rsplit("/", 1)[-1].lower()
    path = pointer.lower()
    if name.endswith(("_fraction", "factor", "ratio", "_r", "status")) or name in ("r", "r_ke"):
        return "-"
    for ending, unit in (("_hz", "Hz"), ("frequency", "Hz"), ("_rpm", "rpm"), ("_s", "s"), ("_n", "N"),
                         ("_m", "m"), ("_deg", "°")):
        if name.endswith(ending):
            return unit
    if "force" in path:
        return "N"
    return None


def _label(name, unit, source=None):
    if unit:
        return f"{name} [{unit}]"
    return f"{name} [as in results{source}]" if source else name


def plot_histograms(values, names, title="Monte Carlo results", path=None, bins=30, axes=None):
    """Histograms of several sampled outputs side by side (a Monte Carlo study), with mean and
    +-1 std. `values` is a list of sequences (NaN skipped); `names` label the x axes (put the
    unit in them). Draws on `axes` (one per output) if given, writes a PNG to `path` only if
    given; returns the Figure."""
    if axes is None:
        figure, axes = plt.subplots(1, len(names), figsize=(3.6 * len(names), 3.8), squeeze=False,
                                    layout="constrained")
    else:
        figure = axes[0].figure
        axes = [list(axes)]
    for ax, name, column in zip(axes[0], names, values):
        data = [x for x in column if x == x]
        if not data:
            ax.set_title(f"{name}: no data", fontsize=8)
            continue
        mean = sum(data) / len(data)
        std = (sum((x - mean) ** 2 for x in data) / max(1, len(data) - 1)) ** 0.5
        ax.hist(data, bins=bins, color="tab:blue", alpha=0.8)
        for x, ls in ((mean, "-"), (mean - std, "--"), (mean + std, "--")):
            ax.axvline(x, color="black", ls=ls, lw=0.9)
        ax.set_xlabel(name, fontsize=8)
        ax.set_title(f"mean {mean:.4g}, std {std:.3g}, n {len(data)}", fontsize=8)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("cases")
    figure.suptitle(title, fontsize=9)
    if path:
        _save_atomically(figure, path)
    return figure


def plot_sweep(result_dir, save=False):
    """{"sweep.png": Figure}: for a random design, histograms of every output; for a grid or
    zip, every output against the first parameter, one line per value of the second. Axes carry
    units: parameters from the swept command's schema, outputs from their names. Written into
    the folder when `save`."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    study = summary["config"]["study"]
    title = study.get("title") or f"sweep of {study['command']}"
    with open(folder / "sweep.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    outputs = list(study["outputs"].keys())
    parameters = list(study["parameters"].keys())

    def number(text):
        try:
            return float(text)
        except ValueError:
            return float("nan")

    units = parameter_units(study["command"])
    output_labels = [_label(o, output_unit(study["outputs"][o]), study["outputs"][o]) for o in outputs]
    ok = [r for r in rows if r["status"] == "ok"]
    if study["design"] == "random":
        figure = plot_histograms([[number(r[o]) for r in ok] for o in outputs], output_labels,
                                 f"{title}\n{len(ok)} of {len(rows)} cases")
        return finish({"sweep.png": figure}, folder, save)
    figure, axes = plt.subplots(len(outputs), 1, figsize=(9, 2.8 * len(outputs) + 0.4), squeeze=False,
                                sharex=True, layout="constrained")
    x_key = parameters[0]
    group_key = parameters[1] if len(parameters) > 1 else None
    groups = {}
    for r in ok:
        groups.setdefault(r[group_key] if group_key else "", []).append(r)
    for ax, output in zip(axes[:, 0], outputs):
        for group, members in groups.items():
            members = sorted(members, key=lambda r: number(r[x_key]))
            xs = [number(r[x_key]) for r in members]
            if all(x != x for x in xs):  # text values: categorical axis
                xs = list(range(len(members)))
            ax.plot(xs, [number(r[output]) for r in members], "o-", ms=3, lw=1.0,
                    label=f"{number(group):g} {units.get(group_key, '').strip('-')}".rstrip() if group_key else None)
        failed = [r for r in rows if r["status"] != "ok"]
        for r in failed:
            ax.axvline(number(r[x_key]), color="red", lw=0.6, alpha=0.5)
        ax.set_ylabel(output_labels[outputs.index(output)], fontsize=8)
        ax.grid(alpha=0.3)
    if group_key:
        axes[0, 0].legend(fontsize=7, title=group_key, title_fontsize=7, loc="upper left",
                          bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel(_label(x_key, units.get(x_key)))
    axes[0, 0].set_title(f"{title}\n{len(ok)} of {len(rows)} cases ok (red: failed cases)", fontsize=9)
    return finish({"sweep.png": figure}, folder, save)

"""Figures of parameter studies: histograms of Monte Carlo outputs and the sweep overview."""

import csv
import json
import pathlib

from ._plot_common import _save_atomically, plt


def plot_histograms(values, names, title="Monte Carlo results", path=None, bins=30):
    """Histograms of several sampled outputs side by side (a Monte Carlo study), with mean and
    +-1 std. `values` is a list of sequences (NaN skipped). Returns the figure or writes `path`."""
    figure, axes = plt.subplots(1, len(names), figsize=(3.6 * len(names), 3.6), squeeze=False)
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
    figure.tight_layout()
    return _save_atomically(figure, path) if path else figure


def plot_sweep(result_dir):
    """sweep.png: for a random design, histograms of every output; for a grid or zip, every
    output against the first parameter, one line per value of the second."""
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

    ok = [r for r in rows if r["status"] == "ok"]
    if study["design"] == "random":
        return [plot_histograms([[number(r[o]) for r in ok] for o in outputs], outputs,
                                f"{title}\n{len(ok)} of {len(rows)} cases", folder / "sweep.png")]
    figure, axes = plt.subplots(len(outputs), 1, figsize=(8, 2.8 * len(outputs)), squeeze=False)
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
                    label=f"{group_key} = {number(group):g}" if group_key else None)
        failed = [r for r in rows if r["status"] != "ok"]
        for r in failed:
            ax.axvline(number(r[x_key]), color="red", lw=0.6, alpha=0.5)
        ax.set_ylabel(output, fontsize=8)
        ax.grid(alpha=0.3)
        if group_key:
            ax.legend(fontsize=7)
    axes[-1, 0].set_xlabel(x_key)
    axes[0, 0].set_title(f"{title}\n{len(ok)} of {len(rows)} cases ok (red: failed cases)", fontsize=9)
    figure.tight_layout()
    return [_save_atomically(figure, folder / "sweep.png")]

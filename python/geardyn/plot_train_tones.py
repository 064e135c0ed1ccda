"""The torus forced response's lines (`geardyn train`, forced on the torus): the strongest
pure orders and combination tones n1 g1 + n2 g2 + ... of every mesh force against input speed,
from forced_tones.csv."""

import csv
import pathlib

from ._plot_common import plt

_SHOWN = 5  # per mesh: the strongest pure orders and the strongest combination tones


def _combination(tone):
    """A tone of two or more generators ("2g1-g2"), not a pure order ("3g1")."""
    return tone.count("g") > 1


def train_tones_figure(result_dir, summary, title):
    """One panel per mesh (at most four): the amplitude [N] of its strongest pure orders (solid)
    and combination tones (sidebands, dashed) against input speed; the generators g_j (per
    input turn) in the title."""
    folder = pathlib.Path(result_dir)
    rows = list(csv.DictReader(open(folder / "forced_tones.csv", newline="")))
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))[:4]
    figure, axes = plt.subplots(len(meshes), 1, figsize=(10.5, 2.6 * len(meshes) + 0.8),
                                sharex=True, squeeze=False, layout="constrained")
    for ax, mesh in zip(axes[:, 0], meshes):
        tracks = {}
        for r in rows:
            if r["mesh"] == mesh:
                tracks.setdefault(r["tone"], []).append((float(r["speed_rpm"]), float(r["amplitude_n"])))
        by_peak = sorted(tracks, key=lambda t: -max(a for _, a in tracks[t]))
        pure = [t for t in by_peak if not _combination(t)][:_SHOWN]
        combinations = [t for t in by_peak if _combination(t)][:_SHOWN]
        for tone in pure + combinations:
            points = sorted(tracks[tone])
            ax.semilogy([s for s, _ in points], [a for _, a in points],
                        "--" if _combination(tone) else "-", lw=0.9, label=tone)
        ax.set_ylabel(f"{mesh}\nline amplitude [N]", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel("input speed [rpm]")
    generators = summary["results"]["forced"]["torus"]["generators"]
    names = ", ".join(f"g{j + 1} = {g['order']:.4g} × input" for j, g in enumerate(generators))
    figure.suptitle(f"{title}: mesh-force lines n·g on the torus ({names}); lines below 1e-3 "
                    "of a speed's largest are not listed", fontsize=9)
    return figure

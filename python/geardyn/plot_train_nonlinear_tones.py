"""The nonlinear steady state on the torus (`geardyn train`, nonlinear with method torus): every
mesh force's orders 1-3 (nonlinear_mesh_orders.csv) and its strongest combination tones
n1 g1 + n2 g2 + ... (nonlinear_tones.csv) against input speed along the continuation, the
folds (nonlinear_torus.csv's branch index) marked; like forced_tones.png for the linear train."""

import csv
import pathlib

from ._plot_common import plt

_ORDERS = 3  # pure orders drawn per mesh
_COMBINATIONS = 3  # strongest combination tones drawn per mesh


def _rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def _points(rows):
    """The continuation point of every row: a new point where the speed changes (the tables
    list each point's rows together, in continuation order)."""
    index, previous, out = -1, None, []
    for r in rows:
        if r["speed_rpm"] != previous:
            index, previous = index + 1, r["speed_rpm"]
        out.append(index)
    return out


def _tracks(rows, points, mesh, key):
    """{name: [(point, speed, amplitude)]} of one mesh, in continuation order."""
    tracks = {}
    for r, p in zip(rows, points):
        if r["mesh"] == mesh:
            tracks.setdefault(key(r), []).append((p, float(r["speed_rpm"]), float(r["amplitude_n"])))
    return tracks


def _draw(ax, track, branch, style, label, colour=None):
    """One track, broken where the branch index changes (a confirmed fold): a fold is where the
    continuation turns back in speed, so the pieces overlap in speed and are drawn apart."""
    pieces, current = [], []
    for p, s, a in track:
        b = branch[p] if p < len(branch) else 0
        if current and current[-1][0] != b:
            pieces.append(current)
            current = [current[-1]]  # joined at the fold
        current.append((b, s, a))
    pieces.append(current)
    line = None
    for k, piece in enumerate(pieces):
        line, = ax.semilogy([s for _, s, _ in piece], [a for _, _, a in piece], style, lw=0.9,
                            color=colour if line is None else line.get_color(),
                            label=label if k == 0 else None)
    return line


def train_nonlinear_tones_figure(result_dir, summary, title):
    """One panel per mesh (at most four): its force's orders 1-3 (solid) and strongest
    combination tones (dashed) [N] against input speed along the continuation; the folds
    (where the branch index of nonlinear_torus.csv increases) as black crosses."""
    folder = pathlib.Path(result_dir)
    orders = _rows(folder / "nonlinear_mesh_orders.csv")
    tones = _rows(folder / "nonlinear_tones.csv")
    points_table = _rows(folder / "nonlinear_torus.csv")
    branch = [int(r["branch"]) for r in points_table]
    folds = [i for i in range(1, len(branch)) if branch[i] != branch[i - 1]]
    order_points, tone_points = _points(orders), _points(tones)
    meshes = list(dict.fromkeys(r["mesh"] for r in orders))[:4]
    figure, axes = plt.subplots(len(meshes), 1, figsize=(10.5, 2.6 * len(meshes) + 0.8),
                                sharex=True, squeeze=False, layout="constrained")
    for ax, mesh in zip(axes[:, 0], meshes):
        pure = _tracks(orders, order_points, mesh, lambda r: int(r["order"]))
        for order in sorted(pure)[:_ORDERS]:
            line = _draw(ax, pure[order], branch, "-", f"order {order}")
            for i in folds:  # the fold points on this order's curve
                at = [(s, a) for p, s, a in pure[order] if p == i]
                if at:
                    ax.plot(*at[0], "x", color="black", ms=6, zorder=5)
        mixed = {t: v for t, v in _tracks(tones, tone_points, mesh, lambda r: r["tone"]).items()
                 if t.count("g") > 1}
        for tone in sorted(mixed, key=lambda t: -max(a for _, _, a in mixed[t]))[:_COMBINATIONS]:
            _draw(ax, mixed[tone], branch, "--", tone)
        ax.set_ylabel(f"{mesh}\nline amplitude [N]", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel("input speed [rpm]")
    folds_text = f"{len(folds)} fold(s) ×" if folds else "no folds"
    figure.suptitle(f"{title}: nonlinear steady state on the torus, mesh-force orders (solid) and "
                    f"combination tones (dashed) along the continuation; {folds_text}", fontsize=9)
    return figure

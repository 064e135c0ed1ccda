"""The flexible housing's response (`geardyn train` with [housing], forced): the acceleration
level at every response point per mesh order against input speed, from housing_response.csv
(issue #37)."""

import csv
import pathlib

from ._plot_common import plt

_STYLES = {1: "-", 2: "--", 3: ":"}


def train_housing_figure(result_dir, summary, title):
    """One panel per response point: its acceleration level [dB re 1e-6 m/s²] at orders 1-3 of
    every mesh against input speed (solid, dashed, dotted), the operating speed marked. A peak
    sits where an order crosses a mode of the train on its housing (modes.csv, mode_type)."""
    folder = pathlib.Path(result_dir)
    rows = list(csv.DictReader(open(folder / "housing_response.csv", newline="")))
    points = list(dict.fromkeys(r["point"] for r in rows))
    figure, axes = plt.subplots(len(points), 1, figsize=(10.5, 2.8 * len(points) + 0.8),
                                sharex=True, squeeze=False, layout="constrained")
    operating = abs(summary["results"]["kinematics"]["input_speed_rpm"])
    for ax, point in zip(axes[:, 0], points):
        tracks = {}
        for r in rows:
            if r["point"] == point:
                tracks.setdefault((r["mesh"], int(r["order"])), []).append(
                    (float(r["speed_rpm"]), float(r["level_db"])))
        for (mesh, order), values in tracks.items():
            values.sort()
            ax.plot([s for s, _ in values], [v for _, v in values], _STYLES.get(order, "-."),
                    lw=1.0, label=f"{mesh} order {order}")
        if operating:
            ax.axvline(operating, color="tab:red", lw=0.8, ls=":", label="operating speed")
        ax.set_ylabel(f"{point}\nacceleration [dB re 1e-6 m/s²]", fontsize=8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel("input speed [rpm]")
    axes[0, 0].set_title(f"{title}: housing response points, acceleration per mesh order "
                         "(frequency domain)", fontsize=9)
    return figure

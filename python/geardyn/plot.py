"""Plots of geardyn result folders, written as PNG next to the data they show.

The command line calls ``python3 -m geardyn.plot COMMAND RESULT_DIR`` after it has written a
command's CSV tables and prints the names of the files it wrote, one per line. From Python,
call the ``plot_<command>`` functions directly. Every PNG is written atomically (temporary name
in the same folder, then rename).
"""

import csv
import json
import math
import os
import pathlib
import sys
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
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    plt.close(figure)
    return path


def _read_profiles(path):
    """tooth_profiles.csv -> {member: (xs, ys)} of the right half of one tooth [m]."""
    profiles = {}
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            xs, ys = profiles.setdefault(row["member"], ([], []))
            xs.append(float(row["x_m"]))
            ys.append(float(row["y_m"]))
    return profiles


def _whole_tooth(xs, ys):
    """One tooth from the middle of the space on its left to the middle of the space on its
    right: the mirrored half (up the left flank) then the half itself reversed (down the right)."""
    left_x = [-x for x in xs]
    return left_x + list(reversed(xs))[1:], ys + list(reversed(ys))[1:]


def _gear_outline(xs, ys, teeth, centre, rotation):
    """The whole gear: the tooth rotated `teeth` times, turned by `rotation`, moved to `centre`."""
    tooth_x, tooth_y = _whole_tooth(xs, ys)
    out_x, out_y = [], []
    for k in range(teeth):
        angle = rotation + 2.0 * math.pi * k / teeth
        c, s = math.cos(angle), math.sin(angle)
        # angle measured clockwise from +y, like the profile's own angles
        out_x += [centre[0] + c * x + s * y for x, y in zip(tooth_x, tooth_y)]
        out_y += [centre[1] - s * x + c * y for x, y in zip(tooth_x, tooth_y)]
    return out_x + out_x[:1], out_y + out_y[:1]


def plot_geometry(result_dir):
    """mesh.png: the pair in mesh (whole gears and a close-up of the contact zone with the line
    of action, path of contact and pitch point). Needs summary.json results and
    tooth_profiles.csv. Returns the list of files written."""
    folder = pathlib.Path(result_dir)
    results = json.loads((folder / "summary.json").read_text())["results"]
    profiles = _read_profiles(folder / "tooth_profiles.csv")
    pinion, gear = results["pinion"], results["gear"]
    z1, z2 = pinion["teeth"], gear["teeth"]
    a = results["centre_distance"]
    alpha = results["operating_pressure_angle"]
    mm = 1e3

    # Pinion at the origin, a tooth centred on +y; gear above, a space centred on -y.
    p_x, p_y = _gear_outline(*profiles["pinion"], z1, (0.0, 0.0), 0.0)
    g_x, g_y = _gear_outline(*profiles["gear"], z2, (0.0, a), math.pi + math.pi / z2)
    # Line of action through the pitch point P, tangent to both base circles.
    r_w1 = pinion["operating_pitch_radius"]
    d = (math.cos(alpha), math.sin(alpha))
    t1 = (-r_w1 * math.sin(alpha) * d[0], r_w1 - r_w1 * math.sin(alpha) * d[1])
    length = results["line_of_action_length"]
    t2 = (t1[0] + length * d[0], t1[1] + length * d[1])
    s0, s1 = results["path_of_contact_start"], results["path_of_contact_end"]
    along = lambda s: (t1[0] + s * d[0], t1[1] + s * d[1])  # noqa: E731

    figure, axes = plt.subplots(1, 2, figsize=(12, 6))
    for ax, zoom in zip(axes, (False, True)):
        ax.plot([v * mm for v in p_x], [v * mm for v in p_y], color="tab:blue", lw=0.8,
                label=f"pinion, {z1} teeth")
        ax.plot([v * mm for v in g_x], [v * mm for v in g_y], color="tab:red", lw=0.8,
                label=f"gear, {z2} teeth")
        for centre, member, colour in (((0.0, 0.0), pinion, "tab:blue"), ((0.0, a), gear, "tab:red")):
            for key, style in (("base_radius", ":"), ("operating_pitch_radius", "-.")):
                ax.add_patch(plt.Circle((centre[0] * mm, centre[1] * mm), member[key] * mm, fill=False,
                                        ls=style, lw=0.6, color=colour))
        ax.plot([t1[0] * mm, t2[0] * mm], [t1[1] * mm, t2[1] * mm], color="0.4", lw=0.7,
                label="line of action T1T2")
        start, end = along(min(s0, s1)), along(max(s0, s1))
        ax.plot([start[0] * mm, end[0] * mm], [start[1] * mm, end[1] * mm], color="black", lw=2.5,
                label=f"path of contact, eps_alpha = {results['contact_ratio_transverse']:.4f}")
        ax.plot([0.0], [r_w1 * mm], "ko", ms=3)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        if zoom:
            half = 1.6 * max(length, 4 * pinion["tip_radius"] - 4 * pinion["root_radius"]) * mm / 2
            ax.set_xlim(-half, half)
            ax.set_ylim(r_w1 * mm - half, r_w1 * mm + half)
            ax.annotate("P", (0.0, r_w1 * mm), xytext=(4, -10), textcoords="offset points")
            ax.set_title("contact zone")
        else:
            ax.set_title(f"{z1}/{z2} teeth, a = {a * mm:.4f} mm, alpha_wt = "
                         f"{results['operating_pressure_angle_deg']:.3f} deg")
            ax.legend(loc="upper right", fontsize=7)
    figure.tight_layout()
    return [_save_atomically(figure, folder / "mesh.png")]


PLOTTERS = {"geometry": plot_geometry}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2 or argv[0] not in PLOTTERS:
        print(f"usage: python3 -m geardyn.plot {{{','.join(PLOTTERS)}}} RESULT_DIR", file=sys.stderr)
        return 2
    for path in PLOTTERS[argv[0]](argv[1]):
        print(pathlib.Path(path).name)
    return 0


if __name__ == "__main__":
    sys.exit(main())

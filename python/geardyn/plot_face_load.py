"""The load distribution across the face (issue 36): the contact pattern — line load over face
position and mesh phase as a colour map, as a gear engineer reads a marking-compound pattern —
and the cycle-mean line load with K_Hβ, for `ltca` (face_load.csv) and each mesh of `train`
(face_load_<mesh>.csv)."""

from ._plot_common import _read_columns, plt


def _grid(table):
    """Phases, face positions [mm] and the line load [N/mm] as a phase × z grid."""
    phases = list(dict.fromkeys(table["mesh_fraction"]))
    zs = list(dict.fromkeys(table["z_m"]))
    where = {(p, z): w for p, z, w in zip(table["mesh_fraction"], table["z_m"], table["line_load_n_per_m"])}
    grid = [[1e-3 * where[(p, z)] for p in phases] for z in zs]
    return phases, [1e3 * z for z in zs], grid


def draw_contact_pattern(ax, table, title, k_hbeta=None):
    """One contact pattern on `ax` (a colour bar beside it)."""
    phases, zs, grid = _grid(table)
    mesh = ax.pcolormesh(phases, zs, grid, shading="nearest", cmap="inferno")
    ax.figure.colorbar(mesh, ax=ax, label="line load [N/mm]")
    ax.set_xlabel("mesh phase (roll angle) [periods]")
    ax.set_ylabel("face position z [mm]")
    label = f"{title}" + (f": K_Hβ = {k_hbeta:.3f}" if k_hbeta is not None else "")
    ax.set_title(label, fontsize=9)


def face_load_figure(folder, title, k_hbeta, prefix="face_load"):
    """face_load.png: the contact pattern and the cycle-mean line load across the face; None
    when the face has a single slice."""
    path = folder / f"{prefix}.csv"
    if not path.exists():
        return None
    table = _read_columns(path)
    if len(set(table["z_m"])) < 2:
        return None
    mean = _read_columns(folder / f"{prefix}_mean.csv")
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [2.2, 1]},
                                         layout="constrained")
    draw_contact_pattern(left, table, "contact pattern", k_hbeta)
    right.plot([1e-3 * w for w in mean["mean_line_load_n_per_m"]], [1e3 * z for z in mean["z_m"]], "o-", ms=2)
    average = sum(mean["mean_line_load_n_per_m"]) / len(mean["mean_line_load_n_per_m"])
    right.axvline(1e-3 * average, color="0.5", ls="--", lw=0.8, label="mean F/b")
    right.set_xlabel("cycle-mean line load [N/mm]")
    right.set_ylabel("face position z [mm]")
    right.grid(alpha=0.3)
    right.legend(fontsize=8)
    figure.suptitle(title, fontsize=9)
    return figure

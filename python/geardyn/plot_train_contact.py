"""Figures of the gearbox's own deflection at its meshes (`geardyn train`, issue 36): the mesh
misalignment of `static` (mesh_misalignment.png), of `contact` the contact pattern of every
mesh, K_Hβ per mesh and the loaded STE harmonics (mesh_contact.png), and of `forced` the whine
orders against speed (whine_orders.png)."""

from ._plot_common import _read_columns, plt
from .plot_face_load import draw_contact_pattern


def mesh_misalignment_figure(folder, title):
    """Per mesh: the mismatch in and out of the plane of action and the centre-distance change
    [µm], bars."""
    table = _read_columns(folder / "mesh_misalignment.csv")
    meshes = list(table["mesh"])
    figure, ax = plt.subplots(figsize=(max(5.0, 1.6 * len(meshes) + 3), 4), layout="constrained")
    series = [("mismatch_m", "f_ma in the plane of action"),
              ("mismatch_out_of_plane_m", "out of the plane of action"),
              ("centre_distance_change_m", "centre-distance change")]
    width = 0.8 / len(series)
    for k, (column, label) in enumerate(series):
        xs = [i + (k - 1) * width for i in range(len(meshes))]
        ax.bar(xs, [1e6 * v for v in table[column]], width, label=label)
    ax.axhline(0.0, color="0.4", lw=0.8)
    ax.set_xticks(range(len(meshes)), meshes)
    ax.set_ylabel("misalignment across the face; centre-distance change [µm]")
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)
    ax.set_title(f"{title}: mesh misalignment from the static deflection", fontsize=9)
    return figure


def _load_cases(left, right, table, meshes):
    """K_Hβ and the loaded STE's first mesh harmonics against the load factor, per mesh."""
    orders = sorted(int(c[len("ste_h"):-2]) for c in table if c.startswith("ste_h"))[:3]
    for k, mesh in enumerate(meshes):
        keep = [i for i, m in enumerate(table["mesh"]) if m == mesh]
        load = [table["load_factor"][i] for i in keep]
        left.plot(load, [table["face_load_factor"][i] for i in keep], "o-", color=f"C{k}", label=mesh)
        for n, style in zip(orders, ("-", "--", ":")):
            right.plot(load, [1e6 * table[f"ste_h{n}_m"][i] for i in keep], style, marker="o", ms=3,
                       color=f"C{k}", label=f"{mesh} {n}× mesh")
    left.set_xlabel("load / operating load [-]")
    left.set_ylabel("face load factor K_Hβ [-]")
    left.set_title("K_Hβ per mesh and load case", fontsize=9)
    right.set_xlabel("load / operating load [-]")
    right.set_ylabel("loaded STE harmonic [µm]")
    right.set_title("loaded STE harmonics against load", fontsize=9)
    for ax in (left, right):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)


def mesh_contact_figure(folder, summary, title):
    """One column per mesh: its contact pattern; below, K_Hβ per mesh and the loaded STE
    harmonics; with load cases (contact_load_cases.csv), K_Hβ and the STE harmonics against
    load."""
    contact = summary["results"]["contact"]
    meshes = list(contact["meshes"])
    columns = max(2, len(meshes))
    cases = folder / "contact_load_cases.csv"
    rows = 3 if cases.exists() else 2
    figure, axes = plt.subplots(rows, columns, figsize=(5.2 * columns, 4 * rows), layout="constrained",
                                squeeze=False)
    if cases.exists():
        _load_cases(axes[2][0], axes[2][1], _read_columns(cases), meshes)
        for j in range(2, columns):
            axes[2][j].axis("off")
    for j, mesh in enumerate(meshes):
        table = _read_columns(folder / f"face_load_{mesh}.csv")
        draw_contact_pattern(axes[0][j], table, f"mesh {mesh}", contact["meshes"][mesh]["face_load_factor"])
    for j in range(len(meshes), columns):
        axes[0][j].axis("off")
    left, right = axes[1][0], axes[1][1]
    left.bar(meshes, [contact["meshes"][m]["face_load_factor"] for m in meshes], color="tab:orange")
    left.axhline(1.0, color="0.4", lw=0.8)
    left.set_ylabel("face load factor K_Hβ [-]")
    left.grid(alpha=0.3, axis="y")
    left.set_title("K_Hβ = peak / mean line load", fontsize=9)
    for mesh in meshes:
        amplitudes = contact["meshes"][mesh]["ste_harmonics_m"]
        orders = range(1, len(amplitudes) + 1)
        right.semilogy(orders, [max(1e-6 * 1e-6, 1e6 * a) for a in amplitudes], "o-", label=mesh)
    right.set_xlabel("mesh order")
    right.set_ylabel("loaded STE amplitude [µm]")
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=8)
    right.set_title("loaded STE harmonics at the static load", fontsize=9)
    for j in range(2, columns):
        axes[1][j].axis("off")
    figure.suptitle(f"{title}: loaded tooth contact under the gearbox's own deflection "
                    f"({contact['iterations']} coupling iterations)", fontsize=9)
    return figure


def whine_orders_figure(folder, summary, title):
    """Whine order levels against speed: the dynamic mesh force of every mesh at each of its
    orders (forced_mesh_orders.csv), one panel per mesh, with the meshes that take their loaded
    contact as excitation (excitation = "ltca") named in the title; below, when the forced
    response wrote forced_bearing_orders.csv, the force every bearing transmits at each mesh's
    first order (the path of the whine into the housing)."""
    table = _read_columns(folder / "forced_mesh_orders.csv")
    meshes = list(dict.fromkeys(table.get("mesh") or []))
    if not meshes:
        return None  # a train without meshes (a rotor with an unbalance) has no whine orders
    bearing_file = folder / "forced_bearing_orders.csv"
    bearings = _read_columns(bearing_file) if bearing_file.exists() else None
    rows = 2 if bearings and bearings["mesh"] else 1
    figure, axes = plt.subplots(rows, len(meshes), figsize=(5.5 * len(meshes), 4.2 * rows),
                                layout="constrained", squeeze=False)
    for ax, mesh in zip(axes[0], meshes):
        keep_mesh = [i for i, m in enumerate(table["mesh"]) if m == mesh]
        for order in sorted({int(table["order"][i]) for i in keep_mesh}):
            keep = [i for i in keep_mesh if int(table["order"][i]) == order]
            ax.semilogy([table["speed_rpm"][i] for i in keep],
                        [max(table["amplitude_n"][i], 1e-6) for i in keep], lw=1.2, label=f"{order}× mesh")
        ax.set_xlabel("input speed [rpm]")
        ax.set_ylabel("dynamic mesh force [N]")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
        ax.set_title(f"mesh {mesh}", fontsize=9)
    if rows == 2:
        for ax, mesh in zip(axes[1], meshes):
            keep_mesh = [i for i, m in enumerate(bearings["mesh"])
                         if m == mesh and int(bearings["order"][i]) == 1]
            largest = max((bearings["amplitude_n"][i] for i in keep_mesh), default=0.0)
            names = list(dict.fromkeys(bearings["bearing"][i] for i in keep_mesh))
            colours = plt.get_cmap("tab20")
            for j, bearing in enumerate(names):
                keep = [i for i in keep_mesh if bearings["bearing"][i] == bearing]
                values = [bearings["amplitude_n"][i] for i in keep]
                if max(values) <= 1e-6 * largest:
                    continue  # a bearing this order does not load (an axial spring of a spur stage)
                ax.semilogy([bearings["speed_rpm"][i] for i in keep], [max(v, 1e-9 * largest) for v in values],
                            lw=1.2, color=colours(j % 20), label=bearing)
            ax.set_xlabel("input speed [rpm]")
            ax.set_ylabel("bearing force at 1× mesh [N]")
            ax.grid(alpha=0.3, which="both")
            ax.legend(fontsize=7, ncol=2)
            ax.set_title(f"bearing forces at the first order of mesh {mesh}", fontsize=9)
    ltca = summary["results"].get("excitation_ltca", {}).get("meshes", {})
    source = f"loaded contact of {', '.join(ltca)}" if ltca else "the meshes' input excitation"
    figure.suptitle(f"{title}: whine orders against speed ({source})", fontsize=9)
    return figure

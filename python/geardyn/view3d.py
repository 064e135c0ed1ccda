"""The interactive 3-D view of a gear train's result: its shafts, gears, planets, carriers,
bearings, couplings and disks as shaded solids (three.js, embedded), a flexible housing's outer
surface (semi-transparent, at rest: its modal motion is not drawn yet), a mode list where a
click animates the mode, and the Campbell diagram linked to it.

The geometry comes from the train's ``summary.json`` (``results.geometry``, written by
``geardyn train``, with the body each part moves with) and ``bodies.csv`` (every body's rest
position); the modes from ``modes.csv`` (frequency, damping, type, strain-energy fractions) and
``mode_shapes.csv`` (complex amplitudes per DOF); the Campbell diagram from ``campbell.csv``.
The viewer itself is JavaScript beside this file (``view3d.js``: the view and its controls;
``view3d_scene.js``: renderer, camera, moving the bodies; ``view3d_parts.js``: the solids;
``view3d_panel.js``: mode list, deflection shapes and Campbell diagram; ``view3d.css``); the
libraries are embedded compressed (``_embed.py``), so the page needs no network.

- ``view_section(folder, summary)``: the HTML fragment the report puts in its page
  (None when the result has no geometry block or no modes)
- ``view_page(folder)``: a standalone HTML page of the view (what ``Result._repr_html_`` shows
  in Jupyter, in an iframe)
"""

import csv
import html
import json
import math
import pathlib

from . import _embed, _housing_surface

_HERE = pathlib.Path(__file__).resolve().parent
# Mode shapes of this many modes at most go into the page: a 270-DOF train has 270 modes, the
# ones a reader animates are the low ones (the Campbell diagram's 12, the forced range).
MAX_MODES = 60
_DOFS = ("x", "y", "z", "theta", "theta_y", "theta_z")  # per body, in this order in the page


def _rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def _number(text, default=0.0):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return default
    return value if math.isfinite(value) else default


def _round(value, digits=4):
    return round(value, digits) if value else 0


def _kinetic_shares(real, imag, bodies):
    """The shares of a mode's kinetic energy [-] in axial, lateral (y, z), torsional (θ) and
    tilting (θ_y, θ_z) motion: Σ m |u|² and Σ J |θ|² over the bodies, with the flexible shafts'
    beam mass lumped half to each node and a diametral inertia of J/2 (a thin disk)."""
    sums = {"axial": 0.0, "lateral": 0.0, "torsional": 0.0, "tilting": 0.0}
    for b, body in enumerate(bodies):
        m, J = body["m"], body["J"]
        a = [real[6 * b + k] ** 2 + imag[6 * b + k] ** 2 for k in range(6)]
        sums["axial"] += m * a[0]
        sums["lateral"] += m * (a[1] + a[2])
        sums["torsional"] += J * a[3]
        sums["tilting"] += 0.5 * J * (a[4] + a[5])
    total = sum(sums.values()) or 1.0
    return {k: v / total for k, v in sums.items()}


def _mode_type(row, shares):
    """A mode's type: "housing" for a flexible housing's own mode, the planetary stage type when
    the train has one (Lin & Parker 1999: rotational, translational, planet), else the motion
    holding over 60 % of its kinetic energy (torsional, lateral, axial, tilting) or "coupled"
    with the largest share."""
    stage = (row.get("stage_type") or "").strip()
    if abs(_number(row.get("frequency_hz"))) < 1e-6:
        return "rigid body" + (f" ({stage})" if stage else "")
    # A flexible housing's own mode (modes.csv: most of its kinetic energy in the housing),
    # whose motion the train's bodies barely share.
    if (row.get("mode_type") or "").strip() == "housing":
        return "housing"
    if stage:
        return stage.replace("/", ", ")
    kind, share = max(shares.items(), key=lambda kv: kv[1])
    return kind if share > 0.6 else "coupled"


def _energy(row):
    """The largest strain-energy fractions of a mode [-], largest first (at most 3; none for a
    rigid-body mode, whose strain energy is round-off)."""
    if abs(_number(row.get("frequency_hz"))) < 1e-6:
        return []
    parts = [(k[len("strain_"):], _number(v)) for k, v in row.items() if k.startswith("strain_")]
    parts = [(k, v) for k, v in parts if v > 0.005]
    parts.sort(key=lambda kv: -kv[1])
    return [[k, _round(v, 3)] for k, v in parts[:3]]


def _shapes(folder, index):
    """{mode number: (real[6 n], imag[6 n])} over the bodies of `index` (body name -> i)."""
    shapes = {}
    with open(folder / "mode_shapes.csv", newline="") as handle:
        reader = csv.reader(handle)
        next(reader)
        for mode, dof, real, imag in reader:
            mode = int(mode)
            if mode > MAX_MODES:
                continue
            body, _, name = dof.rpartition(".")
            if body not in index or name not in _DOFS:
                continue
            re_, im_ = shapes.setdefault(mode, ([0.0] * (6 * len(index)), [0.0] * (6 * len(index))))
            k = 6 * index[body] + _DOFS.index(name)
            re_[k], im_[k] = _number(real), _number(imag)
    return shapes


def _largest(real, imag, bodies):
    """The largest displacement of a shape: a translation, or a rotation times the part's
    radius (at least 1 mm) [m]."""
    largest = 1e-300
    for k in range(len(real)):
        scale = 1.0 if k % 6 < 3 else max(bodies[k // 6]["r"], 1e-3)
        largest = max(largest, scale * math.hypot(real[k], imag[k]))
    return largest


def _normalised(real, imag, bodies):
    """The shape scaled so its largest displacement (_largest) is 1, rounded to 4 digits for
    the page."""
    largest = _largest(real, imag, bodies)
    return [_round(v / largest) for v in real], [_round(v / largest) for v in imag]


def _body_radii(geometry, bodies, index):
    """The radius a body's rotation is seen at [m]: its largest gear or planet tip radius, else
    its shaft's section radius, else 0.05 (for the mode type and the shape's scaling)."""
    for body in bodies:
        body["r"] = 0.0
    for part in geometry.get("gears", []) + geometry.get("planets", []):
        if part["body"] in index:
            body = bodies[index[part["body"]]]
            body["r"] = max(body["r"], part["tip_radius_m"] if not part["internal"] else part["root_radius_m"])
    for shaft in geometry.get("shafts", []):
        radius = max([s["outer_radius_m"] for s in shaft["sections"]] + [0.0])
        for name in shaft["bodies"]:
            if name in index and bodies[index[name]]["r"] == 0.0:
                bodies[index[name]]["r"] = radius or 0.05


def _lump_beams(geometry, summary, bodies, index):
    """Adds half of each flexible shaft element's mass ρ A L [kg] and polar inertia
    ρ J_p L [kg m²] to each of its nodes (bodies.csv holds the lumped parts only)."""
    described = summary.get("config", {}).get("gearbox_description", {}).get("shafts", {})
    for shaft in geometry.get("shafts", []):
        if not shaft.get("flexible"):
            continue
        density = described.get(shaft["shaft"], {}).get("density", 7850.0)
        nodes = [n for n in shaft["bodies"] if n in index]
        for a, b in zip(nodes, nodes[1:]):
            xa, xb = bodies[index[a]]["c"][0], bodies[index[b]]["c"][0]
            mid = 0.5 * (xa + xb)
            for s in shaft["sections"]:
                if s["start_x_m"] - 1e-9 <= mid <= s["start_x_m"] + s["length_m"] + 1e-9:
                    ro, ri = s["outer_radius_m"], s["inner_radius_m"]
                    mass = density * math.pi * (ro ** 2 - ri ** 2) * abs(xb - xa)
                    for n in (a, b):
                        bodies[index[n]]["m"] += 0.5 * mass
                        bodies[index[n]]["J"] += 0.25 * mass * (ro ** 2 + ri ** 2)
                    break


def _campbell(folder, count):
    path = folder / "campbell.csv"
    if not path.exists():
        return None
    rows = _rows(path)
    speeds = [_number(r["speed_rpm"]) for r in rows]
    curves = []
    for k in range(1, count + 1):
        column = f"mode_{k}_hz"
        if rows and column in rows[0]:
            curves.append([_round(_number(r[column]), 3) for r in rows])
    lines = []
    if (folder / "order_lines.csv").exists():
        for r in _rows(folder / "order_lines.csv"):
            lines.append({"name": next(iter(r.values())), "order": _number(r.get("order"))})
    return {"speed_rpm": [_round(s, 3) for s in speeds], "modes_hz": curves, "orders": lines}


def _ods(folder, index, bodies):
    """The operating deflection shapes of forced_ods.csv (forced response, either method):
    [{speed_rpm, mesh, order, frequency_hz, largest_m, re, im}], each normalised like a mode,
    with its largest displacement (rotations at the part's radius) [m]."""
    path = folder / "forced_ods.csv"
    if not path.exists():
        return []
    shapes = {}
    with open(path, newline="") as handle:
        reader = csv.reader(handle)
        next(reader)
        for speed, mesh, order, frequency, dof, _unit, real, imag in reader:
            body, _, name = dof.rpartition(".")
            if body not in index or name not in _DOFS:
                continue
            key = (float(speed), mesh, int(order))
            entry = shapes.setdefault(key, [float(frequency), [0.0] * (6 * len(index)), [0.0] * (6 * len(index))])
            k = 6 * index[body] + _DOFS.index(name)
            entry[1][k], entry[2][k] = _number(real), _number(imag)
    out = []
    for (speed, mesh, order), (frequency, real, imag) in sorted(shapes.items()):
        largest = _largest(real, imag, bodies)
        re_, im_ = _normalised(real, imag, bodies)
        out.append({"speed_rpm": _round(speed, 3), "mesh": mesh, "order": order,
                    "frequency_hz": frequency, "largest_m": largest, "re": re_, "im": im_})
    return out


def view_data(folder, summary):
    """The page's data of the result folder `folder`, or None when it has nothing to show."""
    folder = pathlib.Path(folder)
    geometry = summary.get("results", {}).get("geometry")
    if not geometry or not (folder / "bodies.csv").exists():
        return None
    bodies = [{"name": r["body"], "c": [_round(_number(r["axial_x_m"]), 6), _round(_number(r["centre_y_m"]), 6),
                                        _round(_number(r["centre_z_m"]), 6)],
               "m": _number(r["mass_kg"]), "J": _number(r["polar_inertia_kg_m2"])}
              for r in _rows(folder / "bodies.csv")]
    index = {b["name"]: i for i, b in enumerate(bodies)}
    _body_radii(geometry, bodies, index)
    _lump_beams(geometry, summary, bodies, index)
    modes = []
    if (folder / "modes.csv").exists() and (folder / "mode_shapes.csv").exists():
        shapes = _shapes(folder, index)
        for row in _rows(folder / "modes.csv"):
            number = int(_number(row["mode"]))
            if number not in shapes:
                continue
            real, imag = _normalised(*shapes[number], bodies)
            shares = _kinetic_shares(*shapes[number], bodies)
            modes.append({"mode": number, "frequency_hz": _number(row["frequency_hz"]),
                          "damping_ratio": _number(row.get("damping_ratio")),
                          "type": _mode_type(row, shares), "energy": _energy(row),
                          "kinetic": {k: _round(v, 3) for k, v in shares.items() if v >= 0.005},
                          "re": real, "im": imag})
    if not modes:
        return None
    name = summary.get("config", {}).get("gearbox_description", {}).get("gearbox", {}).get("name")
    speed = summary.get("results", {}).get("modal", {}).get("speed_rpm")
    return {"title": name or summary.get("config", {}).get("title") or "gear train",
            "speed_rpm": speed, "bodies": [{"name": b["name"], "c": b["c"], "r": _round(b["r"], 6)} for b in bodies],
            "geometry": geometry, "modes": modes, "campbell": _campbell(folder, len(modes)),
            "ods": _ods(folder, index, bodies), "housing_surface": _housing(summary)}


def _housing(summary):
    """The housing's outer surface (_housing_surface.outer_surface) in metres, or None."""
    deck = summary.get("results", {}).get("housing", {}).get("deck")
    if not deck:
        return None
    units = summary.get("config", {}).get("gearbox_description", {}).get("housing", {}).get("units")
    return _housing_surface.outer_surface(deck, 1e-3 if units == "mm_t_s" else 1.0)


def _script_json(value):
    return json.dumps(value, allow_nan=False, separators=(",", ":")).replace("</", "<\\/")


_STYLE = (_HERE / "view3d.css")


def view_section(folder, summary, element_id="gd-view3d-0"):
    """The view as an HTML fragment for a page that already holds the libraries
    (``_embed.library_scripts``) and the loader: a container, its data and its mount call.
    None when the result has nothing to draw."""
    data = view_data(folder, summary)
    if data is None:
        return None
    return (f"<div class=\"gd-view3d\" id=\"{element_id}\"></div>"
            f"<script type=\"application/json\" id=\"{element_id}-data\">{_script_json(data)}</script>")


def page_parts():
    """What a page with 3-D views needs once: the style, the compressed libraries, the loader
    and the viewer (script elements)."""
    viewer = "".join(f"<script>{(_HERE / name).read_text(encoding='utf-8')}</script>"
                     for name in ("view3d_parts.js", "view3d_scene.js", "view3d_panel.js", "view3d.js"))
    return (f"<style>{_STYLE.read_text(encoding='utf-8')}</style>" + _embed.library_scripts(["three"])
            + f"<script>{_embed.loader_js()}</script>{viewer}")


def view_page(folder, summary=None):
    """A standalone HTML page of the 3-D view of the result folder `folder` (None when it has
    nothing to draw)."""
    folder = pathlib.Path(folder)
    summary = summary or json.loads((folder / "summary.json").read_text())
    section = view_section(folder, summary)
    if section is None:
        return None
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{html.escape('geardyn 3-D view')}</title>{page_parts()}</head>"
            f"<body style=\"margin:0\">{section}</body></html>\n")

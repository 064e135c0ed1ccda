"""A small REXS gearbox written by the tests themselves (issue 34), so that the REXS importer's
command-line paths run in every clone — not only beside ../shared/rexs, which a user's clone
lacks.

`write_rexs_gearbox(folder)` exports the two-stage reducer of examples/gearboxes/ with
`geardyn export` (REXS 2.0.0 JSON), then gives its load spectrum the load cases of
LOAD_CASES — each sets the motor's speed and the input torque, the two quantities a REXS load
case carries — and writes it as .rexsj and zipped as .rexsz.
"""

import copy
import json
import zipfile

from cli_support import EXAMPLES, run

GEARBOX = EXAMPLES / "gearboxes" / "two_stage_reducer.toml"
#: id -> (input speed [rpm], input torque [N m]); case 1 is the gearbox file's operating point.
LOAD_CASES = {1: (1500.0, 200.0), 2: (3000.0, 400.0), 7: (750.0, 100.0)}


def _set(attributes, name, value):
    for attribute in attributes:
        if attribute["id"] == name:
            attribute["floating_point"] = value
            return
    raise KeyError(name)


def write_rexs_gearbox(folder):
    """Writes folder/reducer.rexsj and folder/reducer.rexsz; returns their paths."""
    exported = folder / "exported.rexsj"
    result = run("export", GEARBOX, "-o", exported, "--quiet")
    assert result.returncode == 0, result.stderr
    document = json.loads(exported.read_text())
    spectrum = document["model"]["load_spectrum"]
    template = spectrum["load_cases"][0]
    cases = []
    for case_id, (speed, torque) in LOAD_CASES.items():
        case = copy.deepcopy(template)
        case["id"] = case_id
        for component in case["components"]:
            if component["type"] == "shaft":
                _set(component["attributes"], "rotational_speed", speed)
            else:
                _set(component["attributes"], "torque_around_u_axis", torque)
        cases.append(case)
    spectrum["load_cases"] = cases
    rexsj = folder / "reducer.rexsj"
    rexsj.write_text(json.dumps(document, indent=1))
    rexsz = folder / "reducer.rexsz"
    with zipfile.ZipFile(rexsz, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.write(rexsj, "reducer.rexsj")
    return rexsj, rexsz


#: The rolling bearings of examples/gearboxes/two_stage_reducer_rolling_bearings.toml as REXS
#: rows and rolling elements (issue 35): name -> (bearing_type, bearing attributes, row
#: attributes, rolling-element attributes), in the units a REXS file writes (mm, deg, mum, kN).
BALL_6208 = (
    "radial_grooved_ball_bearing",
    [("operating_radial_bearing_clearance", "mum", 15.0), ("radial_dynamic_load_rating", "kN", 32.5)],
    [("number_of_rolling_elements", "none", 9), ("pressure_angle", "deg", 0.0),
     ("raceway_radius_of_inner_ring", "mm", 6.604), ("raceway_radius_of_outer_ring", "mm", 6.731),
     ("reference_diameter_rolling_bearing", "mm", 60.0)],
    [("diameter_of_rolling_element", "mm", 12.7)],
)


def tapered_30208(angle_deg):
    """30208-like: 17 rollers 9.5 mm x 14 mm, cup angle 15 deg; a negative angle: the row takes
    the shaft's load towards -u (the gearbox file's reversed = true)."""
    return (
        "radial_tapered_roller_bearing",
        [("radial_dynamic_load_rating", "kN", 63.0), ("operating_radial_bearing_clearance", "mum", 0.0)],
        [("number_of_rolling_elements", "none", 17), ("pressure_angle", "deg", angle_deg),
         ("reference_diameter_rolling_bearing", "mm", 62.0)],
        [("diameter_of_rolling_element", "mm", 9.5), ("length_of_rolling_element", "mm", 14.0)],
    )


ROLLING_BEARINGS = {
    "input_a": BALL_6208, "input_b": BALL_6208,
    "intermediate_a": tapered_30208(15.0), "intermediate_b": tapered_30208(-15.0),
    "output_a": tapered_30208(15.0), "output_b": tapered_30208(-15.0),
}


def _attribute(name, unit, value):
    key = "integer" if isinstance(value, int) else "floating_point"
    return {"id": name, "unit": unit, key: value}


def write_rexs_rolling_bearings(folder, bearings=None, catalogue_only=(), no_stiffness=()):
    """The two-stage reducer exported, its bearings in `bearings` (default ROLLING_BEARINGS)
    turned into rolling_bearing_with_detailed_geometry with one rolling_bearing_row (an
    ordered_assembly part, as Bearinx writes it) and one rolling_element (a part of the row);
    those in `catalogue_only` into catalogue bearings with a designation and a row without
    geometry; those in `no_stiffness` lose their radial stiffness. Returns the .rexsj path."""
    bearings = ROLLING_BEARINGS if bearings is None else bearings
    exported = folder / "exported_bearings.rexsj"
    result = run("export", GEARBOX, "-o", exported, "--quiet")
    assert result.returncode == 0, result.stderr
    document = json.loads(exported.read_text())
    model = document["model"]
    components, relations = model["components"], model["relations"]
    next_id = max(c["id"] for c in components) + 1

    def add(kind, name, attributes):
        nonlocal next_id
        components.append({"id": next_id, "type": kind, "name": name, "attributes": attributes})
        next_id += 1
        return next_id - 1

    def part(assembly, piece, relation="assembly"):
        relations.append({"id": len(relations) + 1, "type": relation, "order": 1,
                          "refs": [{"id": assembly, "role": "assembly", "hint": ""},
                                   {"id": piece, "role": "part", "hint": ""}]})

    for component in components:
        name = component["name"]
        if name in no_stiffness:
            component["attributes"] = [a for a in component["attributes"]
                                       if a["id"] != "radial_stiffness"]
        if name in catalogue_only:
            component["type"] = "rolling_bearing_with_catalog_geometry"
            component["attributes"] = [a for a in component["attributes"]
                                       if a["id"] != "radial_stiffness"]
            component["attributes"] += [{"id": "bearing_type", "unit": "none",
                                         "enum": "radial_grooved_ball_bearing"},
                                        {"id": "catalogue_designation", "unit": "none",
                                         "string": "6208"}]
            part(component["id"], add("rolling_bearing_row", "", [_attribute("pressure_angle", "deg", 0.0)]),
                 "ordered_assembly")
        if name not in bearings:
            continue
        bearing_type, own, row, element = bearings[name]
        component["type"] = "rolling_bearing_with_detailed_geometry"
        component["attributes"] += [{"id": "bearing_type", "unit": "none", "enum": bearing_type}]
        component["attributes"] += [_attribute(*a) for a in own]
        row_id = add("rolling_bearing_row", f"{name} row 1", [_attribute(*a) for a in row])
        part(component["id"], row_id, "ordered_assembly")
        part(row_id, add("rolling_element", f"{name} rolling element",
                         [_attribute(*a) for a in element]))
    path = folder / "reducer_rolling_bearings.rexsj"
    path.write_text(json.dumps(document, indent=1))
    return path

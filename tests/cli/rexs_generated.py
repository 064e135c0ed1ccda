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

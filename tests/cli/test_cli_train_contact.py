"""geardyn train on the flexible two-stage reducer (issue 36): `static` writes the mesh
misalignment, `contact` couples the deflection with the loaded contact across the face of both
meshes to a fixed point, and a mesh with excitation = "ltca" takes its loaded STE and tangent
stiffness into `forced` (whine orders from the gearbox's own deflection)."""

import csv
import json

from cli_support import EXAMPLES, run

FLEXIBLE = EXAMPLES / "train_two_stage_flexible.toml"
QUICK = ["--set", "output.plots=false"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_static_contact_and_ltca_excitation(tmp_path):
    out = tmp_path / "contact"
    result = run("train", str(FLEXIBLE), "--out", str(out), *QUICK,
                 "--set", 'analysis.run=["static", "contact"]', "--set", "contact.positions=32")
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    misalignment = summary["results"]["static"]["misalignment"]
    assert set(misalignment) == {"stage1", "stage2"}
    rows = {r["mesh"]: r for r in _rows(out / "mesh_misalignment.csv")}
    assert abs(float(rows["stage2"]["mismatch_m"])) > 1e-7
    contact = summary["results"]["contact"]
    assert contact["converged"] and len(contact["change_per_iteration"]) == contact["iterations"]
    for mesh in ("stage1", "stage2"):
        k = contact["meshes"][mesh]["face_load_factor"]
        assert 1.0 < k < 3.0
        assert (out / f"face_load_{mesh}.csv").exists()
    table = {r["mesh"]: r for r in _rows(out / "mesh_contact.csv")}
    assert float(table["stage1"]["face_load_factor"]) == contact["meshes"]["stage1"]["face_load_factor"]
    # The load cases: at factor 1 the operating point's fixed point again; the misalignment grows
    # with the load (the deflection is linear in the torque, the coupling moves it a little).
    cases = _rows(out / "contact_load_cases.csv")
    at_one = [r for r in cases if float(r["load_factor"]) == 1.0 and r["mesh"] == "stage2"]
    assert abs(float(at_one[0]["face_load_factor"]) - contact["meshes"]["stage2"]["face_load_factor"]) < 1e-12
    stage2 = [abs(float(r["mismatch_m"])) for r in cases if r["mesh"] == "stage2"]
    assert stage2 == sorted(stage2)

    # The same meshes as the forced response's excitation: k_t(φ) and e = STE − F/k_t.
    excited = tmp_path / "excited"
    result = run("train", str(FLEXIBLE), "--out", str(excited), *QUICK,
                 "--set", 'analysis.run=["forced"]', "--set", "forced.points=5",
                 "--set", "forced.mesh_harmonics=3", "--set", "contact.positions=32",
                 "--set", 'meshes.stage2.excitation="ltca"')
    assert result.returncode == 0, result.stderr
    summary = json.loads((excited / "summary.json").read_text())
    assert summary["results"]["excitation_ltca"]["converged"]
    assert set(summary["results"]["excitation_ltca"]["meshes"]) == {"stage2"}
    assert "forced" in summary["results"]
    # The whine's path into the housing: every radial bearing's force at each mesh's first three
    # orders and every speed (forced_bearing_orders.csv; checked against the DFT of the sampled
    # bearing force in tests/system/train_response_test.cpp), loaded at stage 2's first order.
    orders = _rows(excited / "forced_bearing_orders.csv")
    assert {r["bearing"] for r in orders} >= {"input_a", "input_b", "output_a", "output_b"}
    assert {int(r["order"]) for r in orders} == {1, 2, 3}
    assert len({r["speed_rpm"] for r in orders}) == 5
    first = [float(r["amplitude_n"]) for r in orders
             if r["mesh"] == "stage2" and r["order"] == "1" and "." not in r["bearing"]]
    assert min(first) > 0.0  # every radial bearing (an axial spring may carry none)

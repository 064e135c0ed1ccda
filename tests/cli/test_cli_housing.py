"""Issue #37: a flexible housing in the gearbox file. Bad [housing] input exits 2 naming its key
(before ccx runs, so these need neither ccx nor a mesh)."""

import pathlib
import subprocess

from cli_support import CLI

SOURCE = pathlib.Path(__file__).resolve().parents[2]


def housed_gearbox(folder, housing):
    """The example's housed two-stage reducer with its [housing] replaced by `housing`."""
    text = (SOURCE / "examples/gearboxes/two_stage_reducer_housed.toml").read_text()
    text = text[:text.index("[housing]")] + "[housing]\n" + housing
    (folder / "gearbox.toml").write_text(text)
    (folder / "deck.inp").write_text("*NODE\n1, 0, 0, 0\n")
    analysis = folder / "train.toml"
    analysis.write_text('[gearbox]\nfile = "gearbox.toml"\n[analysis]\nrun = ["modal"]\n')
    return analysis


def run(analysis, tmp_path):
    return subprocess.run([CLI, "train", str(analysis), "--out", str(tmp_path / "out")],
                          capture_output=True, text=True)


def test_units_not_declared_exit_2_naming_the_key(tmp_path):
    result = run(housed_gearbox(tmp_path, 'deck = "deck.inp"\n'), tmp_path)
    assert result.returncode == 2, result.stderr
    assert "housing.units" in result.stderr, result.stderr


def test_a_seat_set_naming_no_bearing_exits_2_naming_it(tmp_path):
    seats = '["INPUT_A", "INPUT_B", "INTERMEDIATE_A", "INTERMEDIATE_B", "OUTPUT_A", "OUTPUT_X"]'
    result = run(housed_gearbox(tmp_path, f'deck = "deck.inp"\nunits = "si"\nseats = {seats}\n'),
                 tmp_path)
    assert result.returncode == 2, result.stderr
    assert "housing.seats" in result.stderr and "OUTPUT_X" in result.stderr, result.stderr
    assert 'did you mean "output_' in result.stderr, result.stderr  # output_a and _b are as close


def test_a_bearing_without_a_seat_exits_2_naming_it(tmp_path):
    result = run(housed_gearbox(tmp_path, 'deck = "deck.inp"\nunits = "si"\nseats = ["INPUT_A"]\n'),
                 tmp_path)
    assert result.returncode == 2, result.stderr
    assert "housing.seats" in result.stderr and "input_b" in result.stderr, result.stderr

"""The type stubs (python/geardyn/_geardyn.pyi) are valid Python, cover every public name of the
compiled module and match what scripts/make_stubs.py generates from the current bindings."""

import ast
import importlib.util
import os
import pathlib

import geardyn._geardyn as core

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
STUB = SOURCE / "python" / "geardyn" / "_geardyn.pyi"


def test_stubs_are_current_and_complete(tmp_path):
    spec = importlib.util.spec_from_file_location("make_stubs", SOURCE / "scripts" / "make_stubs.py")
    make_stubs = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_stubs)
    fresh = tmp_path / "_geardyn.pyi"
    make_stubs.main(fresh)
    assert fresh.read_text() == STUB.read_text(), (
        "regenerate: PYTHONPATH=build/python /usr/bin/python3 scripts/make_stubs.py")
    tree = ast.parse(STUB.read_text())
    declared = {node.name for node in tree.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    public = {name for name in vars(core) if not name.startswith("_")}
    assert public <= declared, sorted(public - declared)

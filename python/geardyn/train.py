"""A gear train built once and analysed many times, in-process: ``geardyn.GearTrain``.

``GearTrain(config)`` reads a gearbox once — an analysis file (TOML, the gearbox inline or
named by ``gearbox.file``), a REXS file, or a dict of the same sections — validates it, builds
the machine and keeps it: ``modal()``, ``frequencies()``, ``static()``, ``forced(speeds_rpm)``,
``campbell()`` analyse it without text or files in between and return pandas DataFrames whose
column names end with their unit (``frequency_hz``), or numpy arrays. ``set(key, value)``
changes a key as ``--set`` does and reassembles only what depends on it: a constant mesh
stiffness (``stiffness_value``), the operating speed or torque are rank-one updates of the
assembled matrices; an analysis option keeps the model; another gearbox key builds it anew.

>>> import geardyn
>>> train = geardyn.GearTrain("examples/train_lin_parker1999.toml")   # doctest: +SKIP
>>> train.frequencies()[1]                                            # doctest: +SKIP
743.2...
>>> train.set("planetary.stage.sun_planet.stiffness_value", 6e8)      # doctest: +SKIP
'parameters'
"""

import os
import pathlib

from . import _geardyn
from ._cli import _toml_value, to_toml
from .results import Result

__all__ = ["GearTrain"]

# Files read as REXS (imported in memory by gearbox.file), as `geardyn import` reads them.
_REXS_SUFFIXES = (".rexs", ".rexsj", ".rexsz", ".json", ".xml")


def _overrides(overrides):
    if isinstance(overrides, dict):
        return [f"{k}={_toml_value(v)}" for k, v in overrides.items()]
    return list(overrides or [])


class GearTrain:
    """A gear train built once (from a dict, a TOML analysis or gearbox file, or a REXS file)
    and analysed many times in this process.

    - ``config``: a path (TOML analysis file; REXS file) or a dict of the file's sections.
    - ``overrides``: {"section.key": value} or ["section.key=value"] (as the CLI's --set).
    - ``load_case``: the REXS load case (REXS files only).
    """

    def __init__(self, config, *, overrides=None, load_case=None):
        sets = _overrides(overrides)
        if isinstance(config, dict):
            self._native = _geardyn.GearTrain(text=to_toml(config), source="<dict>",
                                              base_dir=os.getcwd(), overrides=sets)
            return
        path = pathlib.Path(os.fspath(config))
        with open(path, "rb"):  # OSError (FileNotFoundError, PermissionError) as Python has it
            pass
        if path.suffix.lower() in _REXS_SUFFIXES:
            document = {"gearbox": {"file": str(path.resolve())}}
            if load_case is not None:
                document["gearbox"]["load_case"] = int(load_case)
            self._native = _geardyn.GearTrain(text=to_toml(document), source=str(path),
                                              base_dir=str(path.parent), overrides=sets)
            return
        if load_case is not None:
            sets.append(f"gearbox.load_case={int(load_case)}")
        self._native = _geardyn.GearTrain(path=str(path), overrides=sets)

    def set(self, key, value):
        """Sets ``key`` (dotted, as --set) to ``value``; returns what was reassembled:
        'nothing' (an analysis option), 'parameters' (a constant mesh's stiffness_value, the
        operating speed_rpm or torque) or 'model' (any other gearbox key: built anew).
        geardyn.ConfigError for a value out of range (the train is left as it was)."""
        return self._native.set(key, _toml_value(value))

    def frequencies(self):
        """The natural frequencies of the `modal` analysis [Hz] as a numpy array (the
        frequency_hz column of modes.csv; its speed: modal.speed_rpm or the operating speed)."""
        return self._native.frequencies()

    def modes(self, shapes=True):
        """The `modal` analysis as {column: numpy array} (modes.csv's columns; ``mesh_strain``
        and ``element_strain`` modes × meshes / elements; ``shapes`` DOFs × modes, complex)."""
        return self._native.modes(shapes)

    def modal(self):
        """The `modal` analysis as a DataFrame: modes.csv's columns (frequency_hz,
        damping_ratio, divergent, growth_rate_1_per_s, multiplicity, stage_type,
        translational_fraction, strain_<mesh>, strain_<element>), one row per mode (index
        ``mode`` from 1); the mode shapes in ``df.attrs["shapes"]`` (DOFs × modes) with the DOF
        names in ``df.attrs["dofs"]``."""
        import pandas as pd

        m = self._native.modes(True)
        columns = {k: m[k] for k in ("frequency_hz", "damping_ratio", "divergent",
                                      "growth_rate_1_per_s", "multiplicity", "stage_type",
                                      "translational_fraction")}
        for i, name in enumerate(self._native.mesh_names):
            columns["strain_" + name] = m["mesh_strain"][:, i]
        for i, name in enumerate(self._native.element_names):
            columns["strain_" + name] = m["element_strain"][:, i]
        frame = pd.DataFrame(columns, index=pd.RangeIndex(1, len(m["frequency_hz"]) + 1,
                                                          name="mode"))
        frame.attrs["units"] = {"frequency_hz": "Hz", "growth_rate_1_per_s": "1/s"}
        frame.attrs["speed_rpm"] = self._native.modal_speed_rpm
        frame.attrs["shapes"] = m["shapes"]
        frame.attrs["dofs"] = self._native.dof_names
        return frame

    def static(self):
        """The `static` analysis: static_forces.csv as a DataFrame (component, kind, unit,
        force: mesh forces along the contact normal [N], bearing forces [N] or torques
        [N m])."""
        return self.run(["static"]).to_pandas("static_forces")

    def forced(self, speeds_rpm):
        """The forced response at the input speeds ``speeds_rpm`` [rpm]: forced_response.csv
        as a DataFrame (dynamic factor, peak-to-peak and first-order mesh forces per mesh)."""
        speeds = [float(s) for s in speeds_rpm]
        return Result(self._native.forced(speeds)).to_pandas("forced_response")

    def campbell(self):
        """The Campbell diagram ([campbell] options): campbell.csv as a DataFrame."""
        return self.run(["campbell"]).to_pandas("campbell")

    def run(self, analyses=None):
        """`geardyn train` on the built model: a geardyn.Result with every table and
        summary.json of the analyses named (default: analysis.run)."""
        return Result(self._native.analyze(list(analyses or [])))

    @property
    def dof_names(self):
        """"sun.y", "stage.planet1.theta", … in the order of the matrices."""
        return self._native.dof_names

    @property
    def mesh_names(self):
        return self._native.mesh_names

    @property
    def mass(self):
        """M [kg, kg m²] (numpy, DOFs × DOFs)."""
        return self._native.mass

    @property
    def stiffness(self):
        """K + Ω² K_Ω + Σ k̄ v vᵀ at the operating speed [N/m, N m/rad] (numpy)."""
        return self._native.stiffness

    def __repr__(self):
        return (f"GearTrain({len(self._native.dof_names)} DOFs, "
                f"{len(self._native.mesh_names)} meshes)")

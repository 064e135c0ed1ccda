"""geardyn: gear-pair and geared-rotor dynamics.

From gear geometry to mesh stiffness, dynamic response, spectra and identification. The compiled
core lives in ``geardyn._geardyn``; this package re-exports it and adds ``run`` (every analysis,
in-process, results as numpy arrays and pandas DataFrames) and ``plot``.

>>> r = run("geometry", pinion=Gear(teeth=25, module=3e-3, face_width=0.02),
...         gear=Gear(teeth=30, module=3e-3, face_width=0.02))
>>> r.to_pandas("gears").attrs["units"]["base_radius_m"]
'm'

>>> import geardyn
>>> pinion = geardyn.Gear(teeth=25, module=3e-3, face_width=0.02)
>>> gear = geardyn.Gear(teeth=30, module=3e-3, face_width=0.02)
>>> round(geardyn.GearPair(pinion=pinion, gear=gear).contact_ratio_transverse, 7)
1.6325826
"""

from ._geardyn import (  # noqa: F401  (re-exported API)
    AnalysisResult,
    ConfigError,
    ConstantMeshStiffness,
    FeGearedRotor,
    FeTimeResponse,
    FourierMeshStiffness,
    Gear,
    GearGeometry,
    GearPair,
    LateralRotor,
    MeshStiffness,
    PotentialEnergyMeshStiffness,
    StepMeshStiffness,
    __version__,
    api_directional_stiffness,
    api_mesh_stiffness,
    config_reference,
    full_spectrum,
    gear_whirl_peaks,
    harris_map,
    identify_dte,
    iso6336_stiffness,
    load_config,
    loaded_contact,
    mesh_phase_from_roll_angle,
    roll_angle_from_mesh_phase,
)

from . import _errors, _geardyn  # noqa: E402
from ._cli import FolderResult, load, to_toml  # noqa: F401,E402
from .analysis import COMMANDS, run, sweep  # noqa: F401,E402
from .results import Result  # noqa: F401,E402
from .train import GearTrain  # noqa: F401,E402

# Keyword-argument errors in Python terms (missing, unknown with a did-you-mean).
for _name in dir(_geardyn):
    _obj = getattr(_geardyn, _name)
    if _name.startswith("_") or _name in ("AnalysisResult", "ConfigError"):
        continue
    if isinstance(_obj, type) and "__init__" in vars(_obj):
        _errors.check_class(_obj)
    elif callable(_obj) and not isinstance(_obj, type) and _name in globals():
        globals()[_name] = _errors.checked_function(_obj, _name)
del _name, _obj

MESH_STIFFNESS_MODELS = ("potential_energy", "api", "step", "fourier", "iso6336")


def mesh_stiffness(pair, model="potential_energy", **options):
    """A mesh-stiffness model of a GearPair, by name, as in ``[mesh_stiffness] models``.

    - ``"potential_energy"``: options of PotentialEnergyMeshStiffness (root, foundation_arm,
      foundation, pinion_hub_radius, gear_hub_radius, slices, helical_cos2_beta_b, table_points).
    - ``"api"``: the API constant for the pair's face width and helix angle.
    - ``"iso6336"``: ISO 6336-1 c_gamma_alpha * b (options c_m, material_factor).
    - ``"step"``: ``levels="potential_energy"`` (default; zone means of that model, taking its
      options as ``source_options``), ``"api"``, ``"iso6336"`` or ``k_min=..., k_max=...``.
    - ``"fourier"``: ``order`` harmonics (default 1) fitted to the potential-energy model, with
      ``mean="fit" | "api" | "iso6336"`` or a number [N/m].

    Returns a MeshStiffness: call it with mesh phases; ``.summary(order)`` gives statistics.
    """
    eps = pair.contact_ratio_total
    beta_deg = pair.pinion_spec.helix_angle_deg
    if model == "potential_energy":
        return PotentialEnergyMeshStiffness(pair, **options)
    if model == "api":
        _no_options(model, options)
        return ConstantMeshStiffness("api", api_mesh_stiffness(pair.effective_face_width, beta_deg), eps)
    if model == "iso6336":
        return ConstantMeshStiffness("iso6336", iso6336_stiffness(pair, **options)["mesh_stiffness"], eps)
    if model == "step":
        levels = options.pop("levels", "potential_energy")
        if "k_min" in options or "k_max" in options:
            return StepMeshStiffness(k_min=options.pop("k_min"), k_max=options.pop("k_max"), contact_ratio=eps)
        source_options = options.pop("source_options", {})
        _no_options(model, options)
        if levels == "potential_energy":
            return StepMeshStiffness.from_model(PotentialEnergyMeshStiffness(pair, **source_options))
        return StepMeshStiffness.from_mean(mesh_stiffness(pair, levels)(0.0), eps)
    if model == "fourier":
        order = options.pop("order", 1)
        mean = options.pop("mean", "fit")
        source_options = options.pop("source_options", {})
        _no_options(model, options)
        value = 0.0 if mean == "fit" else (mean if isinstance(mean, (int, float)) else mesh_stiffness(pair, mean)(0.0))
        return FourierMeshStiffness.fit(PotentialEnergyMeshStiffness(pair, **source_options), order, value)
    raise ValueError(f"model = {model!r}: must be one of {', '.join(MESH_STIFFNESS_MODELS)}")


def _no_options(model, options):
    if options:
        raise ValueError(f"model {model!r} takes no option(s) {', '.join(sorted(options))}")


__all__ = [
    "COMMANDS", "ConfigError", "FolderResult", "Result", "load", "run", "sweep", "to_toml",
    "ConstantMeshStiffness", "FourierMeshStiffness", "Gear", "GearGeometry", "GearPair",
    "MeshStiffness", "PotentialEnergyMeshStiffness", "StepMeshStiffness", "__version__",
    "api_directional_stiffness", "api_mesh_stiffness", "config_reference", "iso6336_stiffness",
    "load_config", "mesh_stiffness", "MESH_STIFFNESS_MODELS", "mesh_phase_from_roll_angle",
    "roll_angle_from_mesh_phase",
]


def __getattr__(name):
    """``geardyn.report`` (write_report: the HTML report) is imported on first use, so that
    ``python -m geardyn.report`` (what `geardyn report` runs) does not import it twice."""
    if name == "report":
        import importlib

        return importlib.import_module(".report", __name__)
    raise AttributeError(f"module 'geardyn' has no attribute {name!r}")

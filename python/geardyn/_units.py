"""Units of the columns of geardyn's result tables (``Result.units``, ``df.attrs["units"]``).

Most columns carry their unit in their name, as the CSV files do (``base_radius_m``,
``frequency_hz``, ``speed_rpm``); the others are listed here per table. A dimensionless number
has the unit "" and a text column None. A gear-pair model given in nondimensional form
(``[model] nondimensional``) has dimensionless columns throughout.
"""

import re

# Name endings and their units (docs/development.md, "Result names"): snake_case with a
# lower-case unit suffix. Compared without case, so files written before the convention
# ("_Hz", "_N_m") still read; the longest ending wins ("_n_m" is N m, not m).
_SUFFIXES = sorted([
    ("_nondim", ""), ("_hz_per_rpm", "Hz/rpm"), ("_1_per_s", "1/s"), ("_periods", "periods"),
    ("_m_per_s2", "m/s^2"), ("_m_per_s", "m/s"), ("_rad_per_s2", "rad/s^2"),
    ("_rad_per_s", "rad/s"), ("_n_s_per_m", "N s/m"), ("_n_per_m", "N/m"), ("_n_m", "N m"),
    ("_rad_s", "rad/s"), ("_m_s2", "m/s^2"), ("_m_s", "m/s"), ("_kg_m2", "kg m^2"),
    ("_kg", "kg"), ("_mm", "mm"), ("_um", "µm"), ("_hz", "Hz"), ("_rpm", "rpm"),
    ("_rad", "rad"), ("_deg", "deg"), ("_pa", "Pa"), ("_j", "J"), ("_s", "s"), ("_m", "m"),
    ("_n", "N"), ("_percent", "%"), ("_db", "dB"),
], key=lambda pair: -len(pair[0]))


def suffix_unit(name):
    """The unit a result name ends with ("mesh_force_n" -> "N", "torque_n_m" -> "N m",
    "mesh_frequency_hz_per_rpm" -> "Hz/rpm"), or None when it ends with none."""
    lower = name.lower()
    for suffix, unit in _SUFFIXES:
        if lower.endswith(suffix) and len(name) > len(suffix):
            return unit
    return None


# Dimensionless by their meaning.
_DIMENSIONLESS = re.compile(
    r"^(h\d+|.*ratio.*|.*fraction.*|.*relative.*|.*factor.*|share_pair_\d+|order|mode|index|case|"
    r"count|teeth|undercut|steady|stable|divergent|harmonic|line|dof|sweep_point|point|phase_fraction|tau|sample|"
    r"contact_loss|converged|branch|.*_index|.*_count|iterations|whirl_direction|"
    r"ratio_low|ratio_high|p_value|samples|teeth_.|multiplicity|strain_.*|seed|real|imag)$")

# A unit between underscores inside a name: "p2p_n_stage1" (and "p2p_N_stage1" of older files).
_INFIX = re.compile(r"_(n|hz|N|Hz|rpm|m|s|rad|deg)_")
_INFIX_UNITS = {"n": "N", "hz": "Hz"}

# Columns without a unit in their name: {table: {column: unit}} (tables of any command).
_TABLES = {
    "time_response": {"t": "s", "x": "m", "v": "m/s", "y": "m", "mesh_force": "N", "k": "N/m"},
    "sweep": {"frequency": "Hz", "p2p": "m", "mean": "m", "max": "m", "min": "m",
              "omega": "rad/s", "residual": "m", "rms": "m"},
    "newmark": {"frequency": "Hz", "p2p_newmark": "m", "p2p_hbm": "m"},
    "period": {"t": "s", "x": "m", "y": "m", "mesh_force": "N", "mesh_stiffness": "N/m",
               "tau": "rad"},
    "mesh_stiffness": {"k_total": "N/m", "mesh_phase": "", "roll_angle_rad": "rad"},
    "fourier": {"mean": "N/m", "amplitude": "N/m", "phase": "rad", "a": "N/m", "b": "N/m"},
    "time_history": {"t": "s", "x1": "m", "y1": "m", "x2": "m", "y2": "m"},
    "frequency_components": {"re": "m", "im": "m", "amplitude": "m", "phase": "rad"},
    "spectrum_peaks": {"re": "m", "im": "m", "amplitude": "m", "phase": "rad"},
    "full_spectrum": {"re": "m", "im": "m", "amplitude": "m", "phase": "rad"},
    "study": {"amplitude": "m", "phase": "rad"},
    "harmonics": {"displacement": "m", "acceleration": "m/s^2"},
    "spectrum": {"displacement": "m", "acceleration": "m/s^2"},
    "waterfall": {"amplitude": "m/s^2"},
    "mode_shapes": {"re": "", "im": "", "amplitude": ""},
    "compare_spectra": {"displacement": "m", "acceleration": "m/s^2"},
    "compare_harmonics": {"displacement": "m", "acceleration": "m/s^2"},
    "compare_stiffness": {"stiffness": "N/m"},
    # Gelman (2005): k = K/K̄ and e_f = E/x₀ are normalised, so are their statistics; the
    # mesh phase φ is a fraction of a mesh period.
    "monte_carlo": {"dynamic_mean_excitation": "", "r_ke": "", "d_k": "", "d_e": "",
                    "delta_m1_ef": "", "phase": ""},
    "load_statistics": {"a": "", "m1_k": "", "m1_ef": "", "d_k": "", "d_e": "", "r_ke": "",
                        "delta_m1_ef": "", "variable_term_v": ""},
    "mesh_statistics": {"a": "", "d_k": "", "d_e": "", "r_ke": "", "delta_m1_ef": "",
                        "variable_term_v": ""},
    # One row per identified parameter, each in its own unit (N/m, m, N s/m, rad).
    "identified": {"value": "(per row: parameter)", "ci_low": "(per row: parameter)",
                   "ci_high": "(per row: parameter)", "true": "(per row: parameter)",
                   "error": "(per row: relative, rad for phases)", "identifiable": ""},
    "resimulated_peaks": {"measured_re": "m", "measured_im": "m", "measured_amplitude": "m",
                          "model_re": "m", "model_im": "m", "model_amplitude": "m",
                          "phase": "rad"},
    "static_forces": {"force": "N"},
    "ltca": {"force": "N", "secant_stiffness": "N/m", "tangent_stiffness": "N/m", "phase": ""},
}


def _table_key(name):
    base = name[:-4] if name.endswith(".csv") else name
    return "period" if base.startswith("period_") else base


def unit_of(table, column):
    """The unit of ``column`` in ``table`` ("" dimensionless), or None when unknown."""
    known = _TABLES.get(_table_key(table), {})
    if column in known:
        return known[column]
    if column.startswith(("k_pair_", "k_")) and _table_key(table) == "mesh_stiffness":
        return "N/m"
    if column.startswith("load_pair_"):
        return "N"
    unit = suffix_unit(column)
    if unit is not None:
        return unit
    if _DIMENSIONLESS.match(column):
        return ""
    infix = _INFIX.search(column)
    if infix:
        return _INFIX_UNITS.get(infix.group(1), infix.group(1))
    return None


def sweep_units(config, columns):
    """Units of a sweep table: parameters are configuration keys of the swept command (their
    schema unit), outputs are named results (by the last part of their JSON pointer)."""
    from ._geardyn import config_unit

    study = (config or {}).get("study", {})
    # Results whose numbers below them share a unit (/mesh_force/peak_to_peak is in N).
    parents = {"mesh_force": "N", "y": "m", "x": "m", "transmission_error": "m"}
    leaves = {"frequency": "Hz", "p2p": "m", "natural_frequency": "Hz", "points": "",
              "failures": "", "wall_time_s": "s"}
    specs = study.get("outputs", {})  # resolved: {name: pointer}; as written: ["name=/ptr"]
    if isinstance(specs, list):
        specs = dict(s.partition("=")[::2] if "=" in s else (s, s) for s in specs)
    outputs = {}
    for name, pointer in specs.items():
        parts = pointer.strip("/").split("/")
        unit = leaves.get(parts[-1], unit_of("sweep_outputs", parts[-1]))
        if unit is None and len(parts) > 1:
            unit = parents.get(parts[-2])
        outputs[name] = unit
    units = {}
    for column, values in columns.items():
        if values.dtype.kind in "USO":
            units[column] = None
        elif column in ("case", "seed"):
            units[column] = ""
        elif column in outputs:
            units[column] = "?" if outputs[column] is None else outputs[column]
        else:
            try:
                unit = config_unit(study.get("command", ""), column)
            except ValueError:
                unit = None
            units[column] = "?" if unit is None else ("" if unit == "-" else unit)
    return units


def column_units(result, table, columns):
    """{column: unit} for a Result's table: text columns None, numbers their unit."""
    nondimensional = bool(((result.summary.get("config") or {}).get("model") or {}).get(
        "nondimensional", False))
    units = {}
    for name, values in columns.items():
        if isinstance(values, list):
            units[name] = None
        elif nondimensional and _table_key(table) in ("time_response", "sweep", "newmark", "period"):
            units[name] = ""
        else:
            unit = unit_of(table, name)
            units[name] = unit if unit is not None else "?"
    return units

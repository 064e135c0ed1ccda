"""Result names and printed units (issue 18, item 5; docs/development.md, "Result names"): every
example's stdout gives units, every CSV column and summary.json result key is snake_case with a
lower-case unit suffix (or dimensionless), one spelling per quantity. run_example.py applies
these checks to each example's own run (issue 34: the suite runs every example once);
tests/cli/test_cli_first_day.py checks that they can fail."""

import csv
import json
import re

# One convention for CSV columns and summary keys: the unit ends the name, lower case
# (docs/development.md, "Result names"); db is a level in decibels, its reference named where
# the column is documented (housing_response.csv: re 1e-6 m/s²).
UNIT_SUFFIX = re.compile(
    r"(^|_)(m|mm|um|n|n_m|n_per_m|n_s_per_m|hz|hz_per_rpm|rpm|s|rad|deg|kg|kg_m2|m_per_s|"
    r"m_per_s2|rad_per_s|rad_per_s2|periods|nondim|pa|j|us|db)$")
# Dimensionless by their meaning: ratios, fractions, counts, flags, Gelman's (2005) normalised
# statistics (k = K/K̄, e_f = E/x₀: a, m1_k, d_k, r_ke, ...), indices.
DIMENSIONLESS = re.compile(
    r"^(.*ratio.*|.*fraction.*|.*relative.*|.*factor.*|share_pair_\d+|order|mode|case|count|"
    r"teeth|teeth_[ab]|undercut|steady|stable|divergent|branch|newton_iterations|contact_loss|multiplicity|strain_.*|"
    r"point|solution|step_cuts|critical_multiplier_abs|contact_loss_.*|back_flank_.*|"
    r"sample|seed|harmonic|harmonic_g\d+|identifiable|a|m1_k|m1_ef|d_k|d_e|r_ke|delta_m1_ef|variable_term_v|"
    r"dynamic_mean_excitation)$")
MODE_SHAPES = {"re", "im", "amplitude", "real", "imag"}  # normalised shapes
# A unit written in capitals, at the end or between underscores: "_Hz", "_N_m", "p2p_N_stage1".
CAPITAL_UNIT = re.compile(r"(^|_)(Hz|N|N_m|N_per_m|N_s_per_m|Pa|MPa|J|Kg|KG|RPM|Rpm|Rad|Deg)"
                          r"(_|$)")
# One spelling per quantity: t_s for time, frequency_hz for frequency.
OTHER_SPELLINGS = re.compile(r"^(time|time_s|t|freq|freq_hz|f_hz|time_hz|frequency_s)$")


def badly_cased(name):
    """A name whose unit is not lower case (docs/development.md, "Result names")."""
    return bool(CAPITAL_UNIT.search(name)) or (
        bool(UNIT_SUFFIX.search(name.lower())) and not UNIT_SUFFIX.search(name)
        and not DIMENSIONLESS.match(name.lower()))


def summary_keys_badly_named(value, path=""):
    """Keys of summary.json's results whose unit is not a lower-case suffix."""
    bad = []
    if isinstance(value, dict):
        for key, item in value.items():
            if badly_cased(key) or OTHER_SPELLINGS.match(key) and not isinstance(item, dict):
                bad.append(f"{path}{key}")
            bad += summary_keys_badly_named(item, f"{path}{key}.")
    elif isinstance(value, list):
        for item in value:
            bad += summary_keys_badly_named(item, path)
    return bad

def numeric(values):
    values = [v for v in values if v != ""]
    try:
        return bool(values) and all(float(v) == float(v) or v.lower() == "nan" for v in values)
    except ValueError:
        return False


def columns_without_units(path):
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    header, body = rows[0], rows[1:]
    if "unit" in header:  # one unit per row, named in its own column
        return [name for name in header if badly_cased(name)]
    bad = [name for name in header if badly_cased(name)]
    for i, name in enumerate(header):
        if not numeric([r[i] for r in body if i < len(r)]):
            continue  # text
        if OTHER_SPELLINGS.match(name):
            bad.append(name)
            continue
        if UNIT_SUFFIX.search(name) or DIMENSIONLESS.match(name):
            continue
        if path.name == "mode_shapes.csv" and name in MODE_SHAPES:
            continue
        bad.append(name)
    return bad


NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.\d+(?:[eE][-+]?\d+)?|\d+[eE][-+]?\d+)(?![\w.])")
# A number is followed by its unit, or by "/", "..", "to" or "->" and another number (a pair or
# a range in one unit).
AFTER = re.compile(r"\s*(\[-\]|%|µm|um|mm|m/s\^2|N/m|N s/m|N m|N|Hz|rpm|ms|s|rad|deg|kg|m|dB|"
                   r"periods|GB|MB)(?![\w/])")
JOIN = re.compile(r"\s*(/|\.\.|to|->)\s*")


def numbers_without_units(line, table_unit):
    if table_unit:
        return []
    bad = []
    for match in NUMBER.finditer(line):
        rest = line[match.end():]
        while True:
            join = JOIN.match(rest)
            if not join or not NUMBER.match(rest[join.end():]):
                break
            rest = rest[join.end() + NUMBER.match(rest[join.end():]).end():]
        declared = re.search(r"\[[^\]]+\]", line[:match.start()])
        if not AFTER.match(rest) and not declared:
            bad.append(match.group())
    return bad


def stdout_lines_without_units(text):
    bad, table_unit = [], False
    for line in text.splitlines():
        if line.startswith("results:"):
            continue
        if re.search(r"\[[^\]]+\]", line) and not NUMBER.search(line):
            table_unit = True  # a table header: "model [N/m]   mean   min ..."
            continue
        if table_unit and not line.startswith("  ") or not line.strip():
            table_unit = False
        # A table row: the name then numbers only.
        row = table_unit and re.fullmatch(r"\s+\S+(\s+[-+\d.eE]+)+", line)
        if numbers_without_units(line, row):
            bad.append(line)
    return bad


def naming_failures(command, out, stdout):
    """What an example's run at `out` (its result folder) and its `stdout` break of the
    conventions above, as messages (empty: none)."""
    failures = []
    lines = stdout_lines_without_units(stdout)
    if lines:
        failures.append(f"numbers printed without a unit: {lines[:3]}")
    for table in sorted(out.rglob("*.csv")):
        # The sweep's own table: the swept keys and the outputs the study names (the
        # example's names follow the convention too).
        if command == "sweep" and table.parent == out:
            with open(table, newline="") as handle:
                bad = [n for n in next(csv.reader(handle)) if badly_cased(n)]
        else:
            bad = columns_without_units(table)
        if bad:
            failures.append(f"{table.relative_to(out)}: columns without a lower-case unit "
                            f"{sorted(set(bad))}")
    results = json.loads((out / "summary.json").read_text()).get("results", {})
    bad = sorted(set(summary_keys_badly_named(results)))
    if bad:
        failures.append(f"summary.json result keys without a lower-case unit: {bad}")
    return failures

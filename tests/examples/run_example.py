"""Runs one example end to end and checks the numbers its header comment states (issue 34).

Usage: run_example.py --cli GEARDYN --example examples/NAME.toml --out DIR

The example runs as a user runs it (`geardyn <command> NAME.toml --out DIR`, the command
being the file name's first word) and must exit 0; what it prints and writes must follow the
result-name conventions (result_names.py: units on every printed number, lower-case unit
suffixes in CSV headers and summary.json). Then every line of its header comment of the
form

    #   expect <path> = <value> ± <tolerance>[%]   (why this value, why this tolerance)

is checked against DIR/summary.json: <path> is a dotted path into the JSON with [i] for list
items and ["a.b"] for keys holding dots (e.g. `results.static.mesh_force_n["stage1.sun_planet1"]`); <value> is the number the header states (a published
number, or the value this example is documented to give); the tolerance is absolute, or relative
with a trailing %. An example without any `expect` line fails: an example whose numbers nobody
checks can drift unseen. The run must not warn about the example's own input either (stderr
lines starting with "warning"), unless the header acknowledges that warning with a line

    #   expect-warning <text the warning contains>   (why the example keeps it)

(e.g. the undercut of a published rig's pinion: a property of the case, not a defect of it).
"""

import argparse
import json
import math
import pathlib
import re
import subprocess
import sys

from result_names import naming_failures

EXPECT = re.compile(
    r"^#\s*expect\s+(?P<path>\S+)\s*=\s*(?P<value>[-+0-9.eE]+)\s*(?:±|\+-)\s*"
    r"(?P<tolerance>[0-9.eE+-]+)\s*(?P<relative>%?)")
STEP = re.compile(r'\["([^"]+)"\]|([^.\[\]"]+)|\[(\d+)\]')


def header_lines(example):
    """The leading comment block of the file (up to its first non-comment, non-blank line)."""
    lines = []
    for line in example.read_text().splitlines():
        if line.strip() and not line.lstrip().startswith("#"):
            break
        lines.append(line.strip())
    return lines


def expectations(example):
    found = []
    for line in header_lines(example):
        if re.match(r"^#\s*expect\s", line):
            match = EXPECT.match(line)
            if not match:
                raise SystemExit(f"{example.name}: cannot read the expect line {line!r} "
                                 "(form: '# expect <path> = <value> ± <tolerance>[%]')")
            found.append(match)
    return found


def acknowledged_warnings(example):
    return [re.sub(r"^#\s*expect-warning\s+", "", l).split("   (")[0].strip()
            for l in header_lines(example) if re.match(r"^#\s*expect-warning\s", l)]


def lookup(document, path):
    node = document
    for quoted, key, index in STEP.findall(path):
        try:
            node = node[int(index)] if index else node[quoted or key]
        except (KeyError, IndexError, TypeError):
            raise SystemExit(f"summary.json has no {path!r} (stopped at {quoted or key or index!r})")
    return node


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--example", required=True, type=pathlib.Path)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    options = parser.parse_args()
    example = options.example
    command = example.stem.split("_")[0]
    checks = expectations(example)
    if not checks:
        print(f"FAIL {example.name}: its header states no '# expect' numbers to check")
        return 1

    # Not --quiet: its stdout is checked for units (progress lines go to stderr).
    run = subprocess.run([options.cli, command, str(example), "--out", str(options.out)],
                         capture_output=True, text=True)
    sys.stdout.write(run.stdout)
    sys.stderr.write(run.stderr)
    if run.returncode != 0:
        print(f"FAIL {example.name}: exit {run.returncode}")
        return 1
    failures = []
    known = acknowledged_warnings(example)
    warnings = [l for l in run.stderr.splitlines()
                if l.lower().startswith("warning") and not any(k in l for k in known)]
    if warnings:
        failures.append(f"warns about its own input: {warnings[0]!r}")
    failures += naming_failures(command, options.out, run.stdout)

    summary = json.loads((options.out / "summary.json").read_text())
    for match in checks:
        path, stated = match["path"], float(match["value"])
        tolerance = float(match["tolerance"])
        allowed = tolerance * abs(stated) / 100 if match["relative"] else tolerance
        got = lookup(summary, path)
        ok = isinstance(got, (int, float)) and math.isfinite(got) and abs(got - stated) <= allowed
        print(f"{'ok  ' if ok else 'FAIL'} {path} = {got} (stated {stated} ± {allowed:.3g})")
        if not ok:
            failures.append(f"{path} = {got}, the header states {stated} ± {allowed:.3g}")
    if failures:
        print(f"FAIL {example.name}: " + "; ".join(failures))
        return 1
    print(f"{example.name}: {len(checks)} stated numbers reproduced")
    return 0


if __name__ == "__main__":
    sys.exit(main())

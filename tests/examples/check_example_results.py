"""Checks a sweep example's results against what its header comment states (tests/CMakeLists.txt
registers it as example.<stem>.check for every example with `# expect` lines).

Header lines it reads:
  # expect: tolerance = 1e-6                      relative tolerance of every value below
  # expect: case 4: name = 1234.5, other = 0.5    outputs of one case (sweep.csv columns)
  # expect: name falls as key rises               at every fixed value of the other parameters
  # expect: name rises as key rises

Usage: check_example_results.py EXAMPLE.toml RESULT_FOLDER
"""

import csv
import itertools
import math
import re
import sys


def expectations(example):
    lines = []
    for line in open(example, encoding="utf-8"):
        if not line.startswith("#"):
            break  # the header comment only
        match = re.match(r"#\s*expect:\s*(.*)$", line.rstrip())
        if match:
            lines.append(match.group(1).strip())
    return lines


def main(example, folder):
    rows = list(csv.DictReader(open(f"{folder}/sweep.csv", newline="", encoding="utf-8")))
    failures, checked = [], 0
    tolerance = None
    for text in expectations(example):
        if m := re.fullmatch(r"tolerance\s*=\s*(\S+)", text):
            tolerance = float(m.group(1))
        elif m := re.fullmatch(r"case\s+(\d+):\s*(.*)", text):
            if tolerance is None:
                sys.exit(f"{example}: `# expect: tolerance = ...` must come before the values")
            row = rows[int(m.group(1))]
            if row["status"] != "ok":
                failures.append(f"case {m.group(1)}: status {row['status']}: {row['message']}")
                continue
            for item in m.group(2).split(","):
                name, value = (part.strip() for part in item.split("="))
                got, want = float(row[name]), float(value)
                checked += 1
                if not math.isclose(got, want, rel_tol=tolerance, abs_tol=0.0):
                    failures.append(f"case {m.group(1)}: {name} = {got!r}, the header states "
                                    f"{want!r} (relative tolerance {tolerance:g})")
        elif m := re.fullmatch(r"(\S+)\s+(falls|rises)\s+as\s+(\S+)\s+rises", text):
            name, way, key = m.groups()
            others = [k for k in parameters(example) if k != key]
            groups = {}
            for row in rows:
                groups.setdefault(tuple(row[k] for k in others), []).append(row)
            for fixed, group in groups.items():
                group.sort(key=lambda r: float(r[key]))
                for a, b in itertools.pairwise(group):
                    checked += 1
                    ya, yb = float(a[name]), float(b[name])
                    if not (yb < ya if way == "falls" else yb > ya):
                        failures.append(f"{name} does not {way[:-1]} as {key} rises from "
                                        f"{a[key]} to {b[key]} at {dict(zip(others, fixed))}: "
                                        f"{ya!r} -> {yb!r}")
        else:
            sys.exit(f"{example}: cannot read `# expect: {text}`")
    if checked == 0:
        sys.exit(f"{example}: no `# expect:` values to check")
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"{checked} checks, {len(failures)} failed")
    return 1 if failures else 0


def parameters(example):
    """The swept keys: the quoted keys of [study.parameters]."""
    text = open(example, encoding="utf-8").read()
    section = text.split("[study.parameters]", 1)[1]
    return re.findall(r'^\s*"([^"]+)"\s*=', section, flags=re.M)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

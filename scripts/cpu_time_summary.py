#!/usr/bin/env python3
"""Sum a build's CPU time by group from scripts/cpu_time_wrapper.sh's log (issue 34).

    scripts/cpu_time_summary.py LOG [--top N] [--last]

Each log line is "wall user sys command..."; a compile is named by its -o output, a link by its
-o too. Groups: library (src/), tests, apps (the CLI), python (the module), bench, other; links
are counted apart. The idle wall estimate of the build on J cores is sum(CPU) / J plus the serial
tail (printed: the longest compile and the links), which the caller adds by judgement.
"""
import argparse
import collections
import re


def group(output):
    for prefix, name in (("src/", "library"), ("tests/", "tests"), ("apps/", "apps"),
                         ("python/", "python"), ("bench/", "bench")):
        if output.startswith(prefix):
            return name
    return "other"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log")
    parser.add_argument("--top", type=int, default=30)
    parser.add_argument("--last", action="store_true",
                        help="count each output once, its last command (a build interrupted and "
                             "resumed, or a file rebuilt after an edit)")
    args = parser.parse_args()
    rows = []
    for line in open(args.log, encoding="utf-8", errors="replace"):
        parts = line.split(None, 3)
        if len(parts) < 4 or not re.match(r"^[0-9.]+$", parts[1]):
            continue  # "Command exited with non-zero status" and the like
        out = re.search(r"\s-o\s+(\S+)", parts[3])
        link = " -c " not in f" {parts[3]} "
        rows.append((float(parts[1]) + float(parts[2]), float(parts[0]),
                     out.group(1) if out else parts[3][:60], link))
    if args.last:
        rows = list({out: (cpu, wall, out, link) for cpu, wall, out, link in rows}.values())
    by_group = collections.defaultdict(lambda: [0, 0.0])
    for cpu, _, out, link in rows:
        g = ("link " if link else "") + group(out.split("CMakeFiles/")[0] or out)
        by_group[g][0] += 1
        by_group[g][1] += cpu
    total = sum(r[0] for r in rows)
    print(f"{len(rows)} commands, {total:.1f} s CPU (user + sys)")
    for g, (n, cpu) in sorted(by_group.items(), key=lambda kv: -kv[1][1]):
        print(f"  {g:14s} {n:4d} commands {cpu:8.1f} s  {100 * cpu / total:5.1f} %")
    print(f"top {args.top}:")
    for cpu, wall, out, link in sorted(rows, reverse=True)[:args.top]:
        print(f"  {cpu:7.1f} s CPU {wall:7.1f} s wall  {out}")


if __name__ == "__main__":
    main()

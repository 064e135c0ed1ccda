#!/usr/bin/env python3
"""The library's layout rules (docs/design.md): folders depend on each other one way, no file is
over ~600 lines, no folder holds much more than ~20 % of the lines.

Reads every `#include "geardyn/<module>/..."` in src/<module>/ and include/geardyn/<module>/ and
fails, naming the files, when
  - the folder dependency graph has a cycle (e.g. config/ -> io/ -> config/), or
  - io/ (file formats) includes config/ or analysis/, or a folder below config/ includes config/
    or analysis/ (the machine and its solvers do not know how a file spells them), or
  - a file of src/, include/, apps/ or python/ has more than 600 lines, or
  - a folder (src/<module> with include/geardyn/<module>) holds more than 21 % of the library's
    lines (the rule is "~20 %"; past 21 % the folder is split by concern).
Usage: check_layers.py SOURCE_DIR
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"geardyn/([a-z_]+)/', re.M)
TOP = {"config", "analysis"}  # read files and run analyses: only apps/python include them


def module_graph(root):
    edges = {}
    for base in (root / "src", root / "include" / "geardyn"):
        for path in base.rglob("*"):
            if path.suffix not in (".h", ".cpp") or not path.is_file():
                continue
            rel = path.relative_to(base).parts
            if len(rel) < 2:
                continue  # top-level files (error.h, units.h, did_you_mean.h) depend on nothing
            module = rel[0]
            for target in INCLUDE.findall(path.read_text(encoding="utf-8")):
                if target != module and target != "detail":
                    edges.setdefault((module, target), []).append(str(path.relative_to(root)))
    return edges


def find_cycle(edges):
    graph = {}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
    state = {}

    def visit(node, stack):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt, stack)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node, [])
            if found:
                return found
    return None


MAX_FILE_LINES = 600
MAX_FOLDER_SHARE = 0.21


def size_problems(root):
    problems, per_module, total = [], {}, 0
    for base in ("src", "include", "apps", "python"):
        for path in (root / base).rglob("*"):
            if path.suffix not in (".h", ".cpp", ".py") or not path.is_file():
                continue
            lines = path.read_text(encoding="utf-8").count("\n")
            if lines > MAX_FILE_LINES:
                problems.append(f"{path.relative_to(root)}: {lines} lines (at most {MAX_FILE_LINES})")
            if base in ("src", "include") and path.suffix != ".py":
                rel = path.relative_to(root / base).parts
                if base == "include":
                    rel = rel[1:]
                total += lines
                if len(rel) >= 2:
                    per_module[rel[0]] = per_module.get(rel[0], 0) + lines
    for module, lines in sorted(per_module.items(), key=lambda kv: -kv[1]):
        if lines > MAX_FOLDER_SHARE * total:
            problems.append(f"{module}/: {lines} of {total} lines = {100 * lines / total:.1f} % "
                            f"(at most {100 * MAX_FOLDER_SHARE:.0f} %)")
    shares = ", ".join(f"{m} {100 * n / total:.1f} %" for m, n in
                       sorted(per_module.items(), key=lambda kv: -kv[1])[:3])
    return problems, shares


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    edges = module_graph(root)
    problems = []
    for (a, b), files in sorted(edges.items()):
        if b in TOP and a not in TOP:
            problems.append(f"{a}/ includes {b}/ (in {', '.join(sorted(set(files))[:3])})")
        if a == "config" and b == "analysis":
            problems.append(f"config/ includes analysis/ (in {', '.join(sorted(set(files))[:3])})")
    cycle = find_cycle(edges)
    if cycle:
        hops = []
        for a, b in zip(cycle, cycle[1:]):
            hops.append(f"{a}/ -> {b}/ ({sorted(set(edges[(a, b)]))[0]})")
        problems.append("folder cycle: " + ", ".join(hops))
    sizes, shares = size_problems(root)
    problems += sizes
    if problems:
        print("layout rules broken:\n  " + "\n  ".join(problems))
        return 1
    print(f"{len(edges)} folder dependencies, no cycle; no file over {MAX_FILE_LINES} lines; "
          f"largest folders: {shares}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

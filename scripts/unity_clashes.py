#!/usr/bin/env python3
"""List names that two files of one unity group would both define at file scope (issue 34).

    scripts/unity_clashes.py FILE...            the given files as one group
    scripts/unity_clashes.py --groups BUILD     each unity group of a configured build folder

A unity build compiles several .cpp files as one translation unit, so what each file keeps to
itself — names in an unnamed namespace, `static` functions and variables, classes and test
fixtures at namespace scope, `using` aliases — meets the other files' names. A redefinition is a
compile error, which is the safe outcome; this script finds them before the compiler does, and
also names *overloads* (the same function name with different parameters in two files), which
compile and could silently change which function a call picks. Heuristic (a brace-depth scan of
the source without comments and strings), meant to be read, not to gate the build.
"""
import argparse
import collections
import json
import pathlib
import re
import sys

DECLS = (  # (kind, pattern): the name is the pattern's first group
    ("type", re.compile(r"\b(?:struct|class|enum(?:\s+class)?|union)\s+(\w+)\s*(?:final\s*)?[:{]")),
    ("alias", re.compile(r"\busing\s+(\w+)\s*=[^;]*;")),
    ("variable", re.compile(r"\b(\w+)\s*(?:\[[^\]]*\])?\s*(?:=|\{)[^;{]*;")),
    ("function", re.compile(r"\b(\w+)\s*\([^;{}]*\)\s*(?:const\s*)?(?:noexcept\s*)?"
                            r"(?:->\s*[\w:<>, ]+)?\s*\{")),
)
KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "catch", "namespace", "operator",
            "TEST", "TEST_F", "TEST_P", "TYPED_TEST", "INSTANTIATE_TEST_SUITE_P", "decltype",
            "static_assert", "alignas", "requires", "default", "delete", "const", "constexpr"}


def strip(text):
    text = re.sub(r"//[^\n]*", "", text)
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r'R"(\w*)\(.*?\)\1"', '""', text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)
    text = re.sub(r"'(?:\\.|[^'\\\n])'", "''", text)
    return re.sub(r"^\s*#[^\n]*", "", text, flags=re.M)


def file_scope_text(text):
    """The text a file keeps to itself: at global scope, inside an unnamed namespace, and the
    `static` declarations of named namespaces; bodies of functions and classes cut out."""
    out, stack, i = [], [], 0  # stack: "anon", "named" or "body"
    ns_open = re.compile(r"\bnamespace\s*([\w:]*)\s*\{")
    while i < len(text):
        at_scope = "body" not in stack
        if at_scope:
            m = ns_open.match(text, i)
            if m:
                stack.append("named" if m.group(1) else "anon")
                out.append(" ; ")
                i = m.end()
                continue
        private = "anon" in stack or "named" not in stack
        c = text[i]
        if c == "{":
            if at_scope:
                out.append("{")
            stack.append("body")
        elif c == "}":
            kind = stack.pop() if stack else "named"
            if "body" not in stack:
                out.append("} ;" if kind == "body" else " ; ")
        elif at_scope:
            if private:
                out.append(c)
            elif text.startswith("static ", i) and not text[i - 1:i].isalnum():
                j = text.find(";", i)
                k = text.find("{", i)
                end = min(x for x in (j, k) if x >= 0) if max(j, k) >= 0 else len(text)
                out.append(text[i:end])
                i = end
                continue
            else:
                out.append(" " if c != ";" else ";")
        i += 1
    return "".join(out)


def names(path):
    """{name: {(kind, declaration)}} of what the file keeps to itself, and its macros."""
    raw = pathlib.Path(path).read_text(encoding="utf-8", errors="replace")
    text = file_scope_text(strip(raw))
    found = collections.defaultdict(set)
    for kind, pattern in DECLS:
        for m in pattern.finditer(text):
            name = m.group(1)
            if name in KEYWORDS or name.startswith("_"):
                continue
            found[name].add((kind, re.sub(r"\s+", " ", m.group(0)).strip()[:100]))
    for m in re.finditer(r"\bTEST(?:_F|_P)?\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)", text):
        found[f"{m.group(1)}.{m.group(2)}"].add(("test", "TEST"))
    for m in re.finditer(r"^\s*#\s*define\s+(\w+)", raw, flags=re.M):
        found[m.group(1)].add(("macro", m.group(0).strip()))
    return found


def silent(where):
    """True when the files' declarations of one name would compile together and differ: an
    overload set (a call may pick the other file's function) or a macro defined twice (a
    warning, the second definition wins). Redefinitions of a type, variable or alias are compile
    errors; identical aliases are harmless."""
    kinds = collections.Counter(kind for _, decls in where for kind, _ in decls)
    signatures = {decl for _, decls in where for kind, decl in decls if kind in ("function", "macro")}
    return (kinds["function"] > 1 or kinds["macro"] > 1) and len(signatures) > 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*")
    parser.add_argument("--groups", help="a build folder: check each unity/*.cxx it generated")
    args = parser.parse_args()
    groups = {"given files": args.files}
    if args.groups:
        # The build's own list (compile_commands.json): a reconfigure leaves old groups' files.
        commands = json.loads((pathlib.Path(args.groups) / "compile_commands.json").read_text())
        groups = {}
        for unity in sorted({c["file"] for c in commands if re.search(r"/unity/\w+\.cxx$",
                                                                     c["file"])}):
            here = pathlib.Path(unity).parent  # cmake/unity_groups.cmake: paths relative to it
            groups[unity] = [str((here / f).resolve()) for f in
                             re.findall(r'#include "([^"]+)"', pathlib.Path(unity).read_text())]
    clashes, silent_clashes = 0, 0
    for group, files in groups.items():
        owners = collections.defaultdict(list)
        for f in files:
            for name, decls in names(f).items():
                owners[name].append((f, decls))
        for name, where in sorted(owners.items()):
            if len(where) > 1:
                clashes += 1
                quiet = silent(where)
                silent_clashes += quiet
                print(f"{group}: {name}{'  <- would compile: rename one' if quiet else ''}")
                for f, decls in where:
                    print(f"    {f}: {' | '.join(sorted(d for _, d in decls))}")
    print(f"{clashes} name(s) defined at file scope in more than one file of a group, "
          f"{silent_clashes} of them overloads or macros that would compile")
    return 1 if silent_clashes else 0


if __name__ == "__main__":
    sys.exit(main())

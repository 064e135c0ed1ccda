"""The outer surface of a housing's CalculiX deck, for the 3-D view (issue #38): the faces of
its solid elements that belong to one element only, as triangles between corner nodes (a
quadratic element's edge nodes are left out: the view draws the skin, not the curvature).

``outer_surface(deck, length_m)`` returns ``{"positions": [x, y, z, ...] [m], "triangles":
[i, j, k, ...]}`` or None when the deck has no solid elements (a MatrixMarket housing's deck of
nodes and sets only), cannot be read, or its skin has more than ``MAX_TRIANGLES`` triangles
(the report's size budget: 40 000 triangles are about 1.5 MB of text)."""

import pathlib

MAX_TRIANGLES = 40000

# Corner faces per element family (CalculiX CrunchiX User's Manual 2.20, "Three-dimensional
# elements": the node order of C3D4/C3D10 and C3D8/C3D20).
_TET = ((0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3))
_HEX = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
# TYPE -> (nodes an element lists, corner faces)
_TYPES = {"C3D4": (4, _TET), "C3D10": (10, _TET), "C3D8": (8, _HEX), "C3D8R": (8, _HEX),
          "C3D8I": (8, _HEX), "C3D20": (20, _HEX), "C3D20R": (20, _HEX)}


def _option(card, name):
    for part in card.split(",")[1:]:
        key, _, value = part.partition("=")
        if key.strip().upper() == name:
            return value.strip()
    return None


def _read(path, nodes, elements):
    """Reads *NODE and solid *ELEMENT cards of `path` and the files it *INCLUDEs."""
    mode, kind, pending = None, None, []
    with open(path, encoding="utf-8", errors="replace") as handle:
        for raw in handle:
            line = raw.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                card = line.split(",")[0].strip().upper()
                mode, pending = None, []
                if card == "*NODE":
                    mode = "node"
                elif card == "*ELEMENT":
                    kind = _TYPES.get((_option(line, "TYPE") or "").upper())
                    mode = "element" if kind else None
                elif card == "*INCLUDE":
                    included = _option(line, "INPUT")
                    if included:
                        _read(pathlib.Path(path).parent / included, nodes, elements)
                continue
            fields = [f for f in line.split(",") if f.strip()]
            if mode == "node" and len(fields) >= 4:
                nodes[int(fields[0])] = tuple(float(v) for v in fields[1:4])
            elif mode == "element":
                pending += [int(f) for f in fields]
                if len(pending) >= 1 + kind[0]:
                    elements.append((pending[1:1 + kind[0]], kind[1]))
                    pending = []


def outer_surface(deck, length_m=1.0):
    """The deck's outer faces as triangles, coordinates × `length_m` (metres per deck unit)."""
    nodes, elements = {}, []
    try:
        _read(deck, nodes, elements)
    except (OSError, ValueError):
        return None
    faces = {}
    for corners, family in elements:
        for face in family:
            ids = tuple(corners[k] for k in face)
            key = frozenset(ids)
            faces[key] = None if key in faces else ids
    outer = [ids for ids in faces.values() if ids is not None]
    triangles = []
    for ids in outer:
        triangles.append(ids[:3])
        if len(ids) == 4:
            triangles.append((ids[0], ids[2], ids[3]))
    if not triangles or len(triangles) > MAX_TRIANGLES:
        return None
    index, positions, flat = {}, [], []
    for tri in triangles:
        for n in tri:
            if n not in index:
                if n not in nodes:
                    return None
                index[n] = len(index)
                positions += [round(v * length_m, 5) for v in nodes[n]]
            flat.append(index[n])
    return {"positions": positions, "triangles": flat}

#!/usr/bin/python3
"""A cast box housing for the two-stage reducer (examples/gearboxes/two_stage_reducer.toml),
meshed by gmsh with second-order tetrahedra and written as a CalculiX deck (issue #37).

    /usr/bin/python3 examples/housing_box_gmsh.py OUT.inp [--size 0.012]

The gearbox's shaft axes run along x: input at (y, z) = (0, 0), intermediate at (0.111, 0) (the
first stage's centre distance, position angle 0), output at 0.144 m from it at -30 deg. The box
(SI units: m, kg, s) has 12 mm steel walls, a bore for each bearing in the two end walls and
bolted feet on its underside (*BOUNDARY). Node sets: one per bearing seat, named as the gearbox's
bearings in upper case (INPUT_A on the x = 0 wall, INPUT_B on the far wall, ...), FEET, and the
response points TOP (the cover's middle) and SIDE (the middle of the side wall, y = max).

The deck is written by this script from gmsh's mesh (not by gmsh's own .inp export, which would
also write the named surfaces' triangles as elements): C3D10 with gmsh's edge nodes 8 and 9
swapped into Abaqus' order (Abaqus: edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4; gmsh's tetrahedron of
order 2: 0-1, 1-2, 2-0, 3-0, 3-2, 3-1).
"""
import argparse
import math

import gmsh

WALL = 0.012          # m
LENGTH = 0.38         # m, along the shafts (x from -0.015 to 0.365)
X0 = -0.015
AXES = {"INPUT": (0.0, 0.0, 0.031),           # (y, z, bore radius) [m]
        "INTERMEDIATE": (0.111, 0.0, 0.036),
        "OUTPUT": (0.111 + 0.144 * math.cos(math.radians(30.0)),
                   -0.144 * math.sin(math.radians(30.0)), 0.045)}
Y0, Y1 = -0.075, 0.315  # box extent [m]
Z0, Z1 = -0.150, 0.085


def build(size):
    occ = gmsh.model.occ
    outer = occ.addBox(X0, Y0, Z0, LENGTH, Y1 - Y0, Z1 - Z0)
    inner = occ.addBox(X0 + WALL, Y0 + WALL, Z0 + WALL, LENGTH - 2 * WALL, Y1 - Y0 - 2 * WALL,
                       Z1 - Z0 - 2 * WALL)
    bores = [(3, occ.addCylinder(X0 - 0.01, y, z, LENGTH + 0.02, 0, 0, r))
             for y, z, r in AXES.values()]
    feet = [(3, occ.addBox(X0 + dx, y, Z0 - 0.015, 0.06, 0.05, 0.015))
            for dx in (0.0, LENGTH - 0.06) for y in (Y0, Y1 - 0.05)]
    shell, _ = occ.cut([(3, outer)], [(3, inner)])
    body, _ = occ.fuse(shell, feet)
    housing, _ = occ.cut(body, bores)
    occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [v[1] for v in housing], 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", size)
    gmsh.option.setNumber("Mesh.MeshSizeMin", size / 3)
    gmsh.option.setNumber("Mesh.ElementOrder", 2)
    gmsh.option.setNumber("Mesh.SecondOrderLinear", 1)  # straight edges: no curved-tet checks
    gmsh.model.mesh.generate(3)


def node_coordinates():
    tags, coords, _ = gmsh.model.mesh.getNodes()
    return {int(t): coords[3 * i:3 * i + 3] for i, t in enumerate(tags)}


def nodes_where(coords, test):
    return sorted(t for t, x in coords.items() if test(x))


def write_deck(path, coords):
    types, tags, nodes = gmsh.model.mesh.getElements(3)
    tets = [(t, n) for ty, t, n in zip(types, tags, nodes) if ty == 11]  # 10-node tetrahedra
    order = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]
    tol = 1e-6
    sets = {}
    for name, (y, z, r) in AXES.items():
        for side, x_wall in (("A", X0), ("B", X0 + LENGTH)):
            sets[f"{name}_{side}"] = nodes_where(
                coords, lambda p, y=y, z=z, r=r, xw=x_wall: abs(math.hypot(p[1] - y, p[2] - z) - r)
                < tol and abs(p[0] - xw) < WALL + tol)
    sets["FEET"] = nodes_where(coords, lambda p: abs(p[2] - (Z0 - 0.015)) < tol)
    mid_top = (X0 + LENGTH / 2, 0.5 * (Y0 + Y1), Z1)
    mid_side = (X0 + LENGTH / 2, Y1, 0.5 * (Z0 + Z1))
    for name, target in (("TOP", mid_top), ("SIDE", mid_side)):
        sets[name] = [min(coords, key=lambda t: sum((coords[t][k] - target[k]) ** 2
                                                     for k in range(3)))]
    with open(path, "w") as out:
        out.write("** Box housing of the two-stage reducer (examples/housing_box_gmsh.py), SI\n")
        out.write("*NODE\n")
        for t in sorted(coords):
            x = coords[t]
            out.write(f"{t}, {x[0]:.9g}, {x[1]:.9g}, {x[2]:.9g}\n")
        out.write("*ELEMENT, TYPE=C3D10, ELSET=HOUSING\n")
        count = 0
        for elem_tags, elem_nodes in tets:
            for i, e in enumerate(elem_tags):
                n = elem_nodes[10 * i:10 * i + 10]
                count += 1
                out.write(f"{count}, " + ", ".join(str(int(n[k])) for k in order) + "\n")
        for name, members in sets.items():
            if not members:
                raise SystemExit(f"housing_box_gmsh: node set {name} is empty")
            out.write(f"*NSET, NSET={name}\n")
            for i in range(0, len(members), 8):
                out.write(", ".join(str(m) for m in members[i:i + 8]) + "\n")
        out.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n")
        out.write("*SOLID SECTION, ELSET=HOUSING, MATERIAL=STEEL\n")
        out.write("*BOUNDARY\nFEET, 1, 3\n")
    return count, {k: len(v) for k, v in sets.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--size", type=float, default=0.012, help="largest element edge [m]")
    args = parser.parse_args()
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.model.add("housing")
        build(args.size)
        coords = node_coordinates()
        elements, sets = write_deck(args.out, coords)
    finally:
        gmsh.finalize()
    print(f"{args.out}: {len(coords)} nodes ({3 * len(coords)} DOFs), {elements} C3D10; sets "
          + ", ".join(f"{k} {v}" for k, v in sets.items()))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A structured hexahedral box [0, LX] x [0, L] x [0, L] in Gmsh 2.2 ASCII format, which the
code_saturne 6.0 preprocessor reads. Physical groups (6.0.2 keeps only their numbers as group
names for 2.2 files): 1 inlet (x = 0), 2 outlet (x = LX), 3 wall (y = 0, y = L, z = 0, z = L),
4 fluid. Boundary quads are oriented outwards. Standard library only.

Usage: make_mesh.py OUT.msh [--lx LX] [--nx NX] [--l L] [--n N]   (defaults 0.1 m, 10 cells)
"""
import argparse


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--lx", type=float, default=0.1)
    ap.add_argument("--nx", type=int, default=10)
    ap.add_argument("--l", type=float, default=0.1)
    ap.add_argument("--n", type=int, default=10)
    a = ap.parse_args()
    nx, n = a.nx, a.n

    def nid(i, j, k):  # 1-based node id
        return 1 + i + (nx + 1) * (j + (n + 1) * k)

    def x(i):
        return repr(a.lx * i / nx)  # exact grid coordinates, no accumulated round-off

    def yz(j):
        return repr(a.l * j / n)

    nodes = [(nid(i, j, k), x(i), yz(j), yz(k))
             for k in range(n + 1) for j in range(n + 1) for i in range(nx + 1)]
    elts = []  # (type, physical, elementary, nodes)
    for k in range(n):
        for j in range(n):
            elts.append((3, 1, 1, [nid(0, j, k), nid(0, j, k + 1), nid(0, j + 1, k + 1), nid(0, j + 1, k)]))
            elts.append((3, 2, 2, [nid(nx, j, k), nid(nx, j + 1, k), nid(nx, j + 1, k + 1), nid(nx, j, k + 1)]))
    for k in range(n):
        for i in range(nx):
            elts.append((3, 3, 3, [nid(i, 0, k), nid(i + 1, 0, k), nid(i + 1, 0, k + 1), nid(i, 0, k + 1)]))
            elts.append((3, 3, 4, [nid(i, n, k), nid(i, n, k + 1), nid(i + 1, n, k + 1), nid(i + 1, n, k)]))
    for j in range(n):
        for i in range(nx):
            elts.append((3, 3, 5, [nid(i, j, 0), nid(i, j + 1, 0), nid(i + 1, j + 1, 0), nid(i + 1, j, 0)]))
            elts.append((3, 3, 6, [nid(i, j, n), nid(i + 1, j, n), nid(i + 1, j + 1, n), nid(i, j + 1, n)]))
    for k in range(n):
        for j in range(n):
            for i in range(nx):
                elts.append((5, 4, 7, [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                       nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                                       nid(i, j + 1, k + 1)]))
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat",
             "$PhysicalNames", "4", '2 1 "inlet"', '2 2 "outlet"', '2 3 "wall"', '3 4 "fluid"',
             "$EndPhysicalNames", "$Nodes", str(len(nodes))]
    lines += ["%d %s %s %s" % nd for nd in nodes]
    lines += ["$EndNodes", "$Elements", str(len(elts))]
    lines += ["%d %d 2 %d %d %s" % (e, t, p, g, " ".join(map(str, nds)))
              for e, (t, p, g, nds) in enumerate(elts, start=1)]
    lines.append("$EndElements")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

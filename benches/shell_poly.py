#!/usr/bin/env python3
"""Writes the PLC of a shell for TetGen: the boundary triangles of a tetrakit shell mesh
(X.node/X.ele, the triangulations of both surfaces) as X.poly, with a hole at the given
point inside the inner polytope. Usage: shell_poly.py X.ele OUT.poly HX HY HZ"""
import sys
from collections import Counter

ele, out, hole = sys.argv[1], sys.argv[2], sys.argv[3:6]
rows = lambda path: [l.split() for l in open(path) if l.split() and not l.startswith("#")]
node = rows(ele[:-4] + ".node")
tets = [list(map(int, r[1:5])) for r in rows(ele)[1:]]
faces = Counter()
first = {}
for a, b, c, d in tets:
    for f in ((a, b, c), (a, b, d), (a, c, d), (b, c, d)):
        k = tuple(sorted(f))
        faces[k] += 1
        first[k] = f
boundary = [first[k] for k, n in faces.items() if n == 1]
with open(out, "w") as w:
    w.write(node[0][0] + " 3 0 0\n")
    for r in node[1:]:
        w.write(" ".join(r[:4]) + "\n")
    w.write(f"{len(boundary)} 0\n")
    for f in boundary:
        w.write(f"1\n3 {f[0]} {f[1]} {f[2]}\n")
    w.write(f"1\n1 {hole[0]} {hole[1]} {hole[2]}\n")

#!/usr/bin/env python3
"""Writes the thin twisted shell of BENCHMARKS.md chapter 4: OUTER.xyz a prism over a
regular 200-gon (z = ±1), INNER.xyz the same prism scaled by 0.999 with its bottom turned
by -1 degree and its top by +1 degree. Usage: twisted_shell.py OUTER.xyz INNER.xyz"""
import math
import sys

K = 200


def prism(scale, twist):
    pts = []
    for z, turn in ((-1.0, -twist), (1.0, twist)):
        for j in range(K):
            a = 2 * math.pi * j / K + math.radians(turn)
            pts.append((scale * math.cos(a), scale * math.sin(a), scale * z))
    return pts


for path, pts in ((sys.argv[1], prism(1.0, 0.0)), (sys.argv[2], prism(0.999, 1.0))):
    with open(path, "w") as f:
        f.writelines("%r %r %r\n" % p for p in pts)

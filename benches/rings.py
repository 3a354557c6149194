#!/usr/bin/env python3
"""Sites of a face with ring holes, for the exact stage of `tetrakit mwt`.

Usage: rings.py N K M SEED SIZE OUT

A regular N-gon of radius 1 and K small regular M-gons of radius SIZE (random
centres within radius 0.8, at least 6 SIZE apart, random rotation). The
LMT-skeleton fixes the polygon's sides and the small rings and little between
them, so the exact stage gets one face with K ring holes (BENCHMARKS.md, "Faces
with ring holes").
"""
import math
import random
import sys

n, k, m, seed, size = (int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]),
                       int(sys.argv[4]), float(sys.argv[5]))
random.seed(seed)
pts = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
centres = []
while len(centres) < k:
    r, a = 0.8 * math.sqrt(random.random()), random.random() * 6.283
    c = (r * math.cos(a), r * math.sin(a))
    if all(math.hypot(c[0] - d[0], c[1] - d[1]) > 6 * size for d in centres):
        centres.append(c)
for c in centres:
    t = random.random()
    pts.extend((c[0] + size * math.cos(t + 2 * math.pi * j / m),
                c[1] + size * math.sin(t + 2 * math.pi * j / m)) for j in range(m))
with open(sys.argv[6], "w") as out:
    out.write("".join(f"{x!r} {y!r}\n" for x, y in pts))

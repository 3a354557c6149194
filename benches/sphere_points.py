"""n distinct integer points near a sphere of radius 1000 (convex position), seeded by n.

Usage: python3 benches/sphere_points.py N OUT   writes OUT.xyz and OUT.topcom (TOPCOM's
homogeneous point list, for points2mintriang).
"""
import math
import random
import sys

n, out = int(sys.argv[1]), sys.argv[2]
r = random.Random(n)
pts = []
while len(pts) < n:
    x = [r.gauss(0, 1) for _ in range(3)]
    l = math.sqrt(sum(c * c for c in x))
    q = [round(c / l * 1000) for c in x]
    if q not in pts:
        pts.append(q)
open(out + '.xyz', 'w').write('\n'.join(' '.join(map(str, q)) for q in pts) + '\n')
open(out + '.topcom', 'w').write('[' + ','.join('[' + ','.join(map(str, q + [1])) + ']' for q in pts) + ']\n[]\n')

#!/usr/bin/env python3
"""Writes one shell of the chapter 4 families that are hard for cap removal or touch:
OUTER.xyz and INNER.xyz with about N vertices in all.

  twisted   two K-gon prisms, the inner one scaled 0.999 with its ends turned by -/+1 degree
            (thin, twisted: no vertex of Q sees far)
  coaxial   two aligned K-gon prisms, the inner one 0.95 in radius and height (parallel
            facets, a small gap)
  arcs      two slightly bent perpendicular arcs (z = +1 and z = -1) around a small sphere
            (every tip sees a long chain of the other arc: every surface triangle spans
            the shell)
  lattice   the integer points on a sphere x^2 + y^2 + z^2 = R^2, Q = P/2 (cospherical,
            many coplanar facets, Q's facets parallel to P's)
  circles   the cube [-1, 1]^3 and, on each face, a circle of points: Q is their hull,
            every vertex of Q on a facet of P
  dome      a dome over the square floor z = 0 and a smaller one on the same floor: Q's
            bottom facet inside P's
  corner    a box with Q in its corner: an eighth of a ball about the box's corner, its
            three flat facets (quarter disks, their arcs of points exact on the planes)
            inside three facets of P, Q's vertex at the corner shared (boxes in boxes,
            with every vertex but P's eight on Q)
Coordinates are exact dyadic or integer values where the family needs exact contact.
Usage: shell_families.py FAMILY N OUTER.xyz INNER.xyz"""
import math
import random
import sys


def prism(k, scale, height, twist):
    pts = []
    for z, turn in ((-height, -twist), (height, twist)):
        for j in range(k):
            a = 2 * math.pi * j / k + math.radians(turn)
            pts.append((scale * math.cos(a), scale * math.sin(a), z))
    return pts


def sphere(m, r, rng, upper=False):
    pts = []
    while len(pts) < m:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in p))
        if 1e-3 < n <= 1 and (not upper or p[2] > 0.05 * n):
            pts.append(tuple(r * x / n for x in p))
    return pts


def lattice(n):
    # About 6 sqrt(r2) integer points lie on x^2 + y^2 + z^2 = r2 (none when r2 = 7 mod 8).
    r2 = max(2, int((n / 24.0) ** 2))
    while True:
        r = math.isqrt(r2)
        pts = []
        for x in range(-r, r + 1):
            for y in range(-r, r + 1):
                rest = r2 - x * x - y * y
                if rest >= 0:
                    z = math.isqrt(rest)
                    if z * z == rest:
                        pts.extend({(x, y, z), (x, y, -z)})
        if 2 * len(pts) >= n:
            # Even coordinates only, so that Q = P/2 is on the integer grid too.
            pts = [(2 * x, 2 * y, 2 * z) for x, y, z in pts]
            return pts, [(x // 2, y // 2, z // 2) for x, y, z in pts]
        r2 = max(r2 + 1, int(r2 * 1.05))


def circles(n):
    k = max(3, (n - 8) // 6)
    outer = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    inner = []
    for axis in range(3):
        for side in (-1.0, 1.0):
            for j in range(k):
                a = 2 * math.pi * (j + 0.5) / k
                p = [0.5 * math.cos(a), 0.5 * math.sin(a)]
                p.insert(axis, side)
                inner.append(tuple(p))
    return outer, inner


def dome(n, rng):
    m = n // 2
    floor = [(-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)]
    outer = floor + [p for p in sphere(m, math.sqrt(2.0), rng, upper=True)]
    ring = max(3, m // 8)
    inner = [(0.5 * math.cos(2 * math.pi * j / ring), 0.5 * math.sin(2 * math.pi * j / ring), 0.0)
             for j in range(ring)]
    inner += sphere(m - ring, 0.5, rng, upper=True)
    return outer, inner


def corner(n, rng):
    outer = [(x, y, z) for x in (0.0, 2.0) for y in (0.0, 2.0) for z in (0.0, 2.0)]
    arc = max(3, n // 16)
    inner = [(0.0, 0.0, 0.0)]
    for axis in range(3):
        for j in range(1, arc + 1):
            a = 0.5 * math.pi * j / (arc + 1)
            p = [math.cos(a), math.sin(a)]
            p.insert(axis, 0.0)
            inner.append(tuple(p))
    while len(inner) < n - len(outer):
        p = [abs(rng.gauss(0, 1)) for _ in range(3)]
        r = math.sqrt(sum(x * x for x in p))
        if r > 1e-3 and min(p) > 1e-3 * r:
            inner.append(tuple(x / r for x in p))
    return outer, inner


def arcs(n):
    m = n // 4
    eps = 0.05
    outer = [(t, 0.0, 1.0 - eps * t * t) for t in (2.0 * j / (m - 1) - 1.0 for j in range(m))]
    outer += [(0.0, t, -1.0 + eps * t * t) for t in (2.0 * j / (m - 1) - 1.0 for j in range(m))]
    inner = sphere(n - 2 * m, 0.1, random.Random(3))
    return outer, inner


def family(name, n):
    rng = random.Random(1)
    k = max(3, n // 4)
    if name == "twisted":
        return prism(k, 1.0, 1.0, 0.0), prism(k, 0.999, 0.999, 1.0)
    if name == "coaxial":
        return prism(k, 1.0, 1.0, 0.0), prism(k, 0.95, 0.95, 0.0)
    if name == "arcs":
        return arcs(n)
    if name == "lattice":
        return lattice(n)
    if name == "circles":
        return circles(n)
    if name == "dome":
        return dome(n, rng)
    if name == "corner":
        return corner(n, rng)
    sys.exit("unknown family %r" % name)


def main():
    name, n, outer_path, inner_path = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
    outer, inner = family(name, n)
    for path, pts in ((outer_path, outer), (inner_path, inner)):
        with open(path, "w") as f:
            f.writelines("%r %r %r\n" % tuple(float(x) for x in p) for p in pts)


if __name__ == "__main__":
    main()

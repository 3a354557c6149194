#!/usr/bin/env python3
"""Draws BENCHMARKS.md's chapter 4 chart: tetrahedra per vertex against n (log scale) for
cap removal before and after the flips, bigcaps after the flips and TetGen -pQ, on nested
spheres (solid) and Bern disks (dashed), beside the 9n - 6 bound. Reads the table that
benches/shell.sh prints. Usage: python3 benches/shell_chart.py TABLE.md OUT.svg"""
import math
import sys

rows = []
for line in open(sys.argv[1]):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) < 9 or not cells[1].isdigit():
        continue
    family = "spheres" if cells[0] == "spheres" else "Bern disks"
    n = int(cells[1])
    rows.append((family, n, float(cells[2]), float(cells[3]), float(cells[6]), float(cells[8])))

W, H, L, R, T, B = 640, 400, 60, 170, 20, 50
ns = [r[1] for r in rows]
x0, x1 = math.log10(min(ns)) - 0.1, math.log10(max(ns)) + 0.1
y1 = 11.0
X = lambda n: L + (math.log10(n) - x0) / (x1 - x0) * (W - L - R)
Y = lambda v: T + (1 - v / y1) * (H - T - B)
series = [
    ("cap, removals only", 2, "#d62728"),
    ("cap, after flips", 3, "#1f77b4"),
    ("bigcap, after flips", 4, "#2ca02c"),
    ("TetGen -pQ", 5, "#7f7f7f"),
]
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
for v in range(0, 12, 2):
    out.append(f'<line x1="{L}" y1="{Y(v):.1f}" x2="{W - R}" y2="{Y(v):.1f}" stroke="#eee"/>')
    out.append(f'<text x="{L - 8}" y="{Y(v) + 4:.1f}" text-anchor="end">{v}</text>')
for e in range(math.ceil(x0), math.floor(x1) + 1):
    out.append(f'<text x="{X(10 ** e):.1f}" y="{H - B + 18}" text-anchor="middle">10^{e}</text>')
out.append(f'<line x1="{L}" y1="{Y(9):.1f}" x2="{W - R}" y2="{Y(9):.1f}" stroke="black" stroke-dasharray="2,3"/>')
out.append(f'<text x="{L + 6}" y="{Y(9) - 6:.1f}">9n − 6 (the bound)</text>')
out.append(f'<text x="{(L + W - R) / 2}" y="{H - 12}" text-anchor="middle">n (vertices of both polytopes)</text>')
out.append(f'<text x="14" y="{(T + H - B) / 2}" transform="rotate(-90 14 {(T + H - B) / 2})" text-anchor="middle">tetrahedra per vertex</text>')
for k, (name, col, colour) in enumerate(series):
    for family, dash in (("spheres", ""), ("Bern disks", ' stroke-dasharray="6,4"')):
        pts = [(X(r[1]), Y(r[col])) for r in rows if r[0] == family]
        if not pts:
            continue
        path = " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        out.extend(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3" fill="{colour}"/>' for x, y in pts)
    out.append(f'<line x1="{W - R + 6}" y1="{T + 100 + 18 * k}" x2="{W - R + 26}" y2="{T + 100 + 18 * k}" stroke="{colour}" stroke-width="2"/>')
    out.append(f'<text x="{W - R + 30}" y="{T + 104 + 18 * k}">{name}</text>')
out.append(f'<text x="{W - R + 6}" y="{T + 190}">solid: nested spheres</text>')
out.append(f'<text x="{W - R + 6}" y="{T + 206}">dashed: Bern disks</text>')
out.append("</svg>")
open(sys.argv[2], "w").write("\n".join(out) + "\n")

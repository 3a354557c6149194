#!/usr/bin/env python3
"""Reproduces the chapter 6 part of BENCHMARKS.md.

  python3 benches/ch6.py flips         the flip graph against TOPCOM, side by side, and the
                                       search for isolated tetrahedralizations: for each
                                       family, n = 6, 7, ... until a set takes over 60 s
  python3 benches/ch6.py hamiltonian   `tetrahedralize --hamiltonian` on random convex
                                       polytopes of 5 to 100 vertices (spheres, cylinders,
                                       lattice hulls with many coplanar facets): every one
                                       where no path is found, and the cost over an
                                       ordinary cone
  python3 benches/ch6.py hamiltonian-large
                                       the same past 100 vertices (spheres of 300 to
                                       3000 points, one each, a 300 s limit; SIZES),
                                       and
                                       Kleetopes, where many cones have no path
  python3 benches/ch6.py triangulated  convex polyhedra with triangulated facets: how
                                       often NO happens, by family and size; the smallest
                                       NOs; which witnesses the NOs have

Needs `cargo build --release` and, for `flips`, TOPCOM (Debian `topcom`). Environment:
SEEDS (sets per family and size, default 5 for flips and 200 for triangulated; polytopes
per family for hamiltonian, default 3334), LIMIT
(seconds per set, default 60), FAMILIES (space separated).
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TK = ROOT / "target" / "release" / "tetrakit"
WORK = Path(tempfile.mkdtemp(prefix="tetrakit-ch6-"))


def tk(*args, code=(0, 1, 3)):
    out = subprocess.run([str(TK), *map(str, args)], capture_output=True, text=True)
    if out.returncode not in code:
        raise SystemExit(f"tetrakit {' '.join(map(str, args))}: exit {out.returncode}: {out.stderr}")
    return out


def topcom(points, prog, limit):
    """TOPCOM's count on the same points (exact rationals), and its seconds; None past
    the limit."""
    rows = ",".join("[" + ",".join(str(Fraction(x)) for x in p) + ",1]" for p in points)
    start = time.perf_counter()
    try:
        out = subprocess.run([prog], input=f"[{rows}]\n", capture_output=True, text=True,
                             timeout=limit)
    except subprocess.TimeoutExpired:
        return None, limit
    return int(out.stdout.strip().splitlines()[-1]), time.perf_counter() - start


def read_points(path):
    return [[float(x) for x in line.split()] for line in path.read_text().split("\n") if line.strip()]


def flips():
    seeds = int(os.environ.get("SEEDS", 5))
    limit = float(os.environ.get("LIMIT", 60))
    families = os.environ.get("FAMILIES", "uniform perturbed-grid cospherical lattice convex").split()
    print(f"# flips: {seeds} sets per family and size, {limit:.0f} s per set")
    print("| family | n | tetrahedralizations (median) | components | min flips | isolated "
          "| tetrakit s | TOPCOM all s | TOPCOM/tetrakit | TOPCOM flips s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for fam in families:
        n = 6
        while True:
            counts, comps, mins, iso, ours, theirs, walks = [], set(), [], 0, [], [], []
            over = False
            for seed in range(1, seeds + 1):
                f = WORK / f"{fam}-{n}-{seed}.xyz"
                tk("generate", "points3d", "--dist", fam, "--n", n, "--seed", seed, "-o", f, code=(0,))
                start = time.perf_counter()
                out = tk("flips", f, "--json", "--time-limit", limit, "--limit", 10**8,
                         code=(0, 1, 2, 3))
                took = time.perf_counter() - start
                if out.returncode == 2:  # a flat set (cospherical, small n)
                    continue
                g = json.loads(out.stdout)
                if g["verdict"] == "undecided":
                    over = True
                    break
                ours.append(took)
                counts.append(g["tetrahedralizations"])
                comps.add(g["components"])
                mins.append(g["min_flips"])
                iso += len(g["isolated"])
                pts = read_points(f)
                total, t_all = topcom(pts, "topcom-points2nallfinetriangs", 4 * limit)
                reached, t_walk = topcom(pts, "topcom-points2nfinetriangs", 4 * limit)
                if total is not None and total != g["tetrahedralizations"]:
                    print(f"MISMATCH {f}: TOPCOM {total}, tetrakit {g['tetrahedralizations']}")
                if reached is not None and reached != g["tetrahedralizations"]:
                    print(f"DISCONNECTED? {f}: TOPCOM's flips reach {reached} of {total}")
                theirs.append(t_all)
                walks.append(t_walk)
            if over or not ours:
                print(f"| {fam} | {n} | over {limit:.0f} s | | | | | | | |")
                break
            med = statistics.median
            print(f"| {fam} | {n} | {int(med(counts))} | {sorted(comps)} | {min(mins)} | {iso} "
                  f"| {med(ours):.3f} | {med(theirs):.3f} | {med(theirs) / med(ours):.1f} "
                  f"| {med(walks):.3f} |", flush=True)
            n += 1


def one_path(job):
    fam, n, seed = job
    f = WORK / f"h-{fam}-{n}-{seed}.xyz"
    tk("generate", "points3d", "--dist", fam, "--n", n, "--seed", seed, "-o", f, code=(0,))
    start = time.perf_counter()
    o = json.loads(tk("tetrahedralize", f, "--hamiltonian", "--json", "--time-limit", 60).stdout)
    return fam, n, seed, o, time.perf_counter() - start


def hamiltonian():
    from concurrent.futures import ThreadPoolExecutor
    seeds = int(os.environ.get("SEEDS", 3334))
    families = os.environ.get("FAMILIES", "convex cylinder lattice-hull").split()
    jobs = [(fam, 5 + (seed * 37) % 96 if fam != "cylinder" else 6 + (seed * 37) % 95, seed)
            for fam in families for seed in range(1, seeds + 1)]
    print(f"# hamiltonian: {len(jobs)} polytopes, 5 to 100 vertices")
    rows = {}
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        for fam, n, seed, o, took in pool.map(one_path, jobs):
            r = rows.setdefault(fam, {"n": 0, "yes": 0, "extra": [], "ratio": [], "secs": [],
                                      "apexes": [], "failed": []})
            r["n"] += 1
            r["secs"].append(took)
            if o["verdict"] == "yes":
                r["yes"] += 1
                r["extra"].append(o["tetrahedra"] - o["ordinary_tetrahedra"])
                r["ratio"].append(o["tetrahedra"] / o["ordinary_tetrahedra"])
                r["apexes"].append(o["apexes_tried"])
                r.setdefault("refuted", []).append(o["cones_refuted"])
            else:
                r["failed"].append(f"{fam} n={n} seed={seed} ({o['apexes']} eligible apexes)")
    print("| family | polytopes | path found | extra tetrahedra over an ordinary cone (median, max) "
          "| ratio (mean) | apexes tried (median, max) | with a cone refuted | median s | max s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for fam, r in rows.items():
        med = statistics.median
        print(f"| {fam} | {r['n']} | {r['yes']} | {med(r['extra'])}, {max(r['extra'])} "
              f"| {statistics.mean(r['ratio']):.4f} | {med(r['apexes'])}, {max(r['apexes'])} "
              f"| {sum(1 for k in r.get('refuted', []) if k)} "
              f"| {med(r['secs']):.3f} | {max(r['secs']):.3f} |")
        for f in r["failed"]:
            print(f"NO PATH FOUND: {f}")


def kleetope(points, h):
    """The points with one more over each facet's centroid, `h` out along its normal (a
    small `h` keeps every point a vertex); facets found by brute force, in floating point:
    only the input is made this way, tetrakit decides on it exactly."""
    import itertools
    import numpy as np
    P = np.array(points, dtype=float)
    out = [list(p) for p in P]
    for i, j, k in itertools.combinations(range(len(P)), 3):
        nrm = np.cross(P[j] - P[i], P[k] - P[i])
        d = (P - P[i]) @ nrm
        for sign in (1, -1):
            if np.all(sign * d <= 1e-12):
                out.append(list((P[i] + P[j] + P[k]) / 3 + h * sign * nrm / np.linalg.norm(nrm)))
    return out


def hamiltonian_large():
    limit = int(os.environ.get("LIMIT", 300))
    print("| polytope | n | verdict | found by | apexes tried | cones refuted | steps | cuts "
          "| tetrahedra (ordinary cone) | s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    sets = []
    for n in map(int, os.environ.get("SIZES", "300 1000 1500 2000 3000").split()):
        f = WORK / f"sphere-{n}.xyz"
        tk("generate", "points3d", "--dist", "convex", "--n", n, "--seed", 1, "-o", f, code=(0,))
        sets.append(("sphere", f))
    phi = (1 + 5 ** 0.5) / 2
    solids = {
        "tetrahedron": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]],
        "octahedron": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
        "icosahedron": [p for a in (-1, 1) for b in (-phi, phi) for p in ([0, a, b], [a, b, 0], [b, 0, a])],
    }
    for name, solid in solids.items():
        for level, hs in ((1, [0.1]), (2, [0.1, 0.001])):
            pts = solid
            for h in hs:
                pts = kleetope(pts, h)
            f = WORK / f"klee-{name}-{level}.xyz"
            f.write_text("".join(f"{float(x)!r} {float(y)!r} {float(z)!r}\n" for x, y, z in pts))
            sets.append((f"Kleetope{'²' if level == 2 else ''} of the {name}", f))
    for name, f in sets:
        start = time.perf_counter()
        out = tk("tetrahedralize", f, "--hamiltonian", "--json", "--time-limit", limit)
        took = time.perf_counter() - start
        o = json.loads(out.stdout)
        print(f"| {name} | {o['vertices']} | {o['verdict']} | {o['found_by']} | {o['apexes_tried']} "
              f"| {o['cones_refuted']} | {o['steps']} | {o['cuts']} "
              f"| {o['tetrahedra']} ({o['ordinary_tetrahedra']}) | {took:.2f} |", flush=True)


def triangulated():
    seeds = int(os.environ.get("SEEDS", 200))
    cases = [("prism", n, k) for n in (3, 4, 5, 6, 8, 12) for k in (0, 2)]
    cases += [("cube", 0, k) for k in (0, 2, 4, 8, 16)]
    cases += [("lattice", n, 0) for n in (8, 12, 20, 40)]
    print(f"# triangulated: {seeds} polyhedra per row")
    print("| shape | n | facet points | vertices (median) | NO | witnesses of the NOs | median s |")
    print("|---|---|---|---|---|---|---|")
    smallest = {}
    for shape, n, k in cases:
        nos, kinds, sizes, secs = 0, {}, [], []
        for seed in range(1, seeds + 1):
            f = WORK / f"{shape}-{n}-{k}-{seed}.off"
            gen = tk("generate", "convex-triangulated", "--shape", shape, "--n", max(n, 3),
                     "--facet-points", k, "--seed", seed, "-o", f, code=(0, 2))
            if gen.returncode == 2:
                continue
            start = time.perf_counter()
            o = json.loads(tk("tetrahedralize", f, "--json", "--time-limit", 60).stdout)
            secs.append(time.perf_counter() - start)
            sizes.append(o["vertices"])
            if o["verdict"] == "no":
                nos += 1
                kind = o["witness"]["kind"]
                kinds[kind] = kinds.get(kind, 0) + 1
                best = smallest.get(kind)
                if best is None or o["vertices"] < best[0]:
                    smallest[kind] = (o["vertices"], f"{shape} n={n} facet-points={k} seed={seed}")
        if sizes:
            w = ", ".join(f"{k}: {v}" for k, v in sorted(kinds.items())) or "-"
            print(f"| {shape} | {n if shape != 'cube' else '-'} | {k} | {int(statistics.median(sizes))} "
                  f"| {nos} / {len(sizes)} | {w} | {statistics.median(secs):.3f} |", flush=True)
    for kind, (v, where) in sorted(smallest.items()):
        print(f"smallest NO with a {kind} witness: {v} vertices ({where})")


if __name__ == "__main__":
    {"flips": flips, "hamiltonian": hamiltonian, "hamiltonian-large": hamiltonian_large,
     "triangulated": triangulated}[sys.argv[1] if len(sys.argv) > 1 else "flips"]()

#!/usr/bin/env python3
"""The chapter 2 §2.5–2.6 part of BENCHMARKS.md: how large an instance `contains`,
`constrained` and `tetrahedralize` decide within 60 s, with the size of the formula and of
the DRAT proof of each NO, and TetGen -pY on the same polyhedra.

Usage: python3 benches/constrain.py [--quick] [--tetgen-only | --reductions-only]   (run
from the repository root, after `cargo build --release`; TetGen from Debian for the last
two tables; --tetgen-only runs only those, --reductions-only only the Theorem 2.9 and
gadget tables).
"""
import json
import os
import random
import shutil
import subprocess
import sys
import time

TK = "target/release/tetrakit"
WORK = os.environ.get("WORK", "/tmp/tetrakit-bench-constrain")
LIMIT = "60"
QUICK = "--quick" in sys.argv
TETGEN_ONLY = "--tetgen-only" in sys.argv


def run(args):
    """Runs tetrakit; returns its JSON and wall seconds."""
    t = time.perf_counter()
    out = subprocess.run([TK] + args + ["--json"], capture_output=True, text=True)
    secs = time.perf_counter() - t
    if out.returncode == 2:
        raise SystemExit(f"{args}: {out.stderr}")
    return json.loads(out.stdout), secs


def proof_row(v, drat):
    p = v.get("proof")
    if isinstance(p, dict):
        return f"{p['variables']} / {p['clauses']}", f"{os.path.getsize(drat) / 1e3:.1f} kB"
    return "-", "-"


def decide(cmd, path, label, n, m):
    drat = os.path.join(WORK, "p.drat")
    v, secs = run([cmd, path, "--time-limit", LIMIT, "--proof", drat])
    formula, size = proof_row(v, drat)
    print(
        f"| {label} | {n} | {m} | {v['candidates']} | {v['verdict']} ({v['route']}) | "
        f"{formula} | {size} | {secs:.2f} |"
    )
    return v, secs


def random_instance(n, planar, seed, keep=0.75):
    rng = random.Random(seed)
    pts = set()
    while len(pts) < n:
        pts.add(tuple(rng.randrange(1 << 20) / (1 << 20) for _ in range(2 if planar else 3)))
    pts = sorted(pts)
    pairs = [[a, b] for a in range(n) for b in range(a + 1, n) if rng.random() < keep]
    return [list(p) for p in pts], pairs


def with_hull_edges(name, points, segments):
    """Adds the hull edges `contains` names as missing until none is (a NO for that reason
    alone says nothing about the solver)."""
    segments = list(segments)
    while True:
        path = write(name, points, segments)
        v, _ = run(["contains", path])
        w = v.get("witness", {})
        if w.get("kind") != "missing_hull_edge":
            return path, segments
        segments.append(w["segments"][0])


def write(name, points, segments):
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        json.dump({"points": points, "segments": segments}, f)
    return path


def header(title):
    print(f"\n{title}\n")
    print("| instance | points | segments | candidates | verdict (route) | proof variables / clauses | DRAT | seconds |")
    print("|---|---|---|---|---|---|---|---|")


def main():
    os.makedirs(WORK, exist_ok=True)
    if TETGEN_ONLY:
        tetgen_table()
        hard_table()
        return
    if "--reductions-only" in sys.argv:
        reduction_table()
        gadget_table()
        return
    header("contains (TETRAD): Kuhn grids with one segment added across, or one removed")
    for k in [8, 16] if QUICK else [8, 16, 24, 32]:
        for corrupt in ["add-crossing", "drop-edge"]:
            base = os.path.join(WORK, f"k{k}{corrupt}.ele")
            subprocess.run([TK, "generate", "kuhn", "--size", str(k), "--corrupt", corrupt, "-o", base],
                           check=True, capture_output=True)
            edge = base[:-4] + ".edge"
            m = sum(1 for _ in open(edge)) - 1
            decide("contains", edge, f"kuhn {k} {corrupt}", (k + 1) ** 3, m)
    header("contains (TETRAD): random points in space, each pair a segment with probability 0.85, hull edges added")
    for n in [10, 14, 18] if QUICK else [10, 14, 18, 22, 26, 30, 34, 38]:
        for seed in range(2):
            pts, segs = random_instance(n, False, 1000 * n + seed, keep=0.85)
            path, segs = with_hull_edges("r.json", pts, segs)
            decide("contains", path, f"random {n} #{seed}", n, len(segs))
    header("contains (TRID, planar): random points in the plane, each pair with probability 0.95, hull edges added")
    for n in [10, 20, 30] if QUICK else [10, 20, 30, 40, 50, 60]:
        for seed in range(2):
            pts, segs = random_instance(n, True, 2000 * n + seed, keep=0.95)
            path, segs = with_hull_edges("t.json", pts, segs)
            decide("contains", path, f"planar {n} #{seed}", n, len(segs))
    header("constrained (CT): random points in space, n/2 random pairs as constraints")
    for n in [10, 20] if QUICK else [10, 20, 30, 40, 50, 59]:
        for seed in range(2):
            pts, pairs = random_instance(n, False, 3000 * n + seed, keep=1.0)
            rng = random.Random(seed)
            cons = rng.sample(pairs, n // 2)
            decide("constrained", write("c.json", pts, cons), f"random {n} #{seed}", n, len(cons))
    reduction_table()
    gadget_table()
    tetgen_table()
    hard_table()


def reduction_table():
    """Theorem 2.9 carried through: random planar segment sets, their TETRAD images from
    `reduce trid-to-tetrad`, both decided by `contains`; the answers must agree."""
    header("contains on `reduce trid-to-tetrad` images of random planar sets (pairs kept with probability 0.97, hull edges added); planar answer in the label")
    for n in [10, 20] if QUICK else [10, 20, 30, 40, 50, 60, 70]:
        for seed in range(2):
            pts, segs = random_instance(n, True, 4000 * n + seed, keep=0.97)
            path, segs = with_hull_edges("t2.json", pts, segs)
            planar, _ = run(["contains", path, "--time-limit", LIMIT])
            out = os.path.join(WORK, "t3.json")
            subprocess.run([TK, "reduce", "trid-to-tetrad", path, out], check=True, capture_output=True)
            with open(out) as f:
                lifted = json.load(f)
            v, _ = decide("contains", out, f"planar {n} #{seed}: {planar['verdict']}",
                          len(lifted["points"]), len(lifted["segments"]))
            answers = [v["verdict"]]
            if n <= 30:  # the thesis's sphere construction: 2n + 1 points, all lower pairs
                subprocess.run([TK, "reduce", "trid-to-tetrad", path, out, "--construction", "sphere"],
                               check=True, capture_output=True)
                with open(out) as f:
                    lifted = json.load(f)
                w, _ = decide("contains", out, f"planar {n} #{seed}: {planar['verdict']}, sphere",
                              len(lifted["points"]), len(lifted["segments"]))
                answers.append(w["verdict"])
            for a in answers:
                if "undecided" not in (a, planar["verdict"]) and a != planar["verdict"]:
                    raise SystemExit(f"Theorem 2.9 broken on planar {n} #{seed}")


def gadget_table():
    """Chains (towers) and grids of Schönhardt gadgets for `constrained`, up to its
    60-point limit."""
    header("constrained (CT): gadget chains (one tower of L gadgets) and grids (R × C gadgets)")
    shapes = [(1, 1, l) for l in ([4, 8] if QUICK else [4, 8, 12, 16, 19])]
    shapes += [(r, c, 1) for r, c in ([(2, 2)] if QUICK else [(2, 2), (2, 3), (3, 3)])]
    for r, c, l in shapes:
        path = os.path.join(WORK, "g.json")
        subprocess.run([TK, "generate", "gadget-grid", "--rows", str(r), "--cols", str(c), "--layers", str(l),
                        "-o", path], check=True, capture_output=True)
        with open(path) as f:
            g = json.load(f)
        label = f"chain of {l}" if r == c == 1 else f"grid {r} × {c}"
        decide("constrained", path, label, len(g["points"]), len(g["segments"]))


def tetgen_table():
    print("\ntetrahedralize against TetGen -pY (keep the boundary; Steiner points only inside)\n")
    print("| polyhedron | tetrakit | seconds | TetGen -pY | Steiner points |")
    print("|---|---|---|---|---|")
    for name, args in [("prism twisted +30°", ["--twist", "30"]), ("prism twisted -30°", ["--twist", "-30"]),
                       ("Schönhardt (generate schonhardt)", [])]:
        off = os.path.join(WORK, "s.off")
        subprocess.run([TK, "generate", "schonhardt", *args, "-o", off], check=True, capture_output=True)
        v, secs = run(["tetrahedralize", off])
        ours = f"{v['verdict']}" + (f", {v['tetrahedra']} tetrahedra" if v["verdict"] == "yes" else "")
        tg = "not installed"
        steiner = "-"
        if shutil.which("tetgen"):
            out = subprocess.run(["tetgen", "-pYV", off], capture_output=True, text=True)
            for line in out.stdout.splitlines():
                if "Steiner points" in line or "steiner" in line.lower():
                    steiner = line.strip()
            tg = "ok" if out.returncode == 0 else f"exit {out.returncode}"
        print(f"| {name} | {ours} | {secs:.3f} | {tg} | {steiner} |")


def tetgen_pY(off):
    """TetGen -pYQ on a polyhedron: (outcome, Steiner points, seconds). Steiner points are the
    output's vertices beyond the input's (-Y keeps the boundary, so they are all inside)."""
    t = time.perf_counter()
    try:
        out = subprocess.run(["tetgen", "-pYQ", off], capture_output=True, text=True, timeout=float(LIMIT))
    except subprocess.TimeoutExpired:
        return f"no result in {LIMIT} s (killed)", "-", float(LIMIT)
    secs = time.perf_counter() - t
    node = off[:-4] + ".1.node"
    if out.returncode != 0 or not os.path.exists(node):
        last = (out.stdout + out.stderr).strip().splitlines()
        return f"fails (exit {out.returncode}: {last[-1] if last else ''})", "-", secs
    with open(off) as f:
        f.readline()
        n_in = int(f.readline().split()[0])
    with open(node) as f:
        n_out = int(f.readline().split()[0])
    with open(off[:-4] + ".1.ele") as f:
        tets = int(f.readline().split()[0])
    return f"{tets} tetrahedra", str(n_out - n_in), secs


def hard_table():
    """The hard polyhedron families side by side with TetGen -pY, same run."""
    print("\nhard polyhedra: tetrahedralize against TetGen -pYQ, same run\n")
    print("| polyhedron | vertices | candidates | tetrakit | seconds | TetGen -pY | Steiner points | TetGen s |")
    print("|---|---|---|---|---|---|---|---|")
    fams = [(f"Chazelle K = {k}", ["chazelle", "--grooves", str(k)]) for k in [1, 2, 4, 8, 16, 32]]
    fams += [(f"Schönhardt tower {l} × {d}°", ["schonhardt-tower", "--layers", str(l), "--twist", str(d)])
             for l, d in [(2, 30), (8, 5), (8, 30), (32, 10)]]
    fams += [(f"dented sphere N = {n}", ["perturbed", "--n", str(n), "--dent", "0.5"])
             for n in ([50] if QUICK else [50, 80, 120, 160, 250, 400])]
    for name, gen in fams:
        off = os.path.join(WORK, "h.off")
        for ext in [".1.node", ".1.ele", ".1.face", ".1.edge"]:
            if os.path.exists(off[:-4] + ext):
                os.remove(off[:-4] + ext)
        subprocess.run([TK, "generate", *gen, "-o", off], check=True, capture_output=True)
        v, secs = run(["tetrahedralize", off, "--time-limit", LIMIT])
        ours = v["verdict"]
        if v["verdict"] == "yes":
            ours += f", {v['tetrahedra']} tetrahedra"
            if v.get("short_pairs_budget") is not None:
                ours += f" (short pairs, m = {v['short_pairs_budget']})"
        elif v.get("witness"):
            ours += f" ({v['witness'].get('kind', 'proof')})"
        tg, steiner, tsecs = ("not installed", "-", 0.0)
        if shutil.which("tetgen"):
            tg, steiner, tsecs = tetgen_pY(off)
        with open(off) as f:
            f.readline()
            n = int(f.readline().split()[0])
        print(f"| {name} | {n} | {v.get('candidates', '-')} | {ours} | {secs:.3f} | {tg} | {steiner} | {tsecs:.3f} |")


if __name__ == "__main__":
    main()

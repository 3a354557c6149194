"""Point sets that once broke or stalled `tetrakit mwt`: degenerate, anisotropic and
near-convex sets, each timed beside spade's bulk Delaunay triangulation of the same
sites. Usage: python3 benches/hard2d.py [TETRAKIT] [SPADE_BULK]  (run by benches/hard2d.sh)."""
import json, math, os, random, subprocess, sys, tempfile

T = sys.argv[1] if len(sys.argv) > 1 else "target/release/tetrakit"
SPADE = sys.argv[2] if len(sys.argv) > 2 else "target/release/examples/spade_bulk"


def scanlines(lines, per, width, angle=0.0, jitter=0.0, seed=3):
    """Sites on parallel lines (LiDAR scans), rotated by `angle`, `jitter` across."""
    r = random.Random(seed)
    c, s = math.cos(angle), math.sin(angle)
    out = []
    for l in range(lines):
        for _ in range(per):
            x, y = r.random() * width, l + r.random() * jitter
            out.append((c * x - s * y, s * x + c * y))
    return out


def polar(rings, rays):
    """A radar-like polar grid in floating point: sites on a ray are collinear or off
    the line by a rounding error."""
    return [(r * math.cos(2 * math.pi * k / rays), r * math.sin(2 * math.pi * k / rays))
            for r in range(1, rings + 1) for k in range(rays)]


def polygon_round_cluster(n, k, seed=1):
    """A regular n-gon with k random sites inside half its radius."""
    r = random.Random(seed)
    out = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
    for _ in range(k):
        t, a = 0.5 * math.sqrt(r.random()), r.random() * 2 * math.pi
        out.append((t * math.cos(a), t * math.sin(a)))
    return out


def tiny_grids(clusters, side, seed=0):
    """Small 7 x 7 grids of spacing 1e-3 at random places in the unit square."""
    r = random.Random(seed)
    out = []
    for _ in range(clusters):
        cx, cy = r.random(), r.random()
        out += [(cx + i * 1e-3, cy + j * 1e-3) for i in range(side) for j in range(side)]
    return out


SETS = [
    ("scanlines 100 x 1000", lambda: scanlines(100, 1000, 100.0)),
    ("scanlines, jittered", lambda: scanlines(100, 1000, 100.0, jitter=0.01)),
    ("scanlines, rotated", lambda: scanlines(30, 200, 30.0, angle=0.5)),
    ("10 scan lines x 4000 (dense rows)", lambda: scanlines(10, 4000, 100.0)),
    ("polar grid 50 x 200", lambda: polar(50, 200)),
    ("DEM grid 300^2, step 0.1", lambda: [(i * 0.1, j * 0.1) for i in range(300) for j in range(300)]),
    ("1000-gon round 100 sites", lambda: polygon_round_cluster(1000, 100)),
    ("60 tiny 7 x 7 grids", lambda: tiny_grids(60, 7)),
]


def main():
    d = tempfile.mkdtemp()
    print(f"{'set':28} {'n':>7} {'spade_s':>8} {'mwt_s':>8} {'ratio':>6} {'diamond':>8} {'lmt':>6} {'exact':>6} {'fixed%':>6} {'faces':>6} {'largest':>7}")
    for name, make in SETS:
        pts, seen = [], set()
        for p in make():
            if p not in seen:
                seen.add(p)
                pts.append(p)
        f = os.path.join(d, "s.xyz")
        with open(f, "w") as out:
            out.write("".join(f"{x!r} {y!r}\n" for x, y in pts))
        sp = float(subprocess.run([SPADE, f], capture_output=True, text=True, check=True).stdout)
        r = subprocess.run([T, "mwt", f, "--json"], capture_output=True, text=True, timeout=600)
        if r.returncode != 0:
            print(f"{name:28} {len(pts):>7} {sp:>8.4f} failed: {r.stderr.strip()}")
            continue
        v = json.loads(r.stdout)
        st = v["stage_seconds"]
        mw = v["algorithm_seconds"]
        print(f"{name:28} {len(pts):>7} {sp:>8.4f} {mw:>8.3f} {mw / sp:>6.1f} {st['diamond']:>8.3f} {st['lmt']:>6.3f} {st['exact']:>6.3f} "
              f"{100 * v['skeleton_edges'] / v['edges']:>6.1f} {v['faces_left']:>6} {v['largest_face']:>7}")


if __name__ == "__main__":
    main()

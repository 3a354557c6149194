"""tetrakit's exact MWT beside the exact solver of Keldenich et al., in the same run.

For each family and size: the same two-column point file to both, RUNS alternating runs
(tetrakit, peer, tetrakit, peer, ...) on one core (`taskset -c 0`) and on every core,
wall-clock medians and peak memory (`/usr/bin/time`), and a check that the weights
agree (tetrakit's certified interval meets the peer's [lb, ub]). Prints the Markdown
table BENCHMARKS.md quotes; a run over TIMEOUT seconds is reported as "> TIMEOUT".

Usage (run by benches/mwt_peer.sh, which installs what the peer needs):
    python3 benches/mwt_peer.py TETRAKIT PEER [--runs 3] [--sizes 10000,100000,1000000]
        [--families uniform,gaussian,clustered,grid,scanlines,near-convex] [--cores 1,2]
        [--timeout 600]
"""
import argparse, json, os, signal, statistics, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hard2d import polygon_round_cluster, scanlines  # noqa: E402

SCALED = ("uniform", "gaussian", "clustered")


def write(path, pts):
    with open(path, "w") as out:
        out.write("".join(f"{x!r} {y!r}\n" for x, y in pts))


def instances(tk, families, sizes, work):
    """(label, path) for every instance asked for."""
    for fam in families:
        if fam in SCALED:
            for n in sizes:
                f = os.path.join(work, f"{fam}-{n}.xyz")
                if not os.path.exists(f):
                    subprocess.run([tk, "generate", "points2d", "--dist", fam, "--n", str(n), "-o", f],
                                   check=True, capture_output=True)
                yield f"{fam} 10^{len(str(n)) - 1}" if str(n).strip("0") == "1" else f"{fam} {n}", f
        elif fam == "grid":
            f = os.path.join(work, "grid-300.xyz")
            write(f, [(float(i), float(j)) for i in range(300) for j in range(300)])
            yield "grid 300×300", f
        elif fam == "scanlines":
            # LiDAR-like: 100 scan lines of 1000 returns, rows 1 apart, returns 0.1 apart
            # on average, each row jittered by 1 % of the row spacing.
            f = os.path.join(work, "scanlines.xyz")
            write(f, sorted(set(scanlines(100, 1000, 100.0, jitter=0.01))))
            yield "scan lines 100 × 1000, jittered", f
        elif fam == "near-convex":
            f = os.path.join(work, "near-convex.xyz")
            write(f, polygon_round_cluster(1000, 5))
            yield "1000-gon + 5 inside", f
        else:
            sys.exit(f"unknown family {fam}")


def timed(cmd, one_core, timeout):
    """(seconds, peak MB, stdout) of one run, or (None, None, None) past the timeout."""
    pre = ["taskset", "-c", "0"] if one_core else []
    with tempfile.NamedTemporaryFile("r") as t:
        # A session of its own, so that a timeout kills the solver, not only `time`.
        p = subprocess.Popen(pre + ["/usr/bin/time", "-f", "%e %M", "-o", t.name] + cmd,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             start_new_session=True)
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return None, None, None
        r = subprocess.CompletedProcess(cmd, p.returncode, out, err)
        if r.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed: {r.stderr.strip()[-500:]}")
        secs, kb = t.read().split()[-2:]
    return float(secs), int(kb) / 1024, r.stdout


def median(xs, timeout):
    done = [x for x in xs if x is not None]
    if len(done) < len(xs):
        return None
    return statistics.median(done)


def fmt(x, timeout):
    return f"> {timeout}" if x is None else (f"{x:.2f}" if x < 100 else f"{x:.0f}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tetrakit")
    ap.add_argument("peer")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--sizes", default="10000,100000,1000000")
    ap.add_argument("--families", default="uniform,gaussian,clustered,grid,scanlines,near-convex")
    ap.add_argument("--cores", default="1,2")
    ap.add_argument("--timeout", type=int, default=600)
    ap.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "tetrakit-mwt-peer"))
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    sizes = [int(s) for s in a.sizes.split(",")]
    print("| points | cores | tetrakit s | peer s | tetrakit / peer | peak MB tetrakit / peer | weights |")
    print("|---|---|---|---|---|---|---|")
    result = os.path.join(a.work, "peer.json")
    ratios = []
    for label, f in instances(a.tetrakit, a.families.split(","), sizes, a.work):
        for cores in a.cores.split(","):
            one = cores == "1"
            tk, peer, agree = {"s": [], "mb": []}, {"s": [], "mb": []}, "—"
            for _ in range(a.runs):
                s, mb, out = timed([a.tetrakit, "mwt", f, "--json"], one, a.timeout)
                tk["s"].append(s), tk["mb"].append(mb)
                w = json.loads(out)["weight_interval"] if out else None
                s, mb, _ = timed([a.peer, "-i", f, "-o", result], one, a.timeout)
                peer["s"].append(s), peer["mb"].append(mb)
                if s is not None and w is not None:
                    info = json.load(open(result))["solution_info"]
                    lb, ub = info["total_weight_lb"], info["total_weight_ub"]
                    ok = w[0] <= ub and lb <= w[1]
                    if not ok:
                        sys.exit(f"{label}: weights disagree: tetrakit {w}, peer [{lb}, {ub}]")
                    agree = "agree"
            ts, ps = median(tk["s"], a.timeout), median(peer["s"], a.timeout)
            tm, pm = median(tk["mb"], a.timeout), median(peer["mb"], a.timeout)
            ratio = "—" if ts is None else ("< %.2f" % (ts / a.timeout) if ps is None else f"{ts / ps:.2f}")
            if ts is not None and ps is not None:
                ratios.append(ts / ps)
            mem = f"{tm:.0f} / {'—' if pm is None else f'{pm:.0f}'}" if tm is not None else "—"
            print(f"| {label} | {cores} | {fmt(ts, a.timeout)} | {fmt(ps, a.timeout)} | {ratio} | {mem} | {agree} |",
                  flush=True)
    if ratios:
        print(f"\nworst ratio {max(ratios):.2f}, median {statistics.median(ratios):.2f} "
              f"over {len(ratios)} rows ({a.runs} alternating runs each)")


if __name__ == "__main__":
    main()

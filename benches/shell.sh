#!/usr/bin/env bash
# Reproduces the chapter 4 part of BENCHMARKS.md: `tetrakit shell` on nested random
# spheres (half the points on each, gap 0.2) and on Bern disks (`generate bern-disk`,
# RIDGE:RING in BERN) against TetGen's constrained Delaunay
# tetrahedralization of the same two surfaces (the PLC of tetrakit's boundary triangles,
# a hole inside the inner sphere; `-pQ`, and `-pYQ` which keeps the surfaces unsplit),
# in the same run, alternating. Reports tetrahedra per vertex, Steiner points, seconds
# (medians; tetrakit on every core and, with RAYON_NUM_THREADS=1, on one: TetGen uses
# one) and peak memory; tetrakit's time includes reading, its certificate and writing the
# mesh (-o: .node and .ele), as TetGen's includes writing its own (.node, .ele, .face,
# .edge).
# Then the families of benches/shell_families.py (FAMILIES, NAME:N each): thin twisted
# and coaxial prisms, bent arcs, lattice spheres with Q = P/2, circles on a cube's facets,
# a dome on a dome's floor, an eighth of a ball in a box's corner. Bigcaps get
# BIGCAP_TIMEOUT seconds per run ("-" past it).
# The last column is the largest weight of §4.4's ledger on the cap removal (JSON
# `weights.max`; Theorem 4.2 claims at most 8 for BIGCAP-REMOVE).
# Runs of 10 to 50 ms (n up to 2000) are repeated RUNS_SMALL times, the others RUNS: at
# 7 runs the medians of tetrakit's 10 ms rows moved by a tenth between batches here.
# Usage: bash benches/shell.sh      (env: SIZES, BERN, FAMILIES, RUNS, RUNS_SMALL)   Needs root for apt-get.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${SIZES:-"1000 10000 100000"}
BERN=${BERN:-"1000:250 4000:1000 10000:2500"}
FAMILIES=${FAMILIES:-"twisted:10000 coaxial:10000 arcs:10000 lattice:10000 circles:1000 dome:10000 corner:10000"}
BIGCAP_TIMEOUT=${BIGCAP_TIMEOUT:-60}
RUNS=${RUNS:-3}
RUNS_SMALL=${RUNS_SMALL:-21}
WORK=${WORK:-/tmp/tetrakit-bench-shell}
mkdir -p "$WORK"
if ! command -v tetgen >/dev/null || [ ! -x /usr/bin/time ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq tetgen time >/dev/null
fi
cargo build --release -q
TK=target/release/tetrakit
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
field() { python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }
elapsed() { awk '{print $1}' "$1"; }
# timed OUT CMD...: writes CMD's wall time to OUT, to the microsecond, with nothing else
# inside the interval (benches/timed.py; `date` and GNU time around each run weighed on
# the rows of 10 ms). Returns CMD's status.
timed() { python3 benches/timed.py "$@"; }
# peak CMD...: CMD's peak resident memory in MB, from one run under GNU time.
peak() { /usr/bin/time -f "%M" -o "$WORK/m" "$@" >/dev/null 2>&1 || true; awk '{print int($1/1024)}' "$WORK/m"; }

# How many runs a row of about N vertices gets.
runs_for() { if [ "$1" -le 2000 ]; then echo "$RUNS_SMALL"; else echo "$RUNS"; fi; }

# One row: the shell OUTER INNER against TetGen on the same surfaces, RUNS times (HOLE:
# a point inside the inner polytope, "0 0 0" when not given).
row() {
  local label=$1 o=$2 i=$3 key=$4 runs=$5 hole=${6:-"0 0 0"}
  "$TK" shell "$o" "$i" --json -o "$WORK/s$key.ele" >"$WORK/s.json"
  # shellcheck disable=SC2086
  python3 benches/shell_poly.py "$WORK/s$key.ele" "$WORK/p$key.poly" $hole
  tk=(); t1=(); tb=(); tg=(); ty=()
  for _ in $(seq "$runs"); do
    timed "$WORK/t1" "$TK" shell "$o" "$i" --json -o "$WORK/m.ele" >/dev/null
    tk+=("$(elapsed "$WORK/t1")")
    RAYON_NUM_THREADS=1 timed "$WORK/t5" "$TK" shell "$o" "$i" --json -o "$WORK/m.ele" >/dev/null
    t1+=("$(elapsed "$WORK/t5")")
    if timed "$WORK/t4" timeout "$BIGCAP_TIMEOUT" "$TK" shell "$o" "$i" --method bigcap --json -o "$WORK/m.ele" >"$WORK/b.json"; then
      tb+=("$(elapsed "$WORK/t4")")
    else
      tb+=("-"); echo '{"tetrahedra": "nan"}' >"$WORK/b.json"
    fi
    timed "$WORK/t2" tetgen -pQ "$WORK/p$key.poly" >/dev/null || true
    tg+=("$(elapsed "$WORK/t2")")
    timed "$WORK/t3" tetgen -pYQ "$WORK/p$key.poly" >/dev/null || true
    ty+=("$(elapsed "$WORK/t3")")
  done
  tkm=$(peak "$TK" shell "$o" "$i" --json -o "$WORK/m.ele"); tgm=$(peak tetgen -pQ "$WORK/p$key.poly")
  t=$(field "$WORK/s.json" tetrahedra); t0=$(field "$WORK/s.json" tetrahedra_before_flips)
  nn=$(field "$WORK/s.json" n); bt=$(field "$WORK/b.json" tetrahedra)
  wm=$(python3 -c 'import json,sys;w=json.load(open(sys.argv[1])).get("weights");print(w["max"] if w else "-")' "$WORK/s.json")
  tb_s=$(printf '%s\n' "${tb[@]}" | median)
  [ "$tb_s" = "-" ] && tb_s=nan
  tk_s=$(printf '%s\n' "${tk[@]}" | median); t1_s=$(printf '%s\n' "${t1[@]}" | median); tg_s=$(printf '%s\n' "${tg[@]}" | median); ty_s=$(printf '%s\n' "${ty[@]}" | median)
  tetgen -pQ "$WORK/p$key.poly" >/dev/null || true
  g_t=$(head -1 "$WORK/p$key.1.ele" | awk '{print $1}'); g_n=$(head -1 "$WORK/p$key.1.node" | awk '{print $1}')
  tetgen -pYQ "$WORK/p$key.poly" >/dev/null || true
  y_t=$(head -1 "$WORK/p$key.1.ele" | awk '{print $1}'); y_n=$(head -1 "$WORK/p$key.1.node" | awk '{print $1}')
  awk -v l="$label" -v n="$nn" -v t0="$t0" -v t="$t" -v a="$tk_s" -v a1="$t1_s" -v am="$tkm" -v bt="$bt" -v bs="$tb_s" -v gt="$g_t" -v gn="$g_n" -v b="$tg_s" -v bm="$tgm" \
      -v yt="$y_t" -v yn="$y_n" -v c="$ty_s" -v wm="$wm" 'BEGIN {
    printf "| %s | %d | %.2f | %.2f | %.3f | %.3f | %d | %.2f | %.3f | %.2f | %d | %.3f | %d | %.2f | %d | %.3f | %.2f | %.2f | %s |\n",
      l, n, t0 / n, t / n, a, a1, am, bt / n, bs, gt / n, gn - n, b, bm, yt / n, yn - n, c, a / b, a1 / b, wm }'
}

echo "| shells | n | cap t/n removals | cap t/n flipped | cap s | cap s, 1 thread | cap MB | bigcap t/n flipped | bigcap s | TetGen -pQ t/n | Steiner | s | MB | TetGen -pYQ t/n | Steiner | s | ratio s (cap / -pQ) | ratio, 1 thread | cap largest weight (§4.4) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  o="$WORK/o$n.xyz"; i="$WORK/i$n.xyz"
  "$TK" generate nested --n-outer $((n / 2)) --n-inner $((n / 2)) --gap 0.2 --seed 1 \
    --outer-output "$o" --inner-output "$i" >/dev/null
  row spheres "$o" "$i" "$n" "$(runs_for "$n")"
done
for d in $BERN; do
  ridge=${d%:*}; ring=${d#*:}
  o="$WORK/bo$ridge.xyz"; i="$WORK/bi$ridge.xyz"
  "$TK" generate bern-disk --ridge "$ridge" --ring "$ring" --outer-output "$o" --inner-output "$i" >/dev/null
  row "Bern disk $ridge/$ring" "$o" "$i" "b$ridge" "$(runs_for $((ridge + 2 * ring)))"
done
for f in $FAMILIES; do
  name=${f%:*}; n=${f#*:}
  o="$WORK/fo$name$n.xyz"; i="$WORK/fi$name$n.xyz"
  python3 benches/shell_families.py "$name" "$n" "$o" "$i"
  hole="0 0 0"; [ "$name" = dome ] && hole="0 0 0.25"; [ "$name" = corner ] && hole="0.25 0.25 0.25"
  row "$name" "$o" "$i" "f$name$n" "$(runs_for "$n")" "$hole"
done

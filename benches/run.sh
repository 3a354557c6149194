#!/usr/bin/env bash
# Reproduces BENCHMARKS.md: tetrakit detect on the edge sets of TetGen Delaunay meshes and
# on skew-lines sets, side by side with CGAL's Triangulation_3::is_valid on the same points,
# in the same run. Usage: bash benches/run.sh [sizes...]   (default: 10000 100000 1000000)
# Needs root for apt-get (Debian packages tetgen, libcgal-dev, time).
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${*:-"10000 100000 1000000"}
RUNS=${RUNS:-3}
WORK=${WORK:-/tmp/tetrakit-bench}
mkdir -p "$WORK"

if ! command -v tetgen >/dev/null || [ ! -d /usr/include/CGAL ] || [ ! -x /usr/bin/time ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq tetgen libcgal-dev time >/dev/null
fi
cargo build --release -q
g++ -O2 -DNDEBUG -o "$WORK/cgal_is_valid" benches/cgal_is_valid.cpp -lgmp -lmpfr
TK=target/release/tetrakit

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# runs tetrakit detect RUNS times on $1 (further arguments go to detect);
# prints "median_seconds median_parse peak_kb route"
measure_detect() {
  local secs=() parse=() mem=()
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%M" -o "$WORK/mem.txt" "$TK" detect "$@" --json > "$WORK/out.json" || true
    secs+=("$(python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))["seconds"])' "$WORK/out.json")")
    parse+=("$(python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))["parse_seconds"])' "$WORK/out.json")")
    mem+=("$(cat "$WORK/mem.txt")")
  done
  python3 -c 'import json,sys;d=json.load(open(sys.argv[1]));assert d["verdict"]=="yes",d' "$WORK/out.json"
  local route; route=$(python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))["route"])' "$WORK/out.json")
  echo "$(printf '%s\n' "${secs[@]}" | median) $(printf '%s\n' "${parse[@]}" | median) $(printf '%s\n' "${mem[@]}" | median) $route"
}

row() { # name node edge
  local segs; segs=$(head -1 "$3" | awk '{print $1}')
  read -r t p kb route < <(measure_detect "$3")
  read -r tl _ _ _ < <(measure_detect "$3" --links-only)
  local cg; cg=$("$WORK/cgal_is_valid" "$2" "$RUNS" | python3 -c 'import json,sys;print(json.load(sys.stdin)["is_valid_seconds"])')
  python3 - "$1" "$segs" "$route" "$t" "$p" "$kb" "$cg" "$tl" <<'PY'
import sys
name, segs, route, t, p, kb, cg, tl = sys.argv[1], int(sys.argv[2]), sys.argv[3], *map(float, sys.argv[4:])
print(f"| {name} | {segs:,} | {route} | {t:.3f} | {100*p/t:.0f}% | {kb*1024/segs:.0f} | {cg:.3f} | **{t/cg:.2f}** | {tl:.3f} | {tl/cg:.2f} |")
PY
}

echo "| input | segments | route | detect s (median of $RUNS) | parse share | peak bytes/segment | CGAL is_valid s | detect / is_valid | --links-only s | links-only / is_valid |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  node="$WORK/r$n.node"
  [ -f "$node" ] || python3 -c "
import random,sys
n=int(sys.argv[1]); random.seed(n)
with open(sys.argv[2],'w') as f:
    f.write(f'{n} 3 0 0\n')
    for i in range(n): f.write(f'{i+1} {random.random()!r} {random.random()!r} {random.random()!r}\n')
" "$n" "$node"
  [ -f "$WORK/r$n.1.edge" ] || tetgen -eQ "$node" >/dev/null
  row "Delaunay, $n random points" "$WORK/r$n.1.node" "$WORK/r$n.1.edge"
done
for n in ${SKEW:-100 200 400 800 1600}; do
  "$TK" generate skew-lines --points "$n" -o "$WORK/skew$n.ele" >/dev/null
  row "skew lines, $n points" "$WORK/skew$n.node" "$WORK/skew$n.edge"
done

# The two link methods on the same inputs (links route forced): the sphere sweep (default)
# and the sign table.
links_time() { # file method -> median seconds of the per-vertex phase
  for _ in $(seq "$RUNS"); do
    TETRAKIT_PHASES=1 "$TK" detect "$1" --links-only --links "$2" 2>&1 >/dev/null | awk '/phase links/{print $3}'
  done | median
}
echo
echo "| input | links phase, sweep s | links phase, sign table s | table / sweep |"
echo "|---|---|---|---|"
for f in ${LINKS_INPUTS:-r100000.1 skew400 skew800 skew1600}; do
  [ -f "$WORK/$f.edge" ] || continue
  sw=$(links_time "$WORK/$f.edge" sweep)
  tb=$(links_time "$WORK/$f.edge" table)
  python3 -c "import sys;f,a,b=sys.argv[1],float(sys.argv[2]),float(sys.argv[3]);print(f'| {f} | {a:.3f} | {b:.3f} | {b/a:.1f} |')" "$f" "$sw" "$tb"
done
echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(free -g | awk '/Mem/{print $2}') GiB; $(date -u +%Y-%m-%d)"

#!/usr/bin/env bash
# Paired runs of two tetrakit binaries on the same inputs, alternating A B A B, to tell
# whether a change made anything slower: detect at 10^6 (both routes), the MWT at 10^6,
# and the chapter 3 suite (MINTETRA at 10^5 and 10^6, the exact solver at n = 14, 16).
# Prints medians of the commands' own "seconds" and the ratio after/before.
# Usage: BEFORE=/path/to/old/tetrakit bash benches/paired.sh    (env: AFTER, RUNS, WORK)
# Build the old binary from any commit with `git worktree add /tmp/old <commit>` and
# `cargo build --release` there. Needs root for apt-get (Debian package tetgen).
set -euo pipefail
cd "$(dirname "$0")/.."
: "${BEFORE:?set BEFORE to the tetrakit binary to compare against}"
RUNS=${RUNS:-5}
WORK=${WORK:-/tmp/tetrakit-bench-paired}
mkdir -p "$WORK"
if [ -z "${AFTER:-}" ]; then
  cargo build --release -q
  AFTER=target/release/tetrakit
fi
command -v tetgen >/dev/null || {
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq tetgen >/dev/null
}

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { python3 -c 'import json,sys;print(json.load(sys.stdin)["seconds"])'; }

# Inputs (made once, by the new binary: the generators are unchanged).
n=1000000
[ -f "$WORK/r$n.node" ] || python3 -c "
import random,sys
n=int(sys.argv[1]); random.seed(n)
with open(sys.argv[2],'w') as f:
    f.write(f'{n} 3 0 0\n')
    for i in range(n): f.write(f'{i+1} {random.random()!r} {random.random()!r} {random.random()!r}\n')
" "$n" "$WORK/r$n.node"
[ -f "$WORK/r$n.1.edge" ] || tetgen -eQ "$WORK/r$n.node" >/dev/null
[ -f "$WORK/u$n.xyz" ] || "$AFTER" generate points2d --dist uniform --n "$n" --seed 1 -o "$WORK/u$n.xyz" >/dev/null
for c in 100000 1000000; do
  [ -f "$WORK/bp$c.off" ] || "$AFTER" generate bp-polyhedron --core "$c" --nets $((c / 20)) --augment $((c / 10)) --seed 1 -o "$WORK/bp$c.off" >/dev/null
done
for k in 14 16; do
  [ -f "$WORK/cv$k.xyz" ] || python3 benches/sphere_points.py "$k" "$WORK/cv$k"
done

row() { # name, then the command's arguments
  local name=$1; shift
  local a=() b=()
  for _ in $(seq "$RUNS"); do
    a+=("$("$BEFORE" "$@" --json | seconds)")
    b+=("$("$AFTER" "$@" --json | seconds)")
  done
  local ma mb
  ma=$(printf '%s\n' "${a[@]}" | median)
  mb=$(printf '%s\n' "${b[@]}" | median)
  printf '| %s | %.3f | %.3f | %.3f |\n' "$name" "$ma" "$mb" "$(python3 -c "print($mb / $ma)")"
}

echo "| input | before s (median of $RUNS) | after s | after / before |"
echo "|---|---|---|---|"
row "detect, Delaunay 10^6 points" detect "$WORK/r$n.1.edge"
row "detect --links-only, Delaunay 10^6 points" detect "$WORK/r$n.1.edge" --links-only
row "mwt, uniform 10^6" mwt "$WORK/u$n.xyz"
row "mintetra, BP-polyhedron core 10^5" mintetra "$WORK/bp100000.off"
row "mintetra, BP-polyhedron core 10^6" mintetra "$WORK/bp1000000.off"
row "tetrahedralize --minimal, 14 points" tetrahedralize "$WORK/cv14.xyz" --minimal
row "tetrahedralize --minimal, 16 points" tetrahedralize "$WORK/cv16.xyz" --minimal

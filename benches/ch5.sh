#!/usr/bin/env bash
# Chapter 5 benchmarks: β-skeleton (β = 1.16, circle) and exact MWT against spade's bulk
# Delaunay triangulation of the same points, in the same run. Medians of RUNS (default 3).
# Usage: bash benches/ch5.sh            (skeleton at 1e4..1e6, MWT up to MWT_MAX=10000)
#        MWT_MAX=100000 bash benches/ch5.sh
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${RUNS:-3}
MWT_MAX=${MWT_MAX:-10000}
SIZES=${SIZES:-"10000 100000 1000000"}
cargo build --release --bin tetrakit --example spade_bulk >/dev/null 2>&1
T=target/release/tetrakit
D=$(mktemp -d)
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
field() { python3 -c "import json,sys; print(json.load(sys.stdin)$1)"; }
printf "%-10s %8s %10s %10s %7s %10s %7s %9s %7s %6s\n" dist n spade_s skel_s ratio mwt_s ratio fixed% faces holes
for dist in uniform gaussian clustered; do
  for n in $SIZES; do
    f=$D/$dist$n.xyz
    $T generate points2d --dist "$dist" --n "$n" --seed 1 -o "$f" >/dev/null
    sp=$(RUNS=$RUNS target/release/examples/spade_bulk "$f")
    sk=$(for _ in $(seq "$RUNS"); do $T skeleton "$f" --beta 1.16 --json | field "['seconds_algorithm']"; done | median)
    if [ "$n" -le "$MWT_MAX" ]; then
      js=$($T mwt "$f" --json)
      mw=$(echo "$js" | field "['seconds_algorithm']")
      fixed=$(echo "$js" | python3 -c "import json,sys; v=json.load(sys.stdin); print(round(100*v['skeleton_edges']/v['edges'],1))")
      faces=$(echo "$js" | field "['faces_left']")
      holes=$(echo "$js" | field "['faces_with_holes']")
      mr=$(python3 -c "print(round($mw/$sp,2))")
    else
      mw=-; mr=-; fixed=-; faces=-; holes=-
    fi
    printf "%-10s %8s %10s %10s %7s %10s %7s %9s %7s %6s\n" "$dist" "$n" "$sp" "$sk" \
      "$(python3 -c "print(round($sk/$sp,2))")" "$mw" "$mr" "$fixed" "$faces" "$holes"
  done
done
rm -rf "$D"

#!/usr/bin/env bash
# Chapter 5 benchmarks: β-skeleton (β = 1.16, circle) and exact MWT against spade's bulk
# Delaunay triangulation of the same points, in the same run. Medians of RUNS (default 3).
# Usage: bash benches/ch5.sh            (skeleton at 1e4..1e6, MWT up to MWT_MAX=10000,
#                                        Keil at β = 1.16 unless KEIL=0)
#        MWT_MAX=100000 bash benches/ch5.sh
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${RUNS:-3}
MWT_MAX=${MWT_MAX:-10000}
SIZES=${SIZES:-"10000 100000 1000000"}
[ -x /usr/bin/time ] || { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time >/dev/null; }
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
    sk=$(for _ in $(seq "$RUNS"); do $T skeleton "$f" --beta 1.16 --json | field "['algorithm_seconds']"; done | median)
    if [ "$n" -le "$MWT_MAX" ]; then
      js=$($T mwt "$f" --json)
      mw=$(echo "$js" | field "['algorithm_seconds']")
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


# Keil's construction at β = 1.16 (thesis §5.2): the smallest n that separates xy in this
# realization, and Lemma 5.8's n (the default), by the split along L.
if [ "${KEIL:-1}" = 1 ]; then
  printf "\n%-8s %6s %6s %10s %10s %9s\n" beta n sites seconds xy_in_mwt peak_MB
  for n in 400 420 1000 default; do
    arg=(); [ "$n" != default ] && arg=(--n "$n")
    js=$(/usr/bin/time -f "%M" -o "$D.mem" $T keil --beta 1.16 "${arg[@]}" --json)
    printf "%-8s %6s %6s %10s %10s %9s\n" 1.16 "$(echo "$js" | field "['n']")" \
      "$(echo "$js" | field "['sites']")" "$(echo "$js" | field "['seconds']")" \
      "$(echo "$js" | field "['xy_in_mwt']")" "$(( $(cat "$D.mem") / 1024 ))"
  done
  rm -f "$D.mem"
fi
rm -rf "$D"

#!/usr/bin/env bash
# Reproduces the chapter 3 part of BENCHMARKS.md:
#  A. MINTETRA on generated augmented BP-polyhedra (a Boerdijk-Coxeter helix core with
#     n/20 BP-nets and n/10 stacked tetrahedra), n = 10^3 .. 10^6;
#  B. the exact minimal solver (`tetrahedralize --minimal`) side by side with TOPCOM's
#     points2mintriang on the same points in convex position (integer points near a
#     sphere), in the same run. TOPCOM prints each improvement; the last is its minimum.
# Usage: bash benches/ch3.sh            (env: SIZES, NS, RUNS, TOPCOM_LIMIT)
# Needs root for apt-get (Debian packages topcom, time).
set -euo pipefail
cd "$(dirname "$0")/.."
SIZES=${SIZES:-"1000 10000 100000 1000000"}
NS=${NS:-"12 14 16 18"}
RUNS=${RUNS:-3}
TOPCOM_LIMIT=${TOPCOM_LIMIT:-120}
WORK=${WORK:-/tmp/tetrakit-bench-ch3}
mkdir -p "$WORK"

if ! command -v topcom-points2mintriang >/dev/null || [ ! -x /usr/bin/time ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq topcom time >/dev/null
fi
cargo build --release -q
TK=target/release/tetrakit
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
field() { python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }

echo "## A. MINTETRA (medians of $RUNS runs)"
echo
echo "| vertices | tetrahedra | levels | MINTETRA | validate input | certify output | total | peak RSS |"
echo "|---|---|---|---|---|---|---|---|"
for n in $SIZES; do
  poly="$WORK/bp$n.off"
  [ -f "$poly" ] || "$TK" generate bp-polyhedron --core "$n" --nets $((n / 20)) --augment $((n / 10)) --seed 1 -o "$poly" >/dev/null
  algo=(); parse=(); cert=(); total=(); mem=()
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%M" -o "$WORK/mem.txt" "$TK" mintetra "$poly" --json >"$WORK/m.json"
    algo+=("$(field "$WORK/m.json" mintetra_seconds)")
    parse+=("$(field "$WORK/m.json" parse_seconds)")
    cert+=("$(field "$WORK/m.json" verify_seconds)")
    total+=("$(field "$WORK/m.json" seconds)")
    mem+=("$(cat "$WORK/mem.txt")")
  done
  printf '| %s | %s | %s | %.3f s | %.2f s | %.2f s | %.2f s | %d MB |\n' \
    "$(field "$WORK/m.json" vertices)" "$(field "$WORK/m.json" tetrahedra)" "$(field "$WORK/m.json" levels)" \
    "$(printf '%s\n' "${algo[@]}" | median)" "$(printf '%s\n' "${parse[@]}" | median)" \
    "$(printf '%s\n' "${cert[@]}" | median)" "$(printf '%s\n' "${total[@]}" | median)" \
    $(($(printf '%s\n' "${mem[@]}" | median) / 1024))
done

echo
echo "## B. Exact minimum vs TOPCOM points2mintriang (convex position)"
echo
echo "| n | minimum (tetrakit) | minimum (TOPCOM) | tetrakit (median of $RUNS) | TOPCOM | ratio |"
echo "|---|---|---|---|---|---|"
for n in $NS; do
  python3 benches/sphere_points.py "$n" "$WORK/cv$n"
  tk=()
  for _ in $(seq "$RUNS"); do
    "$TK" tetrahedralize "$WORK/cv$n.xyz" --minimal --json >"$WORK/t.json"
    tk+=("$(field "$WORK/t.json" seconds)")
  done
  tmin=$(field "$WORK/t.json" minimum)
  tks=$(printf '%s\n' "${tk[@]}" | median)
  start=$(date +%s.%N)
  if timeout "$TOPCOM_LIMIT" topcom-points2mintriang <"$WORK/cv$n.topcom" >"$WORK/topcom.out" 2>/dev/null; then
    tc=$(python3 -c "print($(date +%s.%N) - $start)")
    tcmin=$(python3 -c 'import re,sys;s=open(sys.argv[1]).read();m=re.findall(r":= \{(.*)\};",s);print(m[-1].count("},{")+1 if m else "?")' "$WORK/topcom.out")
    ratio=$(python3 -c "print(f'{$tks/$tc:.3f}')")
    tcs=$(python3 -c "print(f'{$tc:.2f} s')")
  else
    tcmin="-"; tcs="> ${TOPCOM_LIMIT} s (killed)"; ratio="< $(python3 -c "print(f'{$tks/$TOPCOM_LIMIT:.3f}')")"
  fi
  printf '| %s | %s | %s | %.2f s | %s | %s |\n' "$n" "$tmin" "$tcmin" "$tks" "$tcs" "$ratio"
done

#!/usr/bin/env bash
# Reproduces the "check on files from Gmsh and VTK" part of BENCHMARKS.md: a unit cube
# meshed by Debian's Gmsh (SIZE = Mesh.MeshSizeMax; 0.016 gives about 10^6 tetrahedra),
# `tetrakit check` on it as Gmsh 4.1 binary `.msh` and as meshio's default `.vtu`
# (base64, zlib), and the Python package on the same mesh: `tetrakit.check(points, tets)`
# from numpy arrays (the arrays already in memory), and meshio's read for comparison.
# Medians of RUNS, alternating; peak memory of the CLI; the parse share from the
# `parse_seconds` of `check --json` (reading the file into points and tetrahedra).
# Usage: bash benches/check_formats.sh      (env: SIZE, RUNS)   Needs root for apt-get.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZE=${SIZE:-0.016}
RUNS=${RUNS:-3}
WORK=${WORK:-/tmp/tetrakit-bench-check}
mkdir -p "$WORK"
if ! command -v gmsh >/dev/null || [ ! -x /usr/bin/time ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gmsh time >/dev/null
fi
python3 -m pip install -q --root-user-action=ignore meshio numpy ./crates/tetrakit-py
cargo build --release -q
TK=target/release/tetrakit
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
if [ ! -f "$WORK/cube-$SIZE.msh" ]; then
  printf 'SetFactory("OpenCASCADE");\nBox(1) = {0,0,0, 1,1,1};\nMesh.MeshSizeMax = %s;\n' "$SIZE" >"$WORK/cube.geo"
  gmsh "$WORK/cube.geo" -3 -format msh41 -bin -o "$WORK/cube-$SIZE.msh" >/dev/null
  python3 -c 'import meshio,sys; m=meshio.read(sys.argv[1]); meshio.write(sys.argv[2], meshio.Mesh(m.points, [c for c in m.cells if c.type=="tetra"]))' \
    "$WORK/cube-$SIZE.msh" "$WORK/cube-$SIZE.vtu"
fi
declare -A secs mem parse
for _ in $(seq "$RUNS"); do
  for ext in msh vtu; do
    /usr/bin/time -f "%e %M" -o "$WORK/t" "$TK" check "$WORK/cube-$SIZE.$ext" --json >"$WORK/c.json"
    secs[$ext]+="$(awk '{print $1}' "$WORK/t") "
    mem[$ext]+="$(awk '{print int($2/1024)}' "$WORK/t") "
    parse[$ext]+="$(python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))["parse_seconds"])' "$WORK/c.json") "
  done
  python3 - "$WORK/cube-$SIZE.vtu" >>"$WORK/py.txt" <<'PY'
import sys, time, meshio, tetrakit
t0 = time.perf_counter(); m = meshio.read(sys.argv[1]); t1 = time.perf_counter()
pts, tets = tetrakit.from_meshio(m)
t2 = time.perf_counter(); r = tetrakit.check(pts, tets); t3 = time.perf_counter()
assert r.valid
print(f"{t1 - t0:.3f} {t3 - t2:.3f} {len(tets)}")
PY
done
tets=$(python3 -c 'import json,sys;print(json.load(open(sys.argv[1]))["tetrahedra"])' "$WORK/c.json")
echo "cube, Mesh.MeshSizeMax = $SIZE: $tets tetrahedra; $(du -m "$WORK/cube-$SIZE.msh" | cut -f1) MB .msh, $(du -m "$WORK/cube-$SIZE.vtu" | cut -f1) MB .vtu"
echo "| input | seconds (median of $RUNS) | of which parsing | peak MB |"
echo "|---|---|---|---|"
for ext in msh vtu; do
  t=$(tr ' ' '\n' <<<"${secs[$ext]}" | grep . | median)
  p=$(tr ' ' '\n' <<<"${parse[$ext]}" | grep . | median)
  echo "| tetrakit check cube.$ext | $t | $(printf '%.2f' "$p") s ($(awk -v p="$p" -v t="$t" 'BEGIN{printf "%.0f", 100*p/t}') %) | $(tr ' ' '\n' <<<"${mem[$ext]}" | grep . | median) |"
done
echo "| Python tetrakit.check(points, tets), arrays in memory | $(tail -n "$RUNS" "$WORK/py.txt" | awk '{print $2}' | median) | (no file) | |"
echo "| (meshio.read of the .vtu, for comparison) | $(tail -n "$RUNS" "$WORK/py.txt" | awk '{print $1}' | median) | | |"

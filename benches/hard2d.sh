#!/usr/bin/env bash
# Hard planar sets for `tetrakit mwt` (degenerate, anisotropic, near-convex), each beside
# spade's bulk Delaunay triangulation of the same sites: bash benches/hard2d.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --bin tetrakit --example spade_bulk >/dev/null 2>&1
python3 benches/hard2d.py target/release/tetrakit target/release/examples/spade_bulk

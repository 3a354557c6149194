#!/usr/bin/env bash
# tetrakit's exact MWT beside the exact solver of Keldenich et al., same inputs, same run
# (benches/mwt_peer.py says what is measured). The peer is PEER (default: the build in
# ../shared/peers/mwt-keldenich/, whose README says how to build it elsewhere); it needs
# Debian libtbb12, libgmp10 and libmpfr6, installed here with `time` when missing.
# Usage: bash benches/mwt_peer.sh [--runs 3] [--sizes 10000,100000,1000000]
#        [--families uniform,gaussian,clustered,grid,scanlines,near-convex] [--cores 1,2]
set -euo pipefail
cd "$(dirname "$0")/.."
PEER=${PEER:-$(realpath ../shared/peers/mwt-keldenich/solve_mwt)}
if [ ! -x "$PEER" ]; then
  echo "no peer at $PEER (set PEER=path/to/solve_mwt)" >&2
  exit 2
fi
if [ ! -x /usr/bin/time ] || ! "$PEER" --help >/dev/null 2>&1; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq time libtbb12 libgmp10 libmpfr6 >/dev/null
fi
cargo build --release --bin tetrakit >/dev/null 2>&1
python3 benches/mwt_peer.py target/release/tetrakit "$PEER" "$@"

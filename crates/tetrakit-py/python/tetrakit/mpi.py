"""A partitioned mesh checked by several processes under MPI.

    mpirun -n K python3 -m tetrakit.mpi check MESH.pvtu [--json] [--convex] [--manifold] [--reorient] [--tets-only] [--output P.pvtu]

Each rank reads only its files of the ``.pvtu`` (file ``f`` on rank ``f mod K``; each
``Piece`` in a file is a piece, numbered as ``tetrakit check`` numbers them) and
checks them in Rust with the GIL released; the ranks exchange interface points by key,
the tetrahedra around interface vertices (ghosts), the boundary faces (to the owners
of the grid cells they meet, for the self-intersection test) and the boundary edges (to
their owners, who join the ranks' boundary components), with mpi4py's ``alltoall``
(seven rounds); no rank holds more of the boundary than its own share. Rank 0 prints what ``tetrakit check MESH.pvtu`` prints, the
same text or JSON, problem for problem, and every rank exits with its exit code: 0 valid,
1 not, 2 bad input (one line naming the file and the line or piece). Ranks with no piece
take part. ``--output P.pvtu`` writes every piece with its problem fields for ParaView,
as ``tetrakit check --output P.pvtu`` does, each rank its own pieces. Needs mpi4py (``pip install mpi4py``, over Open MPI: Debian ``openmpi-bin``
and ``libopenmpi-dev``).

The rounds themselves are :class:`tetrakit._core.RankCheck`, a byte-message state machine
that any transport can drive:

>>> from tetrakit import _core
>>> import numpy as np
>>> rc = _core.RankCheck("missing.pvtu", 0, 1)
>>> buffer, counts = rc.start()
>>> rc.step(np.frombuffer(buffer, np.uint8), counts) is None
True
>>> rc.printed(False, 0.0, 0.0)[0]
2
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from typing import List, Optional

from . import _core


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python3 -m tetrakit.mpi",
        description="Check a partitioned mesh (.pvtu) under MPI, each rank reading its pieces.",
    )
    sub = p.add_subparsers(dest="command", required=True)
    c = sub.add_parser("check", help="check a .pvtu as `tetrakit check` does")
    c.add_argument("input", help="the .pvtu index of the pieces")
    c.add_argument("--json", action="store_true", help="print one JSON object")
    c.add_argument("--convex", action="store_true", help="certify the convex hull is tetrahedralized")
    c.add_argument("--manifold", action="store_true", help="non-manifold boundary edges are problems")
    c.add_argument("--reorient", action="store_true", help="turn negatively oriented tetrahedra")
    c.add_argument("--tets-only", action="store_true",
                   help="check the tetrahedra of pieces with other cells (else those are bad input)")
    c.add_argument("--output", metavar="P.pvtu",
                   help="write every piece with its problem fields (each rank its own pieces)")
    c.add_argument("--stats", action="store_true",
                   help="each rank prints to stderr the bytes it sent, its peak memory and its seconds")
    return p


#: The most bytes one all-to-all moves into or out of a rank: MPI counts and
#: displacements are C ints, so a larger exchange goes in rounds of at most this many.
MESSAGE_LIMIT = 2**31 - 1


def _exchange(comm, buffer: bytes, counts: List[int], limit: int = MESSAGE_LIMIT):
    """All-to-all of one message per rank (``buffer``, rank after rank, ``counts`` long
    each): what every rank sent this one, as a uint8 array and its counts. Where some rank
    would send or receive more than ``limit`` bytes, in rounds that each move at most
    ``limit // size`` bytes between two ranks."""
    import numpy as np
    from mpi4py import MPI
    got = comm.alltoall(counts)
    send = np.frombuffer(buffer, dtype=np.uint8)
    recv = np.empty(sum(got), dtype=np.uint8)
    at = lambda c: np.concatenate([[0], np.cumsum(c)[:-1]]).astype(np.int64)  # noqa: E731
    if comm.allreduce(max(sum(counts), sum(got)), op=MPI.MAX) <= limit:
        comm.Alltoallv([send, (counts, at(counts)), MPI.BYTE], [recv, (got, at(got)), MPI.BYTE])
        return recv, got
    chunk = max(1, limit // comm.size)
    longest = comm.allreduce(max(counts, default=0), op=MPI.MAX)
    starts, ends = at(counts), at(got)
    for r in range(-(-longest // chunk)):
        cut = lambda c: [min(max(x - r * chunk, 0), chunk) for x in c]  # noqa: E731
        out, into = cut(counts), cut(got)
        part = np.concatenate([send[s + r * chunk:s + r * chunk + n] for s, n in zip(starts, out)])
        back = np.empty(sum(into), dtype=np.uint8)
        comm.Alltoallv([part, (out, at(out)), MPI.BYTE], [back, (into, at(into)), MPI.BYTE])
        for s, n, b in zip(ends, into, at(into)):
            recv[s + r * chunk:s + r * chunk + n] = back[b:b + n]
    return recv, got


def run(comm, argv: Optional[List[str]] = None, *, limit: int = MESSAGE_LIMIT) -> int:
    """Runs the command of ``argv`` over the communicator ``comm``; returns the exit code
    (the same on every rank). Rank 0 prints. ``limit``: the most bytes one all-to-all
    moves into or out of a rank (:data:`MESSAGE_LIMIT`; tests set it small)."""
    args = _parser().parse_args(argv)
    if not args.input.lower().endswith(".pvtu"):
        if comm.rank == 0:
            print(f"tetrakit: {args.input}: python3 -m tetrakit.mpi checks a .pvtu "
                  "(use `tetrakit check` for one file)", file=sys.stderr)
        return 2
    if args.output is not None and not args.output.lower().endswith(".pvtu"):
        if comm.rank == 0:
            print(f"tetrakit: --output {args.output}: under MPI the pieces are written "
                  "as a .pvtu (each rank its own)", file=sys.stderr)
        return 2
    start = time.perf_counter()
    # The ranks on one machine share its cores (Open MPI says how many ranks it has).
    local = int(os.environ.get("OMPI_COMM_WORLD_LOCAL_SIZE", "1"))
    os.environ.setdefault("RAYON_NUM_THREADS", str(max(1, (os.cpu_count() or 1) // local)))
    rc = _core.RankCheck(args.input, comm.rank, comm.size,
                         convex=args.convex, manifold=args.manifold, reorient=args.reorient,
                         tets_only=args.tets_only, output=args.output)
    try:
        out = rc.start()
        parsed = time.perf_counter() - start
        while out is not None:
            out = rc.step(*_exchange(comm, *out, limit=limit))
    except BaseException:
        # A rank that fails here (a bug: a message that does not decode) would leave the
        # others waiting in the next exchange: the job stops, with its traceback.
        import traceback
        traceback.print_exc()
        comm.Abort(70)
    code, text = rc.printed(args.json, time.perf_counter() - start, parsed)
    # A piece another rank could not write is the job's error (exit 2, its line).
    failed = comm.gather(text if code == 2 else None, root=0)
    if comm.rank == 0:
        first = next((t for t in failed if t is not None), None)
        if first is not None:
            code, text = 2, first
    code = comm.bcast(code, root=0)
    if args.stats:
        import resource
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
        print(f"rank {comm.rank}/{comm.size}: sent {rc.bytes_sent} bytes, peak {peak} KiB, "
              f"{time.perf_counter() - start:.2f} s", file=sys.stderr)
    if comm.rank == 0:
        if code == 2:
            print(f"tetrakit: {text}", file=sys.stderr)
        else:
            print(text)
    return code


def main(argv: Optional[List[str]] = None) -> int:
    """``python3 -m tetrakit.mpi``: :func:`run` over ``MPI.COMM_WORLD``."""
    try:
        from mpi4py import MPI
    except ImportError:
        print("tetrakit: python3 -m tetrakit.mpi needs mpi4py (pip install mpi4py; "
              "Open MPI: apt-get install openmpi-bin libopenmpi-dev)", file=sys.stderr)
        return 2
    return run(MPI.COMM_WORLD, argv)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Runs a command and writes its wall time in seconds to OUT: the command alone, to the
microsecond, with no `date` or GNU `time` process inside the interval (they weighed on
runs of 10 ms). Peak memory is not measured here: a child forked from Python reports
Python's resident size as its own peak. Exits with the command's status.

Usage: python3 benches/timed.py OUT CMD [ARG...]   (stdout and stderr pass through)
"""
import subprocess
import sys
import time


def main() -> int:
    out, cmd = sys.argv[1], sys.argv[2:]
    start = time.perf_counter()
    status = subprocess.call(cmd)
    seconds = time.perf_counter() - start
    with open(out, "w") as f:
        f.write(f"{seconds:.6f}\n")
    return status if status >= 0 else 128 - status


if __name__ == "__main__":
    sys.exit(main())

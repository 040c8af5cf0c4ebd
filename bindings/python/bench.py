"""Benchmark (not a test): the cost of one block call from Python, and of one numpy scan of
10 048 TON timers against the same scan of the core's TonBank<10048> in Rust.

    python bindings/python/bench.py [--scans N]

The Rust figure is measured inside the extension (`_rust_ton_scan_seconds`: the core's
`TonBank<10048>` scanned with the same inputs and presets, no Python in the loop), so that
both run the same compiled code on the same data; the difference is the boundary: the call,
the array checks, the conversion of PT and the writing of Q and ET into numpy arrays.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import time
from typing import Callable, List

# numpy's BLAS threads spin while idle and take a core from the loop measured (none of the
# work here uses BLAS): one thread.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import plc_timers  # noqa: E402

N = 10_048
SCAN_MS = 10


def best_of(repeats: int, fn: Callable[[], float]) -> float:
    """The median of `repeats` measurements (each a mean over many iterations)."""
    return statistics.median(fn() for _ in range(repeats))


def bench_call(iterations: int) -> float:
    ton = plc_timers.TON(pt="T#500ms")
    call = ton.call
    start = time.perf_counter()
    for k in range(iterations):
        call(k, True)
    return (time.perf_counter() - start) / iterations


def plant(rng: np.random.Generator, scans: int, toggle: float) -> List[np.ndarray]:
    """`scans` input arrays in turn: each IN keeps its value from scan to scan except with
    probability `toggle` (a plant where a few sensors change per scan)."""
    current = rng.random(N) < 0.5
    out = []
    for _ in range(scans):
        flip = rng.random(N) < toggle
        current = current ^ flip
        out.append(current.copy())
    return out


def bench_scan(inputs: List[np.ndarray], pt: np.ndarray, scans: int, reuse: bool) -> float:
    bank = plc_timers.TonBank(N)
    out = (np.zeros(N, np.bool_), np.zeros(N, np.int32)) if reuse else None
    start = time.perf_counter()
    for k in range(scans):
        bank.scan(SCAN_MS * k, inputs[k % len(inputs)], pt, out=out)
    return (time.perf_counter() - start) / scans


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--scans", type=int, default=4000)
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    rng = np.random.default_rng(2026)
    pt = rng.integers(10, 5_000, N).astype(np.int32)

    print(f"python {platform.python_version()}, numpy {np.__version__}, {platform.machine()}")
    call = best_of(args.repeats, lambda: bench_call(100_000))
    print(f"one TON.call from Python: {call * 1e9:8.0f} ns")
    print(f"scan of {N} TON (median of {args.repeats}, {args.scans} scans each):")
    print(f"  {'inputs':<34} {'Rust':>9} {'numpy':>9} {'ratio':>6} {'numpy out=':>11} {'ratio':>6}")
    for name, toggle in (("steady (1% of IN change per scan)", 0.01),
                         ("busy (50% of IN change per scan)", 0.5)):
        inputs = plant(rng, 64, toggle)
        rust = best_of(args.repeats,
                       lambda: plc_timers.plc_timers._rust_ton_scan_seconds(inputs, pt, args.scans))
        fresh = best_of(args.repeats, lambda: bench_scan(inputs, pt, args.scans, False))
        reuse = best_of(args.repeats, lambda: bench_scan(inputs, pt, args.scans, True))
        print(f"  {name:<34} {rust * 1e6:7.1f}us {fresh * 1e6:7.1f}us {fresh / rust:5.2f}x"
              f" {reuse * 1e6:9.1f}us {reuse / rust:5.2f}x")


if __name__ == "__main__":
    main()

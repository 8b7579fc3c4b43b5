#!/usr/bin/env python3
"""Work estimates against measured time, through the command line.

    python3 benches/estimates.py [--cli target/release/casteljau] [--markdown]

For each case the estimate is read from the refusals themselves: the command runs with
`--max-work 1`, and again with the limit just above each estimate it prints, until it stops
refusing for work (an arrangement is priced stage by stage, so the last estimate printed is
the sum of its stages). The measured time is the wall time of the same command with
`--max-work 1e15` (best of `--repeat` runs), less the time of a trivial command (the
process start, which no estimate counts). A work unit is meant to be a nanosecond of this
machine, so the ratio estimate / measured should lie within 3x either way (issue #34).
Standard library only; the cases are the issue's and the benchmark's.
"""

import argparse
import re
import subprocess
import sys
import time

WORK = re.compile(r"estimated work ([0-9.]+e[+-]?[0-9]+)")


def digits(k):
    return f"{k}{'7' * 999}"


def glyph_2000():
    import math

    d = "M1000 0"
    for i in range(1, 2001):
        a = math.tau * i / 2000
        r = 1037.0 if i % 2 else 1000.0
        x, y = round(r * math.cos(a)), round(r * math.sin(a))
        d += f" C{x} {y} {x} {y} {x} {y}"
    return d + " Z"


def curve(n, a, m, b):
    return ", ".join(f"{i * a % m} {i * i % b}" for i in range(n + 1))


BIG_CUBIC = ", ".join(f"{digits(k + 1)} {digits(k + 5)}" for k in range(4))
CUSP_A = "M2 8 Q1.5 9.5 2 7 C3.5 3 6.5 3 5 0 C4.5 0.5 6.5 2 7 1 L2 8 Z"
CUSP_B = "M7 1 C6.5 2 4.5 0.5 5 0 L5.5 3.75 L4 1.25 L5 0 Z"
RING_A = "M0 0 C10 20 30 20 40 0 C30 -20 10 -20 0 0 Z M15 0 C17 5 23 5 25 0 C23 -5 17 -5 15 0 Z"
RING_B = "M20 -30 C40 -10 40 10 20 30 C0 10 0 -10 20 -30 Z M20 -8 C24 -4 24 4 20 8 C16 4 16 -4 20 -8 Z"

def near_cubic(points, bits, seed):
    """`points` scaled by 2^bits, each coordinate moved by a pseudo-random (bits − 8)-bit amount."""
    state = seed

    def noise():
        nonlocal state
        n = 0
        for _ in range(bits // 64 + 1):
            state = (state * 6364136223846793005 + 1442695040888963407) % 2**64
            n = (n << 64) | (state >> 32)
        return n % 2 ** (bits - 8)

    return ", ".join(f"{x * 2**bits + noise()} {y * 2**bits + noise()}" for x, y in points)


# (name, arguments; "{found}" is replaced by the command's own answer without --against)
CASES = [
    ("intersect, two cubics (small integers)", ["intersect", "0 0, 1 3, 3 -1, 4 2", "0 2, 2 -2, 3 4, 4 0"]),
    ("intersect, degree 7 × 7", ["intersect", curve(7, 13, 97, 41), curve(7, 29, 89, 61)]),
    ("intersect --self, degree 8 (a parameter of degree 42)", ["intersect", "--self", curve(8, 13, 97, 41)]),
    ("intersect --self, degree 8 (another curve)", ["intersect", "--self", curve(8, 29, 89, 61)]),
    (
        "intersect, two cubics of 1000-bit integers",
        [
            "intersect",
            near_cubic([(0, 0), (1, 3), (3, -1), (4, 2)], 1000, 1),
            near_cubic([(0, 2), (2, -2), (3, 4), (4, 0)], 1000, 2),
        ],
    ),
    ("intersect, a cubic and a line 10^±300 (exact route)", ["intersect", "0 0, 1 1, 2 1, 3 0", "1e300 1e-300, -1e300 0"]),
    ("elevate --by 1000, 1000-digit cubic", ["elevate", "--by", "1000", BIG_CUBIC]),
    ("elevate --by 2000, small cubic", ["elevate", "--by", "2000", "0 0, 1 2, 3 1, 4 0"]),
    (
        "boolean difference, 1e300 with 1e-300",
        ["boolean", "difference", "M0 0 C1 1 2 1 3 0 Z", "M1e300 0 L1e300 1e-300 L-1e300 0 Z"],
    ),
    ("arrange --json, tiny quadratic roots", ["arrange", "--json", "M0 0 C3 0 -1 0 2 0 Z", "M0 0 H1e300 V1e300 H0 Z"]),
    ("boolean union at a cusp, --against itself", ["boolean", "union", CUSP_A, CUSP_B, "--direction", "cw", "--against", "{found}"]),
    ("boolean union of two rings, --against itself", ["boolean", "union", RING_A, RING_B, "--against", "{found}"]),
    ("boolean simplify, a 2,000-segment glyph", ["boolean", "simplify", glyph_2000()]),
    ("lint --path, the same glyph", ["lint", "--path", glyph_2000()]),
]


def run(cli, args, work):
    t = time.perf_counter()
    p = subprocess.run([cli, *args, "--max-work", work], capture_output=True, text=True)
    return p, time.perf_counter() - t


def estimate(cli, args):
    """The total estimate: raise the limit past each printed estimate until none is refused."""
    limit, last = "1", None
    for _ in range(12):
        p, _ = run(cli, args, limit)
        m = WORK.search(p.stderr + p.stdout)
        if not m:
            return last
        last = float(m.group(1))
        limit = f"{last * 1.06:.3e}"
    return last


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", default="target/release/casteljau")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--markdown", action="store_true")
    a = ap.parse_args()
    # the process start and the reading of the arguments, which no estimate counts
    start = min(run(a.cli, ["eval", "--t", "1/2", "0 0, 1 1"], "1e15")[1] for _ in range(5))
    rows = []
    for name, args in CASES:
        if "{found}" in args:
            base = [x for x in args if x not in ("--against", "{found}")]
            found = subprocess.run([a.cli, *base], capture_output=True, text=True).stdout.strip()
            args = [found if x == "{found}" else x for x in args]
        est = estimate(a.cli, args)
        times = []
        for _ in range(a.repeat):
            p, dt = run(a.cli, args, "1e15")
            if p.returncode not in (0, 1):
                sys.exit(f"{name}: exit {p.returncode}: {p.stderr.strip()}")
            times.append(dt)
        measured = max(min(times) - start, 1e-4)
        ratio = est / 1e9 / measured if est else None
        rows.append((name, est, measured, ratio))
        if not a.markdown:
            print(f"{name}: estimate {est and est / 1e9:.3g} s, measured {measured:.3g} s, ratio {ratio and f'{ratio:.2f}'}", flush=True)
    if a.markdown:
        print("| case | estimate | measured | estimate / measured |")
        print("| --- | ---: | ---: | ---: |")
        for name, est, measured, ratio in rows:
            e = f"{est / 1e9:.3g} s" if est else "(none)"
            r = f"{ratio:.2f}" if ratio else "—"
            print(f"| {name} | {e} | {measured:.3g} s | {r} |")


if __name__ == "__main__":
    main()

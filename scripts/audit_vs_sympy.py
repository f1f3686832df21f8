#!/usr/bin/env python3
"""Side by side: `orthocheck audit --all` (every identity, /expanded included) against SymPy
verifying the same identities (the scripts `orthocheck audit --export all` writes), each run
in one Python process. A measuring tool, not a dependency.

usage: python3 scripts/audit_vs_sympy.py [--repeats N] [--binary target/release/orthocheck]
"""
import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--binary", default="target/release/orthocheck")
    a = ap.parse_args()
    ours = []
    for _ in range(a.repeats):
        t = time.perf_counter()
        subprocess.run([a.binary, "audit", "--all", "--json"], check=True, capture_output=True)
        ours.append(time.perf_counter() - t)
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "sympy"
        subprocess.run([a.binary, "audit", "--export", "all", "--out", str(out)], check=True,
                       capture_output=True)
        scripts = sorted(out.glob("*.py"))
        theirs = []
        for _ in range(a.repeats):
            t = time.perf_counter()
            for s in scripts:
                r = subprocess.run([sys.executable, str(s)], capture_output=True, text=True)
                if r.returncode != 0:
                    print("FAILED", s.name, r.stdout, r.stderr[-400:])
                print(f"  {time.perf_counter() - t:8.2f} s  {s.name}", flush=True)
            theirs.append(time.perf_counter() - t)
    o, s = statistics.median(ours), statistics.median(theirs)
    print(f"orthocheck audit --all: median {o:.3f} s of {ours}")
    print(f"SymPy, {len(scripts)} scripts: median {s:.1f} s of {theirs}")
    print(f"ratio: {s / o:.0f}x")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Time and peak memory of each command-line limit at its value (docs/limits.md): every
command run once on an input at the limit it declares. Build first: cargo build --release.

    python3 scripts/cli_limits.py

Peak memory is the process's maximum resident set (`os.wait4`'s ru_maxrss).
"""
import math
import os
import random
import subprocess
import sys
import tempfile
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.path.join(ROOT, "target", "release", "orthocheck")


def synth(d, name, *args):
    path = os.path.join(d, name)
    subprocess.run([BIN, "synth", *args, "--out", path], check=True, capture_output=True)
    return path


def turntable(d, name, points, frames, window, broken_chain=False):
    """Each point seen in `window` consecutive frames of a turntable (30° elevation), 0.2 %
    noise; first frames spread evenly. When the chain is to break, the frames are listed in
    a seeded random order: the chain of pairs of frames next to each other in the file then
    breaks, and variable projection starts at random, while the frames still link into one
    group (frames that pair off, sharing nothing with the rest, are refused before any
    work)."""
    g = random.Random(1)
    pts = [[g.uniform(-1, 1) for _ in range(3)] for _ in range(points)]
    first = [j * frames // points for j in range(points)]
    g.shuffle(first)
    label = list(range(1, frames + 1))
    if broken_chain:
        random.Random(2).shuffle(label)
    ce, se = math.cos(math.radians(30)), math.sin(math.radians(30))
    rows = []
    for f in range(frames):
        c, s = math.cos(2 * math.pi * f / frames), math.sin(2 * math.pi * f / frames)
        for j, (x, y, z) in enumerate(pts):
            if (f + frames - first[j]) % frames >= window:
                continue
            x1, z1 = c * x + s * z, -s * x + c * z
            n = 1 + g.uniform(-0.002, 0.002)
            rows.append((label[f], f"P{j + 1},{x1 * n:.9f},{(ce * y - se * z1) * n:.9f}"))
    rows.sort(key=lambda r: r[0])
    path = os.path.join(d, name)
    lines = ["frame,point,x,y"] + [f"{f},{rest}" for f, rest in rows]
    open(path, "w").write("\n".join(lines) + "\n")
    return path


def main():
    print("| limit | run | seconds | peak MiB |\n|---|---|---:|---:|")
    with tempfile.TemporaryDirectory() as d:
        two = synth(d, "two500.yaml", "--points", "500", "--frames", "2", "--seed", "1")
        runs = [
            ("DOF_POINTS_TIMES_FRAMES", ["dof", "--points", "200", "--frames", "5"]),
            ("DOF_GRID", ["dof", "--table", "--max-points", "20", "--max-frames", "20"]),
            ("SYNTH_POINTS_TIMES_FRAMES", ["synth", "--points", "1000", "--frames", "1000",
                                           "--seed", "1", "--format", "csv",
                                           "--out", os.path.join(d, "big.csv")]),
            ("FAMILY_POINTS_TIMES_SAMPLES", ["family", "--input", two, "--samples", "10000"]),
            ("NOISE_TRIALS (ex2-noise, one level)", ["noise", "--case", "ex2-noise",
                                                     "--levels", "0.01", "--trials", "1000000"]),
        ]
        for method, n in [("epipolar", 40), ("four", 20), ("five", 30)]:
            f = synth(d, f"id{n}{method}.yaml", "--points", str(n), "--frames", "2",
                      "--seed", "1", "--shuffle")
            runs.append((f"IDENTIFY_POINTS ({method})",
                         ["identify", "--input", f, "--method", method, "--top", "10000"]))
        m = synth(d, "m.csv", "--points", "50000", "--frames", "2", "--seed", "1",
                  "--format", "csv")
        runs.append(("MEMBERSHIP_POINTS", ["membership", "--input", m]))
        full = synth(d, "full.csv", "--points", "250", "--frames", "200", "--seed", "4",
                     "--noise", "0.01", "--format", "csv")
        runs.append(("BUNDLE_WORK, BUNDLE_FRAMES (250 × 200)", ["reconstruct", "--input", full]))
        gram = synth(d, "gram.csv", "--points", "1000", "--frames", "500", "--seed", "1",
                     "--noise", "0.001", "--format", "csv")
        runs.append(("RECONSTRUCT_GRAM (1000 × 500)", ["reconstruct", "--input", gram]))
        robust = synth(d, "robust.csv", "--points", "500", "--frames", "200", "--seed", "1",
                       "--noise", "0.001", "--format", "csv")
        runs.append(("RANSAC_OBSERVATIONS (500 × 200)", ["reconstruct", "--input", robust,
                                                         "--robust"]))
        for points, window in [(10_000, 2), (4_000, 5), (2_000, 10)]:
            g = turntable(d, f"robust{points}w{window}.csv", points, 100, window)
            runs.append((f"RANSAC_GAP_OBSERVATIONS ({points} points, {window} frames each of 100)",
                         ["reconstruct", "--input", g, "--robust"]))
        tt = turntable(d, "tt100k.csv", 100_000, 100, 2)
        runs.append(("VARPRO_WORK, BUNDLE_OBSERVATIONS (100,000 points, 2 frames each of 100)",
                     ["reconstruct", "--input", tt]))
        tb = turntable(d, "tt400.csv", 400, 100, 2, broken_chain=True)
        runs.append(("VARPRO_WORK, random starts (400 points, 2 frames each of 100)",
                     ["reconstruct", "--input", tb]))
        for what, args in runs:
            took, mib = measure(args)
            print(f"| {what} | `{' '.join(os.path.basename(a) for a in args)}` | {took:.2f} | {mib:.0f} |")
            sys.stdout.flush()


def measure(args):
    """Seconds and peak MiB, whatever the exit code (a warning exits 1)."""
    start = time.time()
    child = subprocess.Popen([BIN, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    code = os.waitstatus_to_exitcode(status)
    assert code in (0, 1), f"{args}: exit {code}: {child.stderr.read().decode()}"
    return time.time() - start, usage.ru_maxrss / 1024


if __name__ == "__main__":
    main()

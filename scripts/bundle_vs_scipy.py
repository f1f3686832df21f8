#!/usr/bin/env python3
"""Bundle adjustment side by side: orthocheck's against SciPy's least_squares with a sparse
Jacobian (the SciPy cookbook's bundle-adjustment recipe), from the same start on the same
tracks, in one run.

A measuring tool, not a dependency. Usage:
    scripts/bundle_vs_scipy.py TRACKS.csv [--orthocheck target/release/orthocheck] [--repeat R]
TRACKS.csv is a `frame,point,x,y` file (e.g. from `orthocheck synth --format csv`). The start
is orthocheck's own Tomasi-Kanade reconstruction (`reconstruct --no-bundle --json`); both
refine the same parameters: per frame a rotation R0 exp([w]x) (frame 1's held) and an image
translation, per point its position. Prints, per method, the median wall time of the
adjustment alone and the final cost 1/2 sum |r|^2.
"""
import argparse
import json
import statistics
import subprocess
import time

import numpy as np
from scipy.optimize import least_squares
from scipy.sparse import lil_matrix
from scipy.spatial.transform import Rotation


def read_tracks(path):
    rows = [l.strip().split(",") for l in open(path) if l.strip() and not l.startswith("#")]
    rows = [r for r in rows if r[0] != "frame"]
    frames = sorted({int(r[0]) for r in rows})
    names = list(dict.fromkeys(r[1] for r in rows))
    fi = {f: i for i, f in enumerate(frames)}
    pi = {n: i for i, n in enumerate(names)}
    cam = np.array([fi[int(r[0])] for r in rows])
    pt = np.array([pi[r[1]] for r in rows])
    y = np.array([[float(r[2]), float(r[3])] for r in rows])
    return names, len(frames), cam, pt, y


def run_orthocheck(binary, tracks, bundle):
    args = [binary, "reconstruct", "--input", tracks, "--json"]
    if not bundle:
        args.append("--no-bundle")
    t = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return time.perf_counter() - t, json.loads(out)


def start_of(rec, names):
    r0 = np.array([f["rotation"] for f in rec["frames"]])
    t0 = np.array([f["translation"] for f in rec["frames"]])
    x0 = np.array([rec["points"][n] for n in names])
    return r0, t0, x0


def residuals_fn(r0, k, p, cam, pt, y):
    def f(params):
        w = np.vstack([np.zeros(3), params[: 3 * (k - 1)].reshape(k - 1, 3)])
        t = params[3 * (k - 1): 3 * (k - 1) + 2 * k].reshape(k, 2)
        x = params[3 * (k - 1) + 2 * k:].reshape(p, 3)
        rots = np.einsum("kij,kjl->kil", r0, Rotation.from_rotvec(w).as_matrix())
        proj = np.einsum("nij,nj->ni", rots[cam, :2, :], x[pt]) + t[cam]
        return (proj - y).ravel()
    return f


def sparsity(k, p, cam, pt):
    m = 2 * len(cam)
    a = lil_matrix((m, 3 * (k - 1) + 2 * k + 3 * p), dtype=int)
    rows = np.arange(len(cam))
    for s in range(2):
        for c in range(3):
            keep = cam > 0
            a[2 * rows[keep] + s, 3 * (cam[keep] - 1) + c] = 1
        for c in range(2):
            a[2 * rows + s, 3 * (k - 1) + 2 * cam + c] = 1
        for c in range(3):
            a[2 * rows + s, 3 * (k - 1) + 2 * k + 3 * pt + c] = 1
    return a


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tracks")
    ap.add_argument("--orthocheck", default="target/release/orthocheck")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    names, k, cam, pt, y = read_tracks(a.tracks)
    p = len(names)
    t_tk, start = run_orthocheck(a.orthocheck, a.tracks, bundle=False)
    r0, t0, x0 = start_of(start, names)
    f = residuals_fn(r0, k, p, cam, pt, y)
    params0 = np.concatenate([np.zeros(3 * (k - 1)), t0.ravel(), x0.ravel()])
    jac = sparsity(k, p, cam, pt)
    print(f"{p} points, {k} frames, {len(cam)} observations; start cost {0.5 * np.sum(f(params0) ** 2):.10e}")
    # SciPy's default tolerances, then tolerances at rounding (it stops at max_nfev)
    for label, tol in [("default tolerances", 1e-8), ("tolerances 1e-15", 1e-15)]:
        times, res = [], None
        for _ in range(a.repeat):
            t = time.perf_counter()
            res = least_squares(f, params0, jac_sparsity=jac, x_scale="jac", ftol=tol,
                                xtol=tol, gtol=tol, method="trf", max_nfev=200)
            times.append(time.perf_counter() - t)
        print(f"scipy least_squares (trf, sparse jacobian, {label}): "
              f"{statistics.median(times):.3f} s, cost {res.cost:.10e}, {res.nfev} evaluations")
    full = [run_orthocheck(a.orthocheck, a.tracks, bundle=True) for _ in range(a.repeat)]
    secs = statistics.median(s for s, _ in full) - t_tk
    rec = full[0][1]
    cost = 0.5 * rec["rms"] ** 2 * len(cam)
    print(f"orthocheck bundle_adjust: {secs:.3f} s (whole command less the --no-bundle run), "
          f"cost {cost:.10e}, {rec['iterations']} iterations")


if __name__ == "__main__":
    main()

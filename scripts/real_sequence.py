"""`reconstruct --robust` and `membership` on a real turntable sequence, judged by the
sequence's own calibrated cameras (docs/limits.md, "A real sequence").

    python3 scripts/real_sequence.py TRACKS CAMERAS [OUTDIR]

TRACKS: one track per line, `x1 y1 … xF yF` in pixels, `-1 -1` where unseen (the Oxford
dinosaur's `viff.xy`); CAMERAS: F projection matrices, three lines each, `#` lines skipped
(`real_turntable`'s format). Needs NumPy and a release build (`cargo build --release`).

The cameras triangulate each track (linear least squares) and give each image its true
reprojection error (each frame's mean square over the median frame's is printed) and each
pair of consecutive frames its true epipolar distances (the fundamental matrix of the two
cameras). Written and run:
- OUTDIR/tracks.csv, the whole sequence, and `reconstruct --robust --json` on it: of the
  observations the cameras put beyond 1, 2, 3, 5 px, the share dropped, and of those within,
  the share dropped;
- OUTDIR/pair_F.csv, the points of frames F and F + 1, and `membership --json` on each: the
  members rejected among points whose true epipolar distance is within 1 px, 1–3 px, beyond
  3 px, and the pairs refused.
"""

import json
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "target", "release", "orthocheck")


def load(tracks, cameras):
    v = np.loadtxt(tracks)
    rows = [l for l in open(cameras) if l.strip() and not l.startswith("#")]
    p = np.array([[float(x) for x in l.split()] for l in rows]).reshape(-1, 3, 4)
    assert p.shape[0] * 2 == v.shape[1], "one camera per frame"
    return v, p


def seen(v, f):
    return v[:, 2 * f] != -1


def triangulate(v, p):
    out = []
    for r in v:
        a = []
        for f in range(p.shape[0]):
            if r[2 * f] != -1:
                a += [r[2 * f] * p[f][2] - p[f][0], r[2 * f + 1] * p[f][2] - p[f][1]]
        a = np.array(a)
        w, vec = np.linalg.eigh(a.T @ a)
        out.append(vec[:, 0] / vec[3, 0])
    return np.array(out)


def run(args):
    out = subprocess.run([BIN] + args, capture_output=True, text=True)
    return out.returncode, out.stdout, out.stderr


def robust(v, p, x, outdir):
    path = os.path.join(outdir, "tracks.csv")
    with open(path, "w") as o:
        o.write("frame,point,x,y\n")
        for f in range(p.shape[0]):
            for j in np.nonzero(seen(v, f))[0]:
                o.write(f"{f + 1},T{j + 1},{v[j, 2 * f]},{v[j, 2 * f + 1]}\n")
    code, stdout, stderr = run(["reconstruct", "--robust", "--json", "--input", path])
    print(f"reconstruct --robust: exit {code} {stderr.strip()[:200]}")
    if not stdout.strip():
        return
    d = json.loads(stdout)
    dropped = {(o["point"], o["frame"]) for o in d["dropped"]}
    err, hit = [], []
    for f in range(p.shape[0]):
        for j in np.nonzero(seen(v, f))[0]:
            h = p[f] @ x[j]
            err.append(np.hypot(h[0] / h[2] - v[j, 2 * f], h[1] / h[2] - v[j, 2 * f + 1]))
            hit.append((f"T{j + 1}", f + 1) in dropped)
    err, hit = np.array(err), np.array(hit)
    print(
        f"  {hit.sum()} of {len(hit)} observations dropped, threshold "
        f"{d['threshold']['value']:.4g} px, {len(d['rejected'])} points rejected whole; "
        f"rms {d['rms']:.4g} px; warnings {len(d['warnings'])}"
    )
    whole = set(d["rejected"])
    print(f"  of the dropped, {sum(1 for o in d['dropped'] if o['point'] in whole)} are images of points rejected whole")
    for t in [1, 2, 3, 5]:
        bad = err > t
        print(
            f"  true error > {t} px: {bad.sum()}, dropped {100 * hit[bad].mean():.1f} %; "
            f"within: {(~bad).sum()}, dropped {100 * hit[~bad].mean():.2f} %"
        )


def frames(v, p, x):
    """Each frame's mean squared reprojection error under the cameras, over the median's."""
    ms = []
    for f in range(p.shape[0]):
        e = []
        for j in np.nonzero(seen(v, f))[0]:
            h = p[f] @ x[j]
            e.append((h[0] / h[2] - v[j, 2 * f]) ** 2 + (h[1] / h[2] - v[j, 2 * f + 1]) ** 2)
        ms.append(np.mean(e))
    med = np.median(ms)
    worst = sorted(range(len(ms)), key=lambda f: -ms[f])[:5]
    print("frames that fit worst under the cameras (mean squared error over the median's): "
          + ", ".join(f"{f + 1} ({ms[f] / med:.2f}x)" for f in worst))


def fundamental(p1, p2):
    c = np.linalg.svd(p1)[2][-1]
    e = p2 @ c
    skew = np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    return skew @ p2 @ np.linalg.pinv(p1)


def membership(v, p, outdir):
    bands = {"within 1 px": [0, 0], "1-3 px": [0, 0], "beyond 3 px": [0, 0]}
    refused, pairs = [], 0
    for f in range(p.shape[0] - 1):
        both = np.nonzero(seen(v, f) & seen(v, f + 1))[0]
        if len(both) < 4:
            continue
        pairs += 1
        path = os.path.join(outdir, f"pair_{f + 1}.csv")
        with open(path, "w") as o:
            o.write("frame,point,x,y\n")
            for k, g in enumerate((f, f + 1)):
                for j in both:
                    o.write(f"{k + 1},T{j + 1},{v[j, 2 * g]},{v[j, 2 * g + 1]}\n")
        code, stdout, stderr = run(["membership", "--json", "--input", path])
        if code != 0:
            refused.append((f + 1, stderr.strip()[:80]))
            continue
        member = {o["point"]: o["member"] for o in json.loads(stdout)}
        fm = fundamental(p[f], p[f + 1])
        for j in both:
            x1 = np.array([v[j, 2 * f], v[j, 2 * f + 1], 1.0])
            x2 = np.array([v[j, 2 * f + 2], v[j, 2 * f + 3], 1.0])
            line = fm @ x1
            e = abs(x2 @ line) / np.hypot(line[0], line[1])
            band = "within 1 px" if e <= 1 else "1-3 px" if e <= 3 else "beyond 3 px"
            bands[band][0] += 1
            bands[band][1] += not member[f"T{j + 1}"]
    print(f"membership on {pairs} pairs of consecutive frames: {len(refused)} refused")
    for f, why in refused:
        print(f"  pair {f}: {why}")
    for band, (n, r) in bands.items():
        share = 100 * r / n if n else float("nan")
        print(f"  true epipolar distance {band}: {n} points, {r} rejected ({share:.2f} %)")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    v, p = load(sys.argv[1], sys.argv[2])
    outdir = sys.argv[3] if len(sys.argv) > 3 else "/tmp/real_sequence"
    os.makedirs(outdir, exist_ok=True)
    x = triangulate(v, p)
    frames(v, p, x)
    robust(v, p, x, outdir)
    membership(v, p, outdir)


if __name__ == "__main__":
    main()

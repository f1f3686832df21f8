"""Task D(2): rounding analysis restricted to EXACT projections of the printed body (2,3,4).
A frame's projection is exact iff some rotation maps the body onto it: with P at the origin,
q = image of Q, r = image of R, depths zQ = s_Q sqrt(4-|q|^2), zR = s_R sqrt(16-|r|^2),
and (zR - zQ)^2 = 9 - |r-q|^2 (rotations <-> (q, r, signs) up to the mirror in the image plane).
Keep those whose q, r round to the printed figure (+-0.005; P exactly at the origin as printed).
Compare the range of the second solution with the unrestricted +-0.005 box."""
import numpy as np
from scipy.optimize import brentq, minimize
from d_common import *
rng = np.random.default_rng(7)
H = 0.005

def g(q, r, sg):
    return (sg*np.sqrt(max(16 - r@r, 0)) - np.sqrt(max(4 - q@q, 0)))**2 - (9 - (r-q)@(r-q))

def sample_frame(k, n, sg=1):
    """uniform (qx,qy,rx) in the box, r_y solved on the exact-projection manifold (if in box)"""
    F = FIG[k]; out = []
    tries = 0
    while len(out) < n and tries < 200*n:
        tries += 1
        q = F[1] + rng.uniform(-H, H, 2); rx = F[2, 0] + rng.uniform(-H, H)
        f = lambda ry: g(q, np.array([rx, ry]), sg)
        lo, hi = F[2, 1]-H, F[2, 1]+H
        if f(lo)*f(hi) > 0: continue
        ry = brentq(f, lo, hi, xtol=1e-14)
        out.append(np.array([[0, 0], q, [rx, ry]]))
    return np.array(out), tries

def second(Fs):
    _, disc, sols = solve_sq(np.array([proj_sq(F) for F in Fs]))
    if disc < 0: return None, disc
    # the root other than the true (4,9,16) one: pick the one farther from c^2=16
    s = [np.real(x) for x in sols]
    i = int(np.argmax([abs(x[2]-16) for x in s]))
    return s[i], disc, s[1-i]

frames = []
for k in range(3):
    S, tries = sample_frame(k, 4000)
    frames.append(S)
    print(f"frame {k+1}: {len(S)} exact projections kept of {tries} tries "
          f"(acceptance {len(S)/tries:.3f}); ranges of the squared projections:")
    sq = np.array([proj_sq(F) for F in S])
    print("   a_i^2 [%.5f, %.5f]  b_i^2 [%.5f, %.5f]  c_i^2 [%.5f, %.5f]" % tuple(
        v for j in range(3) for v in (sq[:, j].min(), sq[:, j].max())))
np.save("d2_frames.npy", np.array(frames, dtype=object), allow_pickle=True)

# Monte Carlo over the restricted product set
N = 40000
res, discs, trues = [], [], []
for t in range(N):
    Fs = [frames[k][rng.integers(len(frames[k]))] for k in range(3)]
    out = second(Fs)
    if out[0] is None: discs.append(out[1]); continue
    res.append(out[0]); discs.append(out[1]); trues.append(out[2])
res = np.array(res); trues = np.array(trues)
print(f"\nRESTRICTED (exact projections): {len(res)}/{N} real; discriminant range [{min(discs):.4g}, {max(discs):.4g}]")
print("  true root reproduced: max |(a2,b2,c2)-(4,9,16)| =", np.max(np.abs(trues - [4, 9, 16])))
for j, n in enumerate(['a^2', 'b^2', 'c^2']):
    print(f"  second solution {n}: [{res[:, j].min():.5f}, {res[:, j].max():.5f}]   printed {SOL2[j]}")
feas = np.all(res > 0, axis=1)
print("  fraction with all squares positive:", feas.mean())
np.save("d2_restricted_mc.npy", res)

# UNRESTRICTED box: q, r of each frame uniform in the +-0.005 box
res_u, nreal, first_u = [], 0, []
for t in range(N):
    Fs = FIG + np.concatenate([np.zeros((3, 1, 2)), rng.uniform(-H, H, (3, 2, 2))], axis=1)
    _, disc, sols = solve_sq(np.array([proj_sq(F) for F in Fs]))
    if disc < 0: continue
    nreal += 1
    s = sorted([np.real(x) for x in sols], key=lambda x: x[2])
    res_u.append(np.concatenate(s))
res_u = np.array(res_u)
print(f"\nUNRESTRICTED box: {nreal}/{N} real (disc >= 0)")
for j, n in enumerate(['a^2', 'b^2', 'c^2']):
    print(f"  smaller-c^2 root {n}: [{res_u[:, j].min():.4f}, {res_u[:, j].max():.4f}]   "
          f"larger-c^2 root {n}: [{res_u[:, 3+j].min():.4f}, {res_u[:, 3+j].max():.4f}]")
np.save("d2_unrestricted_mc.npy", res_u)

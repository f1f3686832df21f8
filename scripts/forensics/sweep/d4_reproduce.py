"""Task D(4): an exact configuration (projections of the body (2,3,4) rounding to the figure) whose
second solution is the printed (2.6849, 8.33902, 16.2189): parametrise each frame by (qx,qy,rx)
in the box, r_y solved on the exact-projection manifold (same-sign depths, as the figure implies)."""
import numpy as np
from scipy.optimize import brentq, minimize
from d_common import *
H = 0.005
def ry_of(k, q, rx):
    F = FIG[k]
    f = lambda ry: (np.sqrt(max(16 - rx*rx - ry*ry, 0)) - np.sqrt(4 - q@q))**2 - (9 - (rx-q[0])**2 - (ry-q[1])**2)
    lo, hi = F[2, 1]-H, F[2, 1]+H
    if f(lo)*f(hi) > 0: return None
    return brentq(f, lo, hi, xtol=1e-15)
def frames_of(u):
    u = np.clip(u, -1, 1); out = []
    for k in range(3):
        q = FIG[k, 1] + H*u[3*k:3*k+2]; rx = FIG[k, 2, 0] + H*u[3*k+2]
        ry = ry_of(k, q, rx)
        if ry is None: return None
        out.append([[0, 0], q, [rx, ry]])
    return np.array(out)
def sols(u):
    F = frames_of(u)
    if F is None: return None
    _, disc, s = solve_sq(np.array([proj_sq(f) for f in F]))
    s = [np.real(v) for v in s]; d = [np.linalg.norm(v-[4, 9, 16]) for v in s]
    return s[int(np.argmax(d))], s[int(np.argmin(d))], disc, F
W = np.array([5e-5, 5e-6, 5e-5])
def obj(u):
    o = sols(u)
    if o is None: return 1e12
    return np.sum(((o[0]-SOL2)/W)**2)
rng = np.random.default_rng(3); best = None
for s in range(40):
    r = minimize(obj, rng.uniform(-0.9, 0.9, 9), method='Nelder-Mead',
                 options={'maxiter': 20000, 'xatol': 1e-10, 'fatol': 1e-12})
    if best is None or r.fun < best.fun: best = r
s2, s1, disc, F = sols(best.x)
print("second solution:", np.round(s2, 6), "printed", SOL2, " misfit (half-units):", np.round((s2-SOL2)/W, 3))
print("first solution:", np.round(s1, 9), " disc", disc)
print("projections (P,Q,R per frame):", np.round(F, 6).tolist())
print("figure shifts (units of 0.005):", np.round((F - FIG)/H, 3)[:, 1:].tolist())

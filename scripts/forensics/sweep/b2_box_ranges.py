"""Task B(2): is the printed matrix reachable from the figure within its +-0.005 rounding box?
For each nonzero coefficient: exact range over the box (each coefficient is a polynomial in 24
coordinates; we maximise/minimise it with SLSQP from many starts; bounds are tight since the
polynomials are low degree), then a joint feasibility test: one point of the box reproducing all 18
printed coefficients to their printed rounding."""
import numpy as np
from scipy.optimize import minimize, linprog
from b_common import *
f0 = FIG.ravel()
def coef(f):
    return rows(f.reshape(3,4,2))
NZ = np.argwhere(MAT != 0)
bounds = [(v-0.005, v+0.005) for v in f0]
rng = np.random.default_rng(1)
res = []
for (i, j) in NZ:
    lo, hi = np.inf, -np.inf
    for s in range(6):
        st = f0 + rng.uniform(-0.005, 0.005, f0.size)
        r1 = minimize(lambda f: coef(f)[i, j], st, bounds=bounds, method='L-BFGS-B')
        r2 = minimize(lambda f: -coef(f)[i, j], st, bounds=bounds, method='L-BFGS-B')
        lo, hi = min(lo, r1.fun), max(hi, -r2.fun)
    p = MAT[i, j]
    inside = lo - HU[i, j] <= p <= hi + HU[i, j]
    gap = 0 if inside else (lo - p if p < lo else p - hi)
    res.append((i, j, p, lo, hi, inside, gap/HU[i, j]))
    print(f"row {i+1} col {j+1 if j<6 else '1'}: printed {p:>10} box range [{lo:.5f}, {hi:.5f}]  "
          f"{'inside' if inside else 'OUTSIDE by %.0f half-units' % (gap/HU[i,j])}")
print("inside:", sum(r[5] for r in res), "of", len(res))
# joint: minimise the max normalised coefficient misfit over the box
def worst(f):
    C = coef(f)
    return np.max(np.abs((C - MAT)[MAT != 0] / HU[MAT != 0]))
best = None
for s in range(20):
    st = f0 + rng.uniform(-0.005, 0.005, f0.size)
    # smooth surrogate: sum of squares then polish
    r = minimize(lambda f: np.sum(((coef(f) - MAT)[MAT != 0] / HU[MAT != 0])**2), st,
                 bounds=bounds, method='L-BFGS-B')
    if best is None or r.fun < best.fun: best = r
print("joint least-squares over the box: sum sq (half-units) =", best.fun,
      " worst coefficient misfit =", worst(best.x), "half-units")
C = coef(best.x)
print(np.where(MAT != 0, np.round((C-MAT)/HU, 0), 0))

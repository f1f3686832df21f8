"""Task B(2b): joint minimax over the figure's rounding box: min t s.t. |coef - printed| <= t*HU."""
import numpy as np
from scipy.optimize import minimize
from b_common import *
f0 = FIG.ravel(); NZm = MAT != 0
def coef(f): return rows(f.reshape(3, 4, 2))
for name, H in (("last printed digit", HU), ("6 significant digits", HU6)):
    best = None
    rng = np.random.default_rng(2)
    for s in range(10):
        z0 = np.concatenate([f0 + rng.uniform(-0.004, 0.004, f0.size), [50.0]])
        cons = [{'type': 'ineq', 'fun': lambda z, H=H: z[-1] - ((coef(z[:-1]) - MAT)[NZm] / H[NZm])},
                {'type': 'ineq', 'fun': lambda z, H=H: z[-1] + ((coef(z[:-1]) - MAT)[NZm] / H[NZm])}]
        bnds = [(v - 0.005, v + 0.005) for v in f0] + [(0, None)]
        r = minimize(lambda z: z[-1], z0, method='SLSQP', bounds=bnds, constraints=cons,
                     options={'maxiter': 500, 'ftol': 1e-12})
        w = np.max(np.abs((coef(r.x[:-1]) - MAT)[NZm] / H[NZm]))
        if best is None or w < best[0]: best = (w, r.x[:-1])
    print(f"[{name}] best worst-case coefficient misfit inside the box: {best[0]:.3f} half-units")
    print("   figure shifts used (units of 0.005):", np.round((best[1] - f0) / 0.005, 2).reshape(3, 8))
    np.save(f"b3_box_point_{'6sig' if H is HU6 else 'last'}.npy", best[1])

"""Task B(3b): minimax version of the joint exact fit.  Variables: 3 cameras (rotation vector +
2-D translation) and the six squared edges, each confined to the interval allowed by the table's
printed length AND printed square (6 significant digits).  Minimises t subject to
|figure dev| <= t*0.005 and |coef dev| <= t*half-unit (SLSQP), from the least-squares fit."""
import numpy as np
from scipy.optimize import minimize, least_squares
from b_common import *
from b4_exact_fit import body, project, init_frame, XT

def interval(length, square):
    """squared-edge interval consistent with a printed length and a printed square (%g, 6 digits)"""
    hl = half_unit_6sig(length); hs = half_unit_6sig(square)
    lo = max((length - hl)**2, square - hs); hi = min((length + hl)**2, square + hs)
    return lo, hi
TAB = [(2, 4), (3, 9), (3.562, 12.6878), (7.07107, 50), (7.43303, 55.25), (5.82734, 33.9578)]
IV = [interval(*t) for t in TAB]
NZm = MAT != 0

def resid(z, H, mirror):
    p, x = z[:15], z[15:21]
    B = body(x, mirror)
    F = project(p, B)
    return np.concatenate([(F - FIG).ravel() / 0.005, ((rows(F) - MAT)[NZm]) / H[NZm]])

def run(H, mirror, fix_edges=False):
    x0 = np.array([(lo+hi)/2 for lo, hi in IV])
    B = body(x0, mirror)
    p0 = np.concatenate([init_frame(B, FIG[k]) for k in range(3)])
    z0 = np.concatenate([p0, x0])
    bl = [-np.inf]*15 + [lo for lo, hi in IV]; bu = [np.inf]*15 + [hi for lo, hi in IV]
    if fix_edges:
        bl[15:] = [v - 1e-12 for v in x0]; bu[15:] = [v + 1e-12 for v in x0]
    r = least_squares(lambda z: resid(z, H, mirror), z0, bounds=(bl, bu), x_scale='jac')
    z = r.x
    # minimax by successive L_p (p = 4 .. 64) then SLSQP polish
    for pw in (4, 8, 16, 32, 64):
        m = minimize(lambda z: np.sum(np.abs(resid(z, H, mirror))**pw)**(1/pw), z, method='L-BFGS-B',
                     bounds=list(zip(bl, bu)), options={'maxiter': 3000})
        z = m.x
    t0 = np.max(np.abs(resid(z, H, mirror)))
    cons = [{'type': 'ineq', 'fun': lambda w: w[-1] - resid(w[:-1], H, mirror)},
            {'type': 'ineq', 'fun': lambda w: w[-1] + resid(w[:-1], H, mirror)}]
    m = minimize(lambda w: w[-1], np.concatenate([z, [t0]]), method='SLSQP', constraints=cons,
                 bounds=list(zip(bl, bu)) + [(0, None)], options={'maxiter': 2000, 'ftol': 1e-15})
    if np.max(np.abs(resid(m.x[:-1], H, mirror))) < t0: z = m.x[:-1]
    return z, r

if __name__ == "__main__":
    np.set_printoptions(linewidth=200, suppress=True)
    print("edge intervals:", [(round(lo, 7), round(hi, 7)) for lo, hi in IV])
    for fix in (True, False):
        for mirror in (False, True):
            for name, H in (("last printed digit", HU), ("6th significant digit", HU6)):
                z, r = run(H, mirror, fix)
                res = resid(z, H, mirror)
                print(f"=== edges {'fixed at interval centres' if fix else 'free in intervals'}, mirror={mirror}, "
                      f"half-unit={name}: max|fig| {np.max(np.abs(res[:24])):.3f} (x0.005), "
                      f"max|coef| {np.max(np.abs(res[24:])):.3f} half-units")
                if not mirror and not fix:
                    print(" figure deviations (units of 0.005), rows=frames, cols=Px,Py,Qx,Qy,Rx,Ry,Tx,Ty:")
                    print(np.round(res[:24].reshape(3, 8), 3))
                    C = np.zeros_like(MAT); C[NZm] = res[24:]
                    print(" coefficient deviations (half-units):"); print(np.round(C, 3))
                    print(" squared edges:", np.round(z[15:], 7))
                    B = body(z[15:], mirror); F = project(z[:15], B)
                    print(" projections:", np.round(F, 5).tolist())
                    print(" coefficients:"); print(np.round(rows(F), 6))
                    np.save(f"b5_z_{'last' if H is HU else '6sig'}.npy", z)

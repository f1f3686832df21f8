"""Task B(3): one exact configuration -- rigid body with the table's edge lengths and three
orthographic cameras (rotation + 2-D translation) -- fitted jointly to the figure (+-0.005) and the
24 nonzero printed coefficients (18 x-coefficients + 6 constants; half-units of the last printed
digit, and of the 6th significant digit).  Objective: minimax of the normalised residuals
(figure residual / 0.005 and coefficient residual / half-unit), via SLSQP on t."""
import numpy as np
from scipy.optimize import minimize, least_squares
from scipy.spatial.transform import Rotation as Rot
from b_common import *

def body(x, mirror=False):
    """tetrahedron P,Q,R,T from squared edges x = (PQ,QR,RP,TP,TQ,TR)^2"""
    a2, b2, c2, f2, g2, d2 = x
    P = np.zeros(3); Q = np.array([np.sqrt(a2), 0, 0])
    rx = (a2 + c2 - b2) / (2*np.sqrt(a2)); ry = np.sqrt(c2 - rx*rx); R = np.array([rx, ry, 0])
    tx = (a2 + f2 - g2) / (2*np.sqrt(a2))
    ty = (f2 - d2 + rx*rx + ry*ry - 2*tx*rx) / (2*ry)
    tz = np.sqrt(f2 - tx*tx - ty*ty)
    T = np.array([tx, ty, -tz if mirror else tz])
    return np.array([P, Q, R, T])
XT = np.array([4, 9, 3.562**2, 50, 55.25, 33.9578])   # c = 3.562 (c^2 = 12.687844), others as printed

def project(params, B):
    out = []
    for k in range(3):
        rv, t = params[5*k:5*k+3], params[5*k+3:5*k+5]
        M = Rot.from_rotvec(rv).as_matrix()[:2]
        out.append(B @ M.T + t)
    return np.array(out)

NZm = MAT != 0
def residuals(params, B, H):
    F = project(params, B)
    rf = (F - FIG).ravel() / 0.005
    rc = ((rows(F) - MAT)[NZm]) / H[NZm]
    return np.concatenate([rf, rc])

def init_frame(B, F):
    Bc = B - B.mean(0); Fc = F - F.mean(0)
    M, *_ = np.linalg.lstsq(Bc, Fc, rcond=None)   # 3x2
    M = M.T
    U, S, Vt = np.linalg.svd(M, full_matrices=False)
    M2 = U @ Vt
    r3 = np.cross(M2[0], M2[1]); Rm = np.array([M2[0], M2[1], r3])
    rv = Rot.from_matrix(Rm).as_rotvec()
    t = F.mean(0) - B.mean(0) @ M2.T
    return np.concatenate([rv, t])

def fit(H, mirror, x=XT, verbose=True):
    B = body(x, mirror)
    p0 = np.concatenate([init_frame(B, FIG[k]) for k in range(3)])
    # figure-only start, then joint least squares, then minimax
    r = least_squares(lambda p: residuals(p, B, H)[:24], p0)
    r = least_squares(lambda p: residuals(p, B, H), r.x)
    z0 = np.concatenate([r.x, [np.max(np.abs(residuals(r.x, B, H)))]])
    cons = [{'type': 'ineq', 'fun': lambda z: z[-1] - residuals(z[:-1], B, H)},
            {'type': 'ineq', 'fun': lambda z: z[-1] + residuals(z[:-1], B, H)}]
    m = minimize(lambda z: z[-1], z0, method='SLSQP', constraints=cons,
                 options={'maxiter': 1000, 'ftol': 1e-14})
    p = m.x[:-1] if np.max(np.abs(residuals(m.x[:-1], B, H))) < z0[-1] else r.x
    return p, B, r

if __name__ == "__main__":
    np.set_printoptions(linewidth=200, suppress=True)
    for mirror in (False, True):
        for name, H in (("last printed digit", HU), ("6th significant digit", HU6)):
            p, B, r = fit(H, mirror)
            res = residuals(p, B, H)
            rfig, rco = res[:24], res[24:]
            print(f"=== mirror={mirror}, coefficient half-unit = {name}: LS cost {r.cost:.3f}")
            print(" max |fig dev| (units 0.005): %.3f   max |coef dev| (half-units): %.3f" % (
                np.max(np.abs(rfig)), np.max(np.abs(rco))))
            if not mirror:
                print(" figure deviations (units of 0.005), frames x (P,Q,R,T) x (x,y):")
                print(np.round(rfig.reshape(3, 8), 3))
                C = np.zeros_like(MAT); C[NZm] = rco
                print(" coefficient deviations (half-units), 6x7:")
                print(np.round(C, 3))
                F = project(p, B)
                print(" fitted projections:\n", np.round(F, 5))
                Cf = rows(F)
                print(" fitted coefficients:\n", np.round(Cf, 6))
                xs = np.linalg.solve(Cf[:, :6], -Cf[:, 6]); print(" solution of fitted system:", xs)
                for k in range(3):
                    Rm = Rot.from_rotvec(p[5*k:5*k+3]).as_matrix()
                    print(f" camera {k+1}: view direction (3rd row) {np.round(Rm[2], 5)}, t = {np.round(p[5*k+3:5*k+5], 5)}")
                np.save(f"b4_params_{'last' if H is HU else '6sig'}.npy", p)

"""Task C(2): which member of the one-parameter family the printed coordinates and the figures show.
Construction (lines 926-946) in the frame the figures use: frame-1 rays along x, n along z through P,
frame-2 rays along u = (cos phi, sin phi, 0); rotating the frame-2 rays by theta about n gives
u' = R(theta) u; Q' = q1 ∩ R(theta) q2  <=>  R(-theta) Q' - Q  parallel to u (xy-parts), same for R'."""
import numpy as np
from scipy.optimize import brentq
P = np.zeros(3); Q = np.array([3.46537, 2, -2]); R = np.array([.68697, 5, 4])
Qp = np.array([4.63902, 2, -2]); Rp = np.array([4.37296, 5, 4])
def rot(t):
    c, s = np.cos(t), np.sin(t); return np.array([[c, -s], [s, c]])
def cr(a, b): return a[0]*b[1] - a[1]*b[0]
def rebuild(phi, theta):
    """Q', R' from P, Q, R, phi, theta: Q' = (x, Qy, Qz) with R(-theta)(x,Qy) - Q_xy parallel to u"""
    u = np.array([np.cos(phi), np.sin(phi)]); out = []
    for X in (Q, R):
        # R(-theta)(x, y) - X_xy = t u  ->  (x, y) = R(theta)(X_xy + t u); y fixed -> solve t, then x
        w = rot(theta) @ u; base = rot(theta) @ X[:2]
        t = (X[1] - base[1]) / w[1]; out.append(np.array([base[0] + t*w[0], X[1], X[2]]))
    return out
# 1) the member fixed by the printed coordinates
f = lambda th: cr(rot(-th) @ Qp[:2] - Q[:2], rot(-th) @ Rp[:2] - R[:2])
ths = np.radians(np.linspace(-179, 179, 3581)); vals = [f(t) for t in ths]
roots = [brentq(f, ths[i], ths[i+1]) for i in range(len(ths)-1) if vals[i]*vals[i+1] < 0]
print("theta roots (deg):", np.round(np.degrees(roots), 5))
for th in roots:
    v = rot(-th) @ Qp[:2] - Q[:2]; phi = np.arctan2(v[1], v[0])
    print(f"  theta = {np.degrees(th):.5f} deg, phi = {np.degrees(phi) % 180:.5f} deg (mod 180), "
          f"phi' = phi + theta = {np.degrees(phi+th) % 180:.5f} deg")
# 2) the member drawn: phi and phi' from the four pictures (c_fit.py)
fit = np.load("c_fit.npy", allow_pickle=True).item()
phis = {k: np.degrees(fit[k]['phi']) % 180 for k in fit}
print("ray directions fitted in the pictures (deg, mod 180):", {k+1: round(v, 3) for k, v in phis.items()})
phi_fig = np.radians(np.mean([phis[0], phis[1]])); phi2_fig = np.radians(np.mean([phis[2], phis[3]]))
th_fig = phi2_fig - phi_fig
print(f"figure member: phi = {np.degrees(phi_fig):.3f}, phi' = {np.degrees(phi2_fig):.3f}, theta = {np.degrees(th_fig):.3f} deg")
for name, (ph, th) in {"figure member": (phi_fig, th_fig)}.items():
    q, r = rebuild(ph, th)
    print(f"  rebuilt from the {name}: Q' = {np.round(q, 5)}, R' = {np.round(r, 5)};"
          f" dev Q'x {q[0]-Qp[0]:+.4f}, R'x {r[0]-Rp[0]:+.4f}")
# sensitivity of Q'x, R'x to phi and theta (per degree)
th0 = [t for t in roots if abs(np.degrees(t)) > 1][0]
v = rot(-th0) @ Qp[:2] - Q[:2]; ph0 = np.arctan2(v[1], v[0])
q0, r0 = rebuild(ph0, th0); h = np.radians(1e-3)
dq = [(rebuild(ph0+h, th0)[0][0]-q0[0])/1e-3, (rebuild(ph0, th0+h)[0][0]-q0[0])/1e-3]
dr = [(rebuild(ph0+h, th0)[1][0]-r0[0])/1e-3, (rebuild(ph0, th0+h)[1][0]-r0[0])/1e-3]
print(f"exact member: rebuilt Q' {np.round(q0, 6)}, R' {np.round(r0, 6)}")
print(f"d(Q'x)/d(phi, theta) = {np.round(dq, 4)} per deg; d(R'x)/d(phi, theta) = {np.round(dr, 4)} per deg")
# round-number candidates near the exact member
for phd in (118.5, 118.6, 118.65, 118.7, 120):
    for thd in (-43, -42.9, -42.95, -45):
        q, r = rebuild(np.radians(phd), np.radians(thd))
        print(f"   phi {phd}, theta {thd}: Q'x {q[0]:.5f} R'x {r[0]:.5f}")
# the image of frame 2 before/after: check invariance claim (distances of projections)
def proj2(X, u):
    U = np.array([u[0], u[1], 0]); e1 = np.array([-u[1], u[0], 0]); e2 = np.array([0, 0, 1.])
    return np.array([X@e1, X@e2])
u = np.array([np.cos(ph0), np.sin(ph0)]); u2 = rot(th0) @ u
A = [proj2(X, u) for X in (P, Q, R)]; B = [proj2(X, u2) for X in (P, Qp, Rp)]
dA = [np.linalg.norm(A[i]-A[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
dB = [np.linalg.norm(B[i]-B[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
print("frame-2 projected edge lengths: PQR along u:", np.round(dA, 6), " PQ'R' along u':", np.round(dB, 6))
print("frame-1 projected edge lengths equal trivially (x-rays): PQR", np.round([np.linalg.norm((Q-P)[1:]), np.linalg.norm((R-Q)[1:]), np.linalg.norm((P-R)[1:])], 6))
print("3-D edge lengths PQR:", np.round([np.linalg.norm(Q-P), np.linalg.norm(R-Q), np.linalg.norm(P-R)], 5),
      " PQ'R':", np.round([np.linalg.norm(Qp-P), np.linalg.norm(Rp-Qp), np.linalg.norm(P-Rp)], 5))

"""Model of the author's program for one block: chosen d^2, version (sign of b), assignment."""
import numpy as np
from core import *

def depth_signs(d2, b2, g2, T, Q):
    """frame depths: zT = +sqrt(d2-|T|^2) (flag 1), zQ = s*sqrt(b2-|Q|^2), s chosen so that the
    triangle closes: |zT - zQ|^2 = g2 - |T-Q|^2 (the sign whose residual is smaller)."""
    zT = np.sqrt(max(d2 - T @ T, 0.0)); aQ = np.sqrt(max(b2 - Q @ Q, 0.0))
    gz2 = g2 - (T - Q) @ (T - Q)
    rp = abs((zT - aQ)**2 - gz2); rm = abs((zT + aQ)**2 - gz2)
    s = 1 if rp <= rm else -1
    return zT, aQ, 1, s

def run_block(a, d2, version, f1=None, f2=None):
    f1 = f1 or F1; f2 = f2 or F2
    s1 = proj_sq(f1, ID); s2 = proj_sq(f2, a)
    disc, r, f = b_roots(s1, s2, d2)
    if version not in r: return None
    b2 = r[version]; g2 = a2_of(f, b2, d2)
    P1, Q1, T1 = frame_pts(f1, ID)
    P2, Q2, T2 = frame_pts(f2, a)
    zT1, aQ1, fT1, fQ1 = depth_signs(d2, b2, g2, T1, Q1)
    zT2, aQ2, fT2, fQ2 = depth_signs(d2, b2, g2, T2, Q2)
    e1 = np.array([T1[0], T1[1], fT1 * zT1]); e2 = np.array([Q1[0], Q1[1], fQ1 * aQ1])
    e3 = np.cross(e1, e2)
    M = np.column_stack([e1, e2, e3])
    # T_a, T_b: point (P1, z) with gamma = 0 and gamma = 1
    # alpha T1 + beta Q1 = P1 - gamma e3.xy
    M2 = np.column_stack([T1, Q1])
    PaK = np.r_[np.linalg.solve(M2, P1), 0.0]
    PbK = np.r_[np.linalg.solve(M2, P1 - e3[:2]), 1.0]
    E1 = np.array([T2[0], T2[1], fT2 * zT2]); E2 = np.array([Q2[0], Q2[1], fQ2 * aQ2])
    E3 = np.cross(E1, E2)
    # the printed third coordinate: unsigned depths (flags not applied)
    E1u = np.array([T2[0], T2[1], zT2]); E2u = np.array([Q2[0], Q2[1], aQ2])
    def to2(K):
        xy = K[0] * E1[:2] + K[1] * E2[:2] + K[2] * E3[:2]
        z = K[0] * E1u[2] + K[1] * E2u[2] + K[2] * E3[2]
        zs = K[0] * E1[2] + K[1] * E2[2] + K[2] * E3[2]
        return np.r_[xy, z], zs
    Pa, Pa_zs = to2(PaK); Pb, Pb_zs = to2(PbK)
    return dict(b2=b2, b0=np.sqrt(b2), g2=g2, d2=d2, d0=np.sqrt(d2), disc=disc, f=f,
                fT1=fT1, fQ1=fQ1, fT2=fT2, fQ2=fQ2, zT1=zT1, zQ1=fQ1*aQ1, zT2=zT2, zQ2=fQ2*aQ2,
                PaK=PaK, PbK=PbK, Pa=Pa, Pb=Pb, Pa_zs=Pa_zs, Pb_zs=Pb_zs, P2=P2, P1=P1, T2=T2, Q2=Q2)

def linie(R):
    Pa, Pb, P2 = R['Pa'], R['Pb'], R['P2']
    L = (P2[1] - Pa[1]) * (P2[0] - Pb[0])
    Rr = (P2[0] - Pa[0]) * (P2[1] - Pb[1])
    return L, Rr, L - Rr

def dist(R):
    Pa, Pb, P2 = R['Pa'], R['Pb'], R['P2']
    return abs(linie(R)[2]) / np.hypot(Pb[0] - Pa[0], Pb[1] - Pa[1])

def run_block_signed(a, d2, version, s2sign, f1=None, f2=None):
    """as run_block but with frame 2's depths reflected (zT2 -> -zT2, zQ2 -> -zQ2) if s2sign=-1."""
    f1 = f1 or F1; f2 = f2 or F2
    s1 = proj_sq(f1, ID); s2 = proj_sq(f2, a)
    disc, r, f = b_roots(s1, s2, d2)
    if version not in r: return None
    b2 = r[version]; g2 = a2_of(f, b2, d2)
    P1, Q1, T1 = frame_pts(f1, ID); P2, Q2, T2 = frame_pts(f2, a)
    zT1, aQ1, fT1, fQ1 = depth_signs(d2, b2, g2, T1, Q1)
    zT2, aQ2, fT2, fQ2 = depth_signs(d2, b2, g2, T2, Q2)
    e1 = np.array([*T1, zT1]); e2 = np.array([*Q1, fQ1 * aQ1]); e3 = np.cross(e1, e2)
    M2 = np.column_stack([T1, Q1])
    PaK = np.r_[np.linalg.solve(M2, P1), 0.0]; PbK = np.r_[np.linalg.solve(M2, P1 - e3[:2]), 1.0]
    E1 = np.array([*T2, s2sign * zT2]); E2 = np.array([*Q2, s2sign * fQ2 * aQ2]); E3 = np.cross(E1, E2)
    to2 = lambda K: K[0] * E1 + K[1] * E2 + K[2] * E3
    Pa = to2(PaK); Pb = to2(PbK)
    return dict(Pa=Pa, Pb=Pb, P2=P2, b2=b2, g2=g2)

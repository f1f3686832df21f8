"""Core recomputation of the author's program (program naming: tested P, triangle R,T,Q).
Paper Appendix A (a,b,c) = program (g,b,d) = (TQ, QR, RT)."""
import numpy as np
from parse import frames, blocks, tokens, assignment, half_unit, perms4

F1, F2 = frames()

def frame_pts(f, a):
    """a = (iP,iQ,iR,iT): return P,Q,T relative to R as numpy arrays."""
    iP, iQ, iR, iT = a
    o = np.array(f[iR])
    return np.array(f[iP]) - o, np.array(f[iQ]) - o, np.array(f[iT]) - o

def proj_sq(f, a):
    P, Q, T = frame_pts(f, a)
    return (T - Q) @ (T - Q), Q @ Q, T @ T   # a_i^2 (g), b_i^2 (b), c_i^2 (d)

def coeffs(s):
    a2, b2, c2 = s
    A = 2 * (-a2 + b2 + c2); B = 2 * (a2 - b2 + c2); C = 2 * (a2 + b2 - c2)
    K = a2 * a2 + b2 * b2 + c2 * c2 - 2 * a2 * b2 - 2 * a2 * c2 - 2 * b2 * c2
    return A, B, C, K

ID = (0, 1, 2, 3)

def appendixA(s1, s2):
    """f_cb, f_c, f_b, f_Cst, f_b2, f_c2 exactly as printed in Appendix A (frames i=1,2)."""
    A1, B1, C1, K1 = coeffs(s1); A2, B2, C2, K2 = coeffs(s2)
    den = (-A2 + A1)
    fcb = 2 * ((C2 - C1) * (B2 - B1) / den**2 - (C2 - C1) / den - (B2 - B1) / den - 1)
    fc = (C2 - C1) * A1 / den + C1 - 2 * (K2 - K1) / den + 2 * (K2 - K1) * (C2 - C1) / den**2
    fb = (B2 - B1) * A1 / den + B1 - 2 * (K2 - K1) / den + 2 * (K2 - K1) * (B2 - B1) / den**2
    fcst = ((K2 - K1) / den)**2 + (K2 - K1) * A1 / den + K1
    fb2 = (1 - (B2 - B1) / den)**2
    fc2 = (1 - (C2 - C1) / den)**2
    return dict(fcb=fcb, fc=fc, fb=fb, fcst=fcst, fb2=fb2, fc2=fc2,
                p=(B2 - B1) / den, q=(C2 - C1) / den, r=(K2 - K1) / den)

def F(s, x):
    """twofold-squared relation for frame proj s at squared lengths x=(a2,b2,c2)."""
    A, B, C, K = coeffs(s); a, b, c = x
    return a*a + b*b + c*c - 2*a*b - 2*a*c - 2*b*c + K + A*a + B*b + C*c

def b_roots(s1, s2, c2):
    f = appendixA(s1, s2)
    lin = c2 * f['fcb'] + f['fb']
    cst = c2 * f['fc'] + c2 * c2 * f['fc2'] + f['fcst']
    disc = lin * lin - 4 * f['fb2'] * cst
    out = {}
    for sg in (-1, 1):
        if disc >= 0:
            out[sg] = (-lin + sg * np.sqrt(disc)) / (2 * f['fb2'])
    return disc, out, f

def a2_of(f, b2, c2):
    return f['p'] * b2 + f['q'] * c2 + f['r']

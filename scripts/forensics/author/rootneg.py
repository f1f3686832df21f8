"""Delta_b at d^2 = longest projection of TR: analytically zero (Delta_b = kappa (x-d1^2)(x-d2^2)),
numerically +-rounding. Sign statistics under tiny perturbations of the frame data (standing in for
the program's unrounded data), evaluated exactly as Appendix A writes the coefficients."""
import numpy as np, fractions
from core import *
rng = np.random.default_rng(1)

def delta_b(s1, s2, x):
    f = appendixA(s1, s2)
    lin = x * f['fcb'] + f['fb']
    cst = x * f['fc'] + x * x * f['fc2'] + f['fcst']
    return lin * lin - 4 * f['fb2'] * cst, lin * lin + 4 * abs(f['fb2']) * (abs(x * f['fc']) + x * x * f['fc2'] + abs(f['fcst']))

def exact_check(a):
    Fr = fractions.Fraction
    f1 = [(Fr(str(x)), Fr(str(y))) for x, y in F1]; f2 = [(Fr(str(x)), Fr(str(y))) for x, y in F2]
    def pq(f, a):
        iP, iQ, iR, iT = a; o = f[iR]
        Q = (f[iQ][0] - o[0], f[iQ][1] - o[1]); T = (f[iT][0] - o[0], f[iT][1] - o[1])
        n = lambda v: v[0] * v[0] + v[1] * v[1]
        return (n((T[0] - Q[0], T[1] - Q[1])), n(Q), n(T))
    s1 = pq(f1, ID); s2 = pq(f2, a)
    f = appendixA(s1, s2)
    x = max(s1[2], s2[2])
    lin = x * f['fcb'] + f['fb']; cst = x * f['fc'] + x * x * f['fc2'] + f['fcst']
    return lin * lin - 4 * f['fb2'] * cst

if __name__ == '__main__':
    for a in perms4():
        s1 = proj_sq(F1, ID); s2 = proj_sq(F2, a)
        f = appendixA(s1, s2); kappa = f['fcb']**2 - 4 * f['fb2'] * f['fc2']
        lo = max(s1[2], s2[2])
        D0, S = delta_b(s1, s2, lo)
        ex = exact_check(a)
        neg = 0; vals = []
        N = 2000
        for _ in range(N):
            g1 = [(x + rng.uniform(-5e-7, 5e-7) * (x != 0), y + rng.uniform(-5e-7, 5e-7) * (y != 0)) for x, y in F1]
            g2 = [(x + rng.uniform(-5e-7, 5e-7) * (x != 0), y + rng.uniform(-5e-7, 5e-7) * (y != 0)) for x, y in F2]
            t1 = proj_sq(g1, ID); t2 = proj_sq(g2, a)
            d, _ = delta_b(t1, t2, max(t1[2], t2[2]))
            neg += d < 0; vals.append(d)
        vals = np.array(vals)
        print(a, 'kappa=%+.4g exact(6-dec data)=%s double=%+.3g  scale S*eps=%.3g  perturbed: neg %4d/%d, zero %d, |max| %.3g' % (
            kappa, float(ex), D0, S * 2.2e-16, neg, N, int((vals == 0).sum()), np.abs(vals).max()))

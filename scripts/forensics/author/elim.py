"""General elimination: from F1-F2 (linear) eliminate one squared length, substitute in F1,
get a quadratic form in the two others: coefficients dict over monomials."""
import sympy as sp
from core import *
u = sp.symbols('g2 b2 d2')   # program naming squared lengths: g=TQ (paper a), b=QR, d=RT (paper c)

def elim_coeffs(s1, s2, elim, into=1):
    """elim: index of variable to eliminate (0=g,1=b,2=d). returns poly in the other two."""
    A1, B1, C1, K1 = coeffs(s1); A2, B2, C2, K2 = coeffs(s2)
    lin = [A1 - A2, B1 - B2, C1 - C2]; k = K1 - K2
    others = [i for i in range(3) if i != elim]
    expr = -(sum(lin[i] * u[i] for i in others) + k) / lin[elim]
    x = list(u); x[elim] = expr
    s = s1 if into == 1 else s2
    A, B, C, K = coeffs(s)
    a, b, c = x
    Fx = sp.expand(a*a + b*b + c*c - 2*a*b - 2*a*c - 2*b*c + K + A*a + B*b + C*c)
    P = sp.Poly(Fx, u[others[0]], u[others[1]])
    return {m: float(cf) for m, cf in zip(P.monoms(), P.coeffs())}, others

"""Task A: symbolic checks of the displays (sympy).  Each printed formula is transcribed from the
LaTeX (macros expanded by hand, display breaks joined) and compared with a derivation."""
import sympy as sp
a, b, c, ai, bi, ci, a1, b1, c1 = sp.symbols('a b c a_i b_i c_i a_1 b_1 c_1', positive=True)
X, Y, Z = a**2-ai**2, b**2-bi**2, c**2-ci**2
# (1) p3f3sqr (lines 178-188): twofold squaring of  ±sqrt X ± sqrt Y ± sqrt Z = 0
twofold = sp.expand(X**2+Y**2+Z**2-2*X*Y-2*X*Z-2*Y*Z)
# check it is the product of the four sign patterns' factor (it vanishes for every sign pattern):
sx, sy, sz = sp.symbols('sx sy sz', positive=True)
prod = sp.expand((sx+sy+sz)*(sx+sy-sz)*(sx-sy+sz)*(-sx+sy+sz))
print("twofold squaring = -(product of sign patterns) with sx^2=X..:",
      sp.expand(prod.subs({sx: sp.sqrt(X), sy: sp.sqrt(Y), sz: sp.sqrt(Z)}) + twofold) == 0)
printed = (a**4+b**4+c**4-2*a**2*b**2-2*a**2*c**2-2*b**2*c**2
           + ai**4+bi**4+ci**4-2*ai**2*bi**2-2*ai**2*ci**2-2*bi**2*ci**2
           + 2*(-ai**2+bi**2+ci**2)*a**2 + 2*(ai**2-bi**2+ci**2)*b**2 + 2*(ai**2+bi**2-ci**2)*c**2)
print("(1) p3f3sqr printed == twofold squaring:", sp.expand(printed - twofold) == 0)
Fi = printed
F1 = printed.subs({ai: a1, bi: b1, ci: c1})
# (2) section 3 (lines 440-450): LHS = RHS with LHS = Cst_i - Cst_1
lhs = (ai**4+bi**4+ci**4-2*ai**2*bi**2-2*ai**2*ci**2-2*bi**2*ci**2
       - a1**4-b1**4-c1**4+2*a1**2*b1**2+2*a1**2*c1**2+2*b1**2*c1**2)
rhs = (2*a**2*(ai**2-bi**2-ci**2-a1**2+b1**2+c1**2) + 2*b**2*(-ai**2+bi**2-ci**2+a1**2-b1**2+c1**2)
       + 2*c**2*(-ai**2-bi**2+ci**2+a1**2+b1**2-c1**2))
print("(2) section 3: LHS - RHS == F_i - F_1 exactly:", sp.expand(lhs - rhs - (Fi - F1)) == 0)
# (3) section 4 (lines 510-543): each equation == F_i - F_1 of its triangle, with the edges renamed
d, f, g, di, fi, gi, d1, f1, g1 = sp.symbols('d f g d_i f_i g_i d_1 f_1 g_1', positive=True)
def sec3(u, v, w, ui, vi, wi, u1, v1, w1):
    m = {a: u, b: v, c: w, ai: ui, bi: vi, ci: wi, a1: u1, b1: v1, c1: w1}
    return sp.expand((lhs - rhs).subs(m, simultaneous=True)), sp.expand((Fi - F1).subs(m, simultaneous=True))
for name, tri in (("PQT (a,g,f)", (a, g, f, ai, gi, fi, a1, g1, f1)), ("QRT (d,b,g)", (d, b, g, di, bi, gi, d1, b1, g1)),
                  ("RPT (d,f,c)", (d, f, c, di, fi, ci, d1, f1, c1))):
    e, ref = sec3(*tri)
    print(f"(3) section 4 {name}: printed form == F_i - F_1 of the triangle:", sp.expand(e - ref) == 0)
# transcriptions of the three printed section-4 equations (lines 510-518, 522-531, 535-543)
PQT = ((ai**4+gi**4+fi**4-2*ai**2*gi**2-2*ai**2*fi**2-2*gi**2*fi**2-a1**4-g1**4-f1**4+2*a1**2*g1**2+2*a1**2*f1**2+2*g1**2*f1**2)
       - (2*a**2*(ai**2-gi**2-fi**2-a1**2+g1**2+f1**2) + 2*g**2*(-ai**2+gi**2-fi**2+a1**2-g1**2+f1**2)
          + 2*f**2*(-ai**2-gi**2+fi**2+a1**2+g1**2-f1**2)))
QRT = ((di**4+bi**4+gi**4-2*di**2*bi**2-2*di**2*gi**2-2*bi**2*gi**2-d1**4-b1**4-g1**4+2*d1**2*b1**2+2*d1**2*g1**2+2*b1**2*g1**2)
       - (2*d**2*(di**2-bi**2-gi**2-d1**2+b1**2+g1**2) + 2*b**2*(-di**2+bi**2-gi**2+d1**2-b1**2+g1**2)
          + 2*g**2*(-di**2-bi**2+gi**2+d1**2+b1**2-g1**2)))
RPT = ((di**4+fi**4+ci**4-2*di**2*fi**2-2*di**2*ci**2-2*fi**2*ci**2-d1**4-f1**4-c1**4+2*d1**2*f1**2+2*d1**2*c1**2+2*f1**2*c1**2)
       - (2*d**2*(di**2-fi**2-ci**2-d1**2+f1**2+c1**2) + 2*f**2*(-di**2+fi**2-ci**2+d1**2-f1**2+c1**2)
          + 2*c**2*(-di**2-fi**2+ci**2+d1**2+f1**2-c1**2)))
for name, e, tri in (("PQT", PQT, (a, g, f, ai, gi, fi, a1, g1, f1)), ("QRT", QRT, (d, b, g, di, bi, gi, d1, b1, g1)),
                     ("RPT", RPT, (d, f, c, di, fi, ci, d1, f1, c1))):
    print(f"    transcription {name} == F_i - F_1:", sp.expand(e - sec3(*tri)[1]) == 0)
# (4) Appendix A: eliminate a^2 from F_1, F_2 written with the macros
A1, A2_, B1, B2_, C1, C2_, K1, K2 = sp.symbols('faca1 faca2 facb1 facb2 facc1 facc2 facCst1 facCst2')
A, B, C = sp.symbols('A B C')   # a^2, b^2, c^2
E = A**2+B**2+C**2-2*A*B-2*A*C-2*B*C
G1 = E + K1 + A1*A + B1*B + C1*C; G2 = E + K2 + A2_*A + B2_*B + C2_*C
Asol = sp.solve(sp.expand(G2 - G1), A)[0]
elim = sp.Poly(sp.expand(sp.together(G1.subs(A, Asol)) * (A1 - A2_)**2), B, C)
D = (-A2_ + A1)
f_cb = 2*((C2_-C1)*(B2_-B1)/D**2 - (C2_-C1)/D - (B2_-B1)/D - 1)
f_c = (C2_-C1)*A1/D + C1 - 2*(K2-K1)/D + 2*(K2-K1)*(C2_-C1)/D**2      # printed without '*' before the fraction
f_b = (B2_-B1)*A1/D + B1 - 2*(K2-K1)/D + 2*(K2-K1)*(B2_-B1)/D**2
f_K = ((K2-K1)/D)**2 + (K2-K1)*A1/D + K1
f_b2 = (1-(B2_-B1)/D)**2; f_c2 = (1-(C2_-C1)/D)**2
printedA = B**2*f_b2 + B*(C*f_cb + f_b) + (C*f_c + C**2*f_c2 + f_K)
print("(4) Appendix A: printed b^4 f_b2 + b^2(c^2 f_cb + f_b) + (c^2 f_c + c^4 f_c2 + f_Cst) == F_1 with a^2 eliminated:",
      sp.simplify(sp.together(printedA - G1.subs(A, Asol))) == 0)
# (5) section 2.2 Cramer (lines 248-262)
da1, db1, dc1, dK1, da2, db2, dc2, dK2 = sp.symbols('d_a1 d_b1 d_c1 d_K1 d_a2 d_b2 d_c2 d_K2')
sol = sp.solve([da1*A+db1*B+dc1*C+dK1, da2*A+db2*B+dc2*C+dK2], [A, B])
a2p = ((-dc1*C-dK1)*db2 - (-dc2*C-dK2)*db1)/(da1*db2-da2*db1)
b2p = (da1*(-dc2*C-dK2) - da2*(-dc1*C-dK1))/(da1*db2-da2*db1)
print("(5) Cramer a^2, b^2 as printed:", sp.simplify(sol[A]-a2p) == 0, sp.simplify(sol[B]-b2p) == 0)
# (6) the missing '+' (lines 205-208): as printed the constant multiplies the c^2 term
dA, dB, dC, dK = sp.symbols('dA dB dC dK')
printed_eq1 = dA*A + dB*B + dC*C*dK; corrected = dA*A + dB*B + dC*C + dK
print("(6) lines 205-208 printed - corrected =", sp.factor(printed_eq1 - corrected))
printed_eq2 = dA*A + dB*B*dC*C*dK
print("    lines 209-216 printed - corrected =", sp.factor(printed_eq2 - corrected))

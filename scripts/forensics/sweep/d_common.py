"""Task D common: section 2 example (lines 366-427): body (2,3,4), figure (lines 414-420)."""
import numpy as np
import sympy as sp
FIG = np.array([[[0.00, 0.00], [0.81, 0.93], [1.00, 3.80]],
                [[0.00, 0.00], [1.36, 0.90], [1.44, 3.73]],
                [[0.00, 0.00], [1.09, 1.15], [0.43, 3.96]]])
SOL1 = np.array([4, 9, 16.]); SOL2 = np.array([2.6849, 8.33902, 16.2189])

def proj_sq(F):
    P, Q, R = F
    return np.array([np.sum((P-Q)**2), np.sum((Q-R)**2), np.sum((R-P)**2)])   # a_i^2,b_i^2,c_i^2

# paper's procedure, lines 197-327, done symbolically once
A2, B2, C2 = sp.symbols('A2 B2 C2')   # a^2, b^2, c^2
s = sp.symbols('a1:4 b1:4 c1:4')       # squared projections a_i^2, b_i^2, c_i^2 (i=1..3)
a_, b_, c_ = s[0:3], s[3:6], s[6:9]
def faca(i): return 2*(-a_[i]+b_[i]+c_[i])
def facb(i): return 2*(a_[i]-b_[i]+c_[i])
def facc(i): return 2*(a_[i]+b_[i]-c_[i])
def facCst(i): return a_[i]**2+b_[i]**2+c_[i]**2-2*a_[i]*b_[i]-2*a_[i]*c_[i]-2*b_[i]*c_[i]
def Fi(i):  # eq. p3f3sqr with squared quantities
    return (A2**2+B2**2+C2**2-2*A2*B2-2*A2*C2-2*B2*C2 + facCst(i)
            + faca(i)*A2 + facb(i)*B2 + facc(i)*C2)
da = [faca(i)-faca(2) for i in (0, 1)]; db = [facb(i)-facb(2) for i in (0, 1)]
dc = [facc(i)-facc(2) for i in (0, 1)]; dK = [facCst(i)-facCst(2) for i in (0, 1)]
den = da[0]*db[1]-da[1]*db[0]
Ac = ((-dc[0])*db[1]-(-dc[1])*db[0])/den; ACst = ((-dK[0])*db[1]-(-dK[1])*db[0])/den
Bc = (da[0]*(-dc[1])-da[1]*(-dc[0]))/den; BCst = (da[0]*(-dK[1])-da[1]*(-dK[0]))/den
Acs, ACs, Bcs, BCs = sp.symbols('A_c A_Cst B_c B_Cst')
# printed substitution (lines 316-326)
printed_sub = ((Acs*C2+ACs)**2 + (Bcs*C2+BCs)**2 + C2**2 - 2*(Acs*C2+ACs)*(Bcs*C2+BCs)
               - 2*(Acs*C2+ACs)*C2 - 2*(Bcs*C2+BCs)*C2
               + (a_[2]**2+b_[2]**2+c_[2]**2-2*a_[2]*b_[2]-2*a_[2]*c_[2]-2*b_[2]*c_[2])
               + 2*(-a_[2]+b_[2]+c_[2])*(Acs*C2+ACs) + 2*(a_[2]-b_[2]+c_[2])*(Bcs*C2+BCs)
               + 2*(a_[2]+b_[2]-c_[2])*C2)
poly = sp.Poly(sp.expand(printed_sub), C2)
qa, qb, qc = [poly.coeff_monomial(C2**k) for k in (2, 1, 0)]
_f = sp.lambdify([s, Acs, ACs, Bcs, BCs], [qa, qb, qc])
_g = sp.lambdify([s], [Ac, ACst, Bc, BCst])

def solve_sq(sq):
    """sq: 3x3 array of squared projections (frames x (a,b,c)). Returns quadratic coefficients,
    discriminant, and the two solutions (a^2,b^2,c^2) (complex if disc<0)."""
    args = list(sq[:, 0]) + list(sq[:, 1]) + list(sq[:, 2])
    Ac_, ACst_, Bc_, BCst_ = _g(args)
    qa_, qb_, qc_ = _f(args, Ac_, ACst_, Bc_, BCst_)
    disc = qb_**2 - 4*qa_*qc_
    r = np.sqrt(complex(disc))
    roots = [(-qb_ - r)/(2*qa_), (-qb_ + r)/(2*qa_)]
    sols = [np.array([Ac_*c2+ACst_, Bc_*c2+BCst_, c2]) for c2 in roots]
    return (qa_, qb_, qc_), disc, sols

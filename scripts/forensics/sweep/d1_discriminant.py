"""Task D(1): the quadratic in c^2 at the printed figure data; discriminant; conditioning."""
import numpy as np, sympy as sp
from d_common import *
# check: the printed substitution equals F3 with a^2, b^2 replaced (symbolic identity)
sub = sp.expand(Fi(2).subs({A2: Acs*C2+ACs, B2: Bcs*C2+BCs}) - printed_sub)
print("printed substitution (lines 316-326) == F3(a^2=A_c c^2+A_Cst, b^2=B_c c^2+B_Cst):", sub == 0)
sq = np.array([proj_sq(F) for F in FIG])
print("squared projections (a_i^2, b_i^2, c_i^2):\n", sq)
(qa, qb, qc), disc, sols = solve_sq(sq)
print(f"quadratic: {qa:.6g} c^4 + {qb:.6g} c^2 + {qc:.6g} = 0")
print(f"discriminant = {disc:.6g};  relative discriminant disc/qb^2 = {disc/qb**2:.3e}")
print(f"sqrt(disc)/|qa| = root separation = {np.sqrt(disc)/abs(qa):.6g}")
for sl in sols: print("solution (a^2,b^2,c^2):", np.round(np.real(sl), 5))
print("printed:", SOL1, SOL2)
# sensitivity: derivative of each root wrt the 12 figure coordinates (finite differences)
f0 = FIG.copy()
def roots_of(F):
    _, d, so = solve_sq(np.array([proj_sq(Fk) for Fk in F]))
    return np.real(np.concatenate(so))
base = roots_of(f0); J = []
for k in range(3):
    for p in (1, 2):
        for ax in (0, 1):
            h = 1e-6; F = f0.copy(); F[k, p, ax] += h; J.append((roots_of(F) - base)/h)
J = np.array(J)  # 12 x 6
names = ['a2(1)', 'b2(1)', 'c2(1)', 'a2(2)', 'b2(2)', 'c2(2)']
print("sum_k |d root / d coord_k| * 0.005 (linear worst case over the +-0.005 box):")
for j, n in enumerate(names): print(f"  {n}: {np.sum(np.abs(J[:, j]))*0.005:.4f}")
# same at exact data: disc scaling. How the discriminant controls c^2 sensitivity:
dd = []
for k in range(3):
    for p in (1, 2):
        for ax in (0, 1):
            h = 1e-6; F = f0.copy(); F[k, p, ax] += h
            dd.append((solve_sq(np.array([proj_sq(Fk) for Fk in F]))[1] - disc)/h)
print("linear worst-case change of the discriminant over the box:", np.sum(np.abs(dd))*0.005, " vs disc", disc)

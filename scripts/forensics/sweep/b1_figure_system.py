"""Task B(1): build the section-4 system from the figure's two-decimal coordinates and solve it."""
import numpy as np
from b_common import *
R = rows(FIG)
np.set_printoptions(linewidth=200, suppress=True)
print("coefficient matrix from the figure (rows F2-F1: PQT,QRT,RPT ; F3-F1: PQT,QRT,RPT):")
print(np.round(R, 5))
# sign convention: compare with printed
for sgn in (+1, -1):
    d = sgn*R - MAT
    print("sign", sgn, "max |dev| on nonzero:", np.max(np.abs(d[MAT != 0])))
sgn = +1
D = (sgn*R - MAT)
print("\ndeviation (figure - printed) in half-units of the last printed digit (nonzero entries):")
print(np.where(MAT != 0, np.round(D/HU, 1), 0))
print("relative deviation %:")
print(np.where(MAT != 0, np.round(100*D/np.where(MAT!=0,MAT,1), 2), 0))
A, b = R[:, :6], -R[:, 6]
x = np.linalg.solve(A, b)
print("\nsolution from the figure:", np.round(x, 4))
print("printed x:", X_PRINTED)
print("deviation:", np.round(x - X_PRINTED, 4), " rel %:", np.round(100*(x-X_PRINTED)/X_PRINTED, 2))
print("edge lengths:", np.round(np.sqrt(np.abs(x)), 4), "vs", np.round(np.sqrt(X_PRINTED), 4))
print("cond(A) figure:", np.linalg.cond(A), " cond(A) printed:", np.linalg.cond(MAT[:, :6]))
xp = np.linalg.solve(MAT[:, :6], -MAT[:, 6])
print("solution of the printed matrix:", xp, "rel dev %", 100*(xp-X_PRINTED)/X_PRINTED)
print("printed matrix residual at printed x:", MAT[:, :6]@X_PRINTED + MAT[:, 6])
print("figure matrix residual at printed x:", R[:, :6]@X_PRINTED + R[:, 6])
# projected edges vs true edges (feasibility)
for k, F in enumerate(FIG):
    print("frame", k+1, "projected squared edges", np.round(proj_sq(F), 4))

"""Task B common data: Section 4 example (lines 575-672)."""
import numpy as np
# figure (lines 626, 630, 634): \DREID{P}{Q}{R}{T}
FIG = np.array([
    [[1.38, 0.00], [2.58, 1.59], [0.52, 3.22], [0.00, 1.43]],
    [[0.39, 0.00], [1.59, 1.58], [0.00, 3.07], [0.73, 0.68]],
    [[0.43, 0.00], [1.70, 1.45], [0.00, 3.39], [0.18, 2.20]],
])
# printed coefficient matrix (lines 641-656), columns x1..x6, 1
MAT_STR = [
 ["-16.9258","0","0","-3.65832","3.43508","0","60.831"],
 ["0","-0.423132","0","0","11.5049","-20.161","52.7865"],
 ["0","0","1.82806","9.25371","0","-15.3188","34.3132"],
 ["-5.18936","0","0","-9.99644","9.04194","0","21.0125"],
 ["0","-11.1085","0","0","3.03494","-4.07729","70.7523"],
 ["0","0","-3.25323","-4.82034","0","7.10581","40.9956"],
]
MAT = np.array([[float(s) for s in r] for r in MAT_STR])
def half_unit(s):
    """half a unit of the last printed digit"""
    s = s.lstrip('-')
    if '.' in s:
        d = len(s.split('.')[1]); return 0.5 * 10.0**(-d)
    return 0.5
HU = np.array([[half_unit(s) for s in r] for r in MAT_STR])
X_PRINTED = np.array([4, 9, 12.6878, 50, 55.25, 33.9578])
# point indices P,Q,R,T = 0,1,2,3 ; x1..x6 = PQ, QR, RP, TP, TQ, TR
EDGES = [(0,1),(1,2),(2,0),(3,0),(3,1),(3,2)]
# the three triangle relations (section 4): (edge opposite-free triple) in x-indices
# PQT: a=PQ(x1), g=TQ(x5), f=TP(x4);  QRT: d=TR(x6), b=QR(x2), g=TQ(x5);  RPT: d=TR(x6), f=TP(x4), c=RP(x3)
TRIS = [(0,4,3), (5,1,4), (5,3,2)]

def proj_sq(F):
    """squared projected edge lengths of one frame (4x2 array) in x1..x6 order"""
    return np.array([np.sum((F[i]-F[j])**2) for i,j in EDGES])

def Cst(u,v,w):
    return u*u+v*v+w*w-2*u*v-2*u*w-2*v*w

def rows(frames):
    """The paper's equations (lines 510-543) for i=2,3, moved to one side:
    sum_k coef_k x_k + const = 0 with const = Cst_i - Cst_1 and
    coef of X (edge squared, opposite sign pattern) = -2(X_i - Y_i - Z_i - X_1 + Y_1 + Z_1).
    Row order: i=2: PQT,QRT,RPT ; i=3: PQT,QRT,RPT."""
    s = [proj_sq(F) for F in frames]
    out = []
    for i in (1,2):
        for tri in TRIS:
            r = np.zeros(7)
            u = [s[i][k] for k in tri]; u1 = [s[0][k] for k in tri]
            for m in range(3):
                X, Y, Z = u[m], u[(m+1)%3], u[(m+2)%3]
                X1, Y1, Z1 = u1[m], u1[(m+1)%3], u1[(m+2)%3]
                r[tri[m]] = -2*(X - Y - Z - X1 + Y1 + Z1)
            r[6] = Cst(*u) - Cst(*u1)
            out.append(r)
    return np.array(out)

def half_unit_6sig(v):
    """half a unit in the 6th significant digit (C's %g): 60.831 may be 60.8310"""
    v = abs(float(v))
    return 0.5 * 10.0**(np.floor(np.log10(v)) - 5)
HU6 = np.array([[half_unit_6sig(float(s)) if float(s) != 0 else 0.5 for s in r] for r in MAT_STR])

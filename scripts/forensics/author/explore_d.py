from core import *
import numpy as np
from scipy.optimize import brentq
seen = {}
for blk in blocks():
    a = assignment(blk, F2)
    if a in seen: continue
    seen[a] = blk
    s1 = proj_sq(F1, ID); s2 = proj_sq(F2, a)
    d2p = float(blk['d'])
    lo = max(s1[2], s2[2])
    f = appendixA(s1, s2)
    # Delta_b as polynomial in x=d^2
    L = np.poly1d([f['fcb'], f['fb']]); C = np.poly1d([f['fc2'], f['fc'], f['fcst']])
    D = L*L - 4*f['fb2']*C
    xs = np.linspace(lo*0.5, 3000, 200001)
    def feats(x):
        disc, r, _ = b_roots(s1, s2, x)
        return disc, r
    cands = {'lo': lo, 'Droots': [z.real for z in D.r if abs(z.imag)<1e-9]}
    # boundaries: b^2 = maxb, g^2 = maxg
    mb = max(s1[1], s2[1]); mg = max(s1[0], s2[0])
    for sg in (-1, 1):
        def bb(x):
            disc, r, _ = b_roots(s1, s2, x)
            return r.get(sg, np.nan)
        vals = np.array([bb(x) for x in xs[::100]])
        gg = np.array([a2_of(f, bb(x), x) for x in xs[::100]])
        for name, arr, m in (('b', vals, mb), ('g', gg, mg)):
            z = arr - m
            idx = np.where(np.sign(z[:-1]) * np.sign(z[1:]) < 0)[0]
            cands[f'{name}{sg:+d}=max'] = [round(float(xs[::100][i]), 2) for i in idx]
    print(a, 'printed d', d2p, 'b0', blk['b0'], {k: v for k, v in cands.items()})

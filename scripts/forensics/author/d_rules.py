"""Item 5: hypotheses for the program's choice of c^2 (printed d). Reports, per hypothesis, how many
of the 16 assignments it reproduces within d's printed precision and the worst relative miss."""
import numpy as np
from parse import blocks, assignment, half_unit
import core
F1, F2 = core.F1, core.F2
rows = {}
for blk in blocks():
    a = assignment(blk, F2)
    if a in rows: continue
    d0 = float(blk['d0']); hu = half_unit(blk['d0'])
    rows[a] = (d0 * d0, 2 * d0 * hu)

def feats(a):
    s1 = core.proj_sq(F1, core.ID); s2 = core.proj_sq(F2, a)
    f = core.appendixA(s1, s2)
    lo = max(s1[2], s2[2]); hi = min(s1[2], s2[2])
    mb = max(s1[1], s2[1]); mg = max(s1[0], s2[0])
    t = np.roots([f['fb2'], f['fcb'], f['fc2']]).real
    return s1, s2, f, lo, hi, mb, mg, np.sort(t)

H = {
    'c^2 = longest projection': lambda s1, s2, f, lo, hi, mb, mg, t: lo,
    'c^2 = longest projection + 1': lambda s1, s2, f, lo, hi, mb, mg, t: lo + 1,
    'c = longest projection + 0.1': lambda s1, s2, f, lo, hi, mb, mg, t: (np.sqrt(lo) + .1)**2,
    'c = 1.1 x longest projection': lambda s1, s2, f, lo, hi, mb, mg, t: 1.21 * lo,
    'c^2 = 2 lo - hi': lambda s1, s2, f, lo, hi, mb, mg, t: 2 * lo - hi,
    'c^2 = lo + hi': lambda s1, s2, f, lo, hi, mb, mg, t: lo + hi,
    'c^2 = max b^2 / t_small (asymptote)': lambda s1, s2, f, lo, hi, mb, mg, t: mb / t[0],
    'c^2 = max b^2 / t_large': lambda s1, s2, f, lo, hi, mb, mg, t: mb / t[1],
    'c^2 = lo + max b^2 proj': lambda s1, s2, f, lo, hi, mb, mg, t: lo + mb,
    'c^2 = lo + max g^2 proj': lambda s1, s2, f, lo, hi, mb, mg, t: lo + mg,
    'c^2 = -f_b/f_cb': lambda s1, s2, f, lo, hi, mb, mg, t: -f['fb'] / f['fcb'],
    'c^2 = -f_c/(2 f_c2) (vertex)': lambda s1, s2, f, lo, hi, mb, mg, t: -f['fc'] / (2 * f['fc2']),
    'c^2 = sum of the 3 longest proj.^2': lambda s1, s2, f, lo, hi, mb, mg, t: lo + mb + mg,
}

if __name__ == '__main__':
    from scipy.optimize import brentq
    # tangency hypotheses: c^2 where b^2_-(c^2) (resp. g^2) is minimal (touches max projection)
    def tangent(a, which, v):
        s1, s2, f, lo, hi, mb, mg, t = feats(a)
        xs = lo * (1 + np.geomspace(1e-6, 100, 20000))
        vals = []
        for x in xs:
            disc, r, _ = core.b_roots(s1, s2, x)
            b2 = r.get(v, np.nan); vals.append(b2 if which == 'b' else core.a2_of(f, b2, x))
        i = int(np.nanargmin(vals)); return xs[i]
    for nm, w, v in (('b', 'b', -1), ('b', 'b', 1), ('g', 'g', -1), ('g', 'g', 1)):
        H[f'c^2 at min of {nm}^2 (version {v:+d})'] = (w, v)
    print('%-42s %s  %s' % ('hypothesis', 'hits/16', 'worst |rel. miss|, median'))
    for name, h in H.items():
        hits = 0; rel = []
        for a, (x, tol) in rows.items():
            y = tangent(a, *h) if isinstance(h, tuple) else h(*feats(a))
            hits += abs(y - x) <= tol
            rel.append(abs(y - x) / x)
        print('%-42s %2d/16   %.3g, %.3g' % (name, hits, max(rel), np.median(rel)))

"""Item 1/2: the ERROR lines. Fdg_dg/Fdg_g2 = f_cb/f_{b^2} (Appendix A, program naming c->d);
printed for the assignments whose Delta_b leading coefficient kappa = f_cb^2 - 4 f_{b^2} f_{c^2} < 0."""
import numpy as np
from parse import tokens, half_unit, frames
import core
F1, F2 = frames()
NONZERO = [(f, i, k) for f in (0, 1) for i in range(4) for k in range(2) if (F1, F2)[f][i][k] != 0.0]

def ratio(a, f1, f2):
    f = core.appendixA(core.proj_sq(f1, core.ID), core.proj_sq(f2, a))
    return f['fcb'] / f['fb2'], f['fcb']**2 - 4 * f['fb2'] * f['fc2']

def bound(a):
    r0, _ = ratio(a, F1, F2); b = 0
    for fi, i, k in NONZERO:
        fs = [list(map(list, F1)), list(map(list, F2))]; fs[fi][i][k] += 1e-7
        r, _ = ratio(a, [tuple(p) for p in fs[0]], [tuple(p) for p in fs[1]])
        b += abs(r - r0) / 1e-7 * 5e-7
    return r0, b

if __name__ == '__main__':
    printed = [e[1] for e in tokens() if e[0] == 'fdg']
    neg = [a for a in core.perms4() if ratio(a, F1, F2)[1] < 0]
    print('assignments with kappa<0:', neg)
    used = set(); n_ok = 0; worst = 0
    for s in printed:
        p = float(s); hu = half_unit(s)
        a = min(neg, key=lambda a: abs(ratio(a, F1, F2)[0] - p))
        r, b = bound(a)
        miss = abs(r - p) / hu; tol = 1 + b / hu
        n_ok += miss <= tol; worst = max(worst, miss / tol); used.add(a)
        print('printed %-11s assignment %s computed %.7g miss %.3g half-units (tolerance %.3g)' % (s, a, r, miss, tol))
    print('%d of %d printed ratios within tolerance; assignments covered: %d (each twice: %s)' % (n_ok, len(printed), len(used), len(printed) == 2 * len(used)))
    for a in core.perms4():
        r, k = ratio(a, F1, F2)
        print(a, 'kappa=%+.5g  f_cb/f_b2=%.6g' % (k, r))

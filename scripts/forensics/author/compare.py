"""Compare every printed number of the 32 debug blocks with the model of the program.
Units: half a unit in the last printed digit (%g, six significant digits).
Tolerance: 1 half-unit + first-order propagation of the inputs' rounding (the frames' six
decimals, +-5e-7 on each nonzero coordinate; d0's six significant digits)."""
import numpy as np
from parse import frames, blocks, half_unit, assignment
import core, program

F1, F2 = frames()
NONZERO = [(f, i, k) for f in (0, 1) for i in range(4) for k in range(2)
           if (F1, F2)[f][i][k] != 0.0]

def quantities(a, d0, version, f1, f2):
    R = program.run_block(a, d0 * d0, version, f1, f2)
    L, Rr, D = program.linie(R)
    q = {'b': R['b2'], 'b0': R['b0'], 'd': d0 * d0, 'd0': d0}
    for n in ('PaK', 'PbK', 'Pa', 'Pb'):
        for k in range(3): q[f'{n}[{k}]'] = R[n][k]
    for n in ('P2', 'P1', 'T2', 'Q2'):
        for k in range(2): q[f'{n}[{k}]'] = R[n][k]
    P1_, Q1_, T1_ = core.frame_pts(f1, core.ID)
    for k in range(2): q[f'T1[{k}]'] = T1_[k]; q[f'Q1[{k}]'] = Q1_[k]
    q['lin[0]'] = L; q['lin[1]'] = Rr; q['lin[2]'] = D
    q['flags'] = (R['fT1'], R['fQ1'], R['fT2'], R['fQ2'])
    return q

def perturbed(f, i, k, h):
    g = [list(p) for p in f]; g[i][k] += h; return [tuple(p) for p in g]

def bounds(a, d0, version, d0_half):
    base = quantities(a, d0, version, F1, F2)
    bnd = {k: 0.0 for k in base if k != 'flags'}
    h = 1e-7
    for (fi, i, k) in NONZERO:
        fs = [F1, F2]; fs[fi] = perturbed(fs[fi], i, k, h)
        qp = quantities(a, d0, version, fs[0], fs[1])
        for key in bnd: bnd[key] += abs(qp[key] - base[key]) / h * 5e-7
    bnd['d'] = 2 * d0 * d0_half
    qp = quantities(a, d0 + d0_half * 1e-2, version, F1, F2)
    for key in bnd:
        if key not in ('d', 'd0'):
            bnd[key] += abs(qp[key] - base[key]) / (d0_half * 1e-2) * d0_half
    return base, bnd

def printed(blk):
    out = {'b': blk['b'], 'b0': blk['b0'], 'd': blk['d'], 'd0': blk['d0']}
    for n in ('PaK', 'PbK', 'Pa', 'Pb'):
        for k in range(3): out[f'{n}[{k}]'] = blk[n][k]
    for n in ('P2', 'P1', 'T2', 'Q2', 'T1', 'Q1'):
        for k in range(2): out[f'{n}[{k}]'] = blk[n][k]
    for k in range(3): out[f'lin[{k}]'] = blk['lin'][k]
    return out

if __name__ == '__main__':
    import collections
    stats = collections.defaultdict(lambda: [0, 0, 0.0, 0, None])  # n, within-tol, worst half-units, exact(<=1hu)
    flagmatch = 0
    rows = []
    for blk in blocks():
        a = assignment(blk, F2); v = int(blk['version'])
        d0 = float(blk['d0'])
        base, bnd = bounds(a, d0, v, half_unit(blk['d0']))
        fl = tuple(int(blk[k]) for k in ('fT1', 'fQ1', 'fT2', 'fQ2'))
        flagmatch += fl == base['flags']
        for key, s in printed(blk).items():
            p = float(s); hu = half_unit(s); c = base[key]
            miss = abs(p - c) / hu
            tol = 1 + bnd[key] / hu
            group = key
            if key in ('lin[0]', 'lin[1]', 'lin[2]') and abs(p) < 1e-10:
                group = key + ' (rounding-level)'
            st = stats[group]
            st[0] += 1; st[1] += miss <= tol; st[3] += miss <= 1
            if miss > st[2]: st[2] = miss; st[4] = (blk['line'], s, c, tol)
            rows.append((blk['line'], key, s, c, miss, tol))
    print('flags match: %d of 32' % flagmatch)
    print('%-24s %5s %8s %8s  %s' % ('quantity', 'n', 'in-tol', '<=1hu', 'worst miss (half-units) [line, printed, computed, tol]'))
    for k, (n, ok, worst, ex, info) in stats.items():
        print('%-24s %5d %8d %8d  %.3g %s' % (k, n, ok, ex, worst, info))
    import json
    json.dump(rows, open('compare_rows.json', 'w'), indent=0, default=float)

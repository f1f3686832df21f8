from core import *
import numpy as np
seen = {}
for blk in blocks():
    a = assignment(blk, F2)
    if a in seen: continue
    seen[a] = blk
    s1 = proj_sq(F1, ID); s2 = proj_sq(F2, a)
    d2p = float(blk['d'])
    lo = max(s1[2], s2[2])
    f = appendixA(s1, s2)
    print(a, 'printed d', d2p, 'lo', lo, 'maxb', max(s1[1], s2[1]), 'maxg', max(s1[0], s2[0]))
    for x in [lo, lo*(1+1e-9), lo*1.01, lo*1.05, lo*1.1, lo*1.2, d2p, lo*1.5, lo*2, lo*4]:
        disc, r, _ = b_roots(s1, s2, x)
        print('   d2=%10.4f disc=%12.5g' % (x, disc), ' '.join('b2%+d=%9.4f g2=%9.4f' % (k, v, a2_of(f, v, x)) for k, v in r.items()))

"""Item 5 corollary: the point-line distance of every block does not depend on the chosen c."""
import numpy as np
from parse import blocks, assignment
import core, program
worst = 0
for blk in blocks():
    a = assignment(blk, core.F2); v = int(blk['version'])
    s1 = core.proj_sq(core.F1, core.ID); s2 = core.proj_sq(core.F2, a); lo = max(s1[2], s2[2])
    d_print = program.dist(program.run_block(a, float(blk['d0'])**2, v))
    for k in (1.0001, 1.01, 1.5, 3, 30, 300):
        d = program.dist(program.run_block(a, lo * k, v))
        worst = max(worst, abs(d - d_print) / max(d_print, 1e-12) if d_print > 1e-5 else abs(d - d_print))
print('largest relative change of the distance over c^2 in {1.0001..300} x longest projection: %.3g' % worst)

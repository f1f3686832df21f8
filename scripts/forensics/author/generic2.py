"""Item 6 continued: all four combinations (b sign) x (frame-2 mirror); planar scenes."""
import numpy as np, collections
import program, core
from generic import scene

def d_of(R, size):
    return program.dist(R) / size

def combos(f1, f2, x):
    size = max(np.hypot(*p) for p in f2)
    out = {}
    for v in (-1, 1):
        for s in (1, -1):
            R = program.run_block_signed(core.ID, x, v, s, f1, f2)
            out[(v, s)] = None if R is None else d_of(R, size) < 1e-7
    return out

if __name__ == '__main__':
    tally = collections.Counter(); tally_planar = collections.Counter()
    for seed in range(200):
        X, f1, f2, z1, z2 = scene(seed)
        s1 = core.proj_sq(f1, core.ID); s2 = core.proj_sq(f2, core.ID)
        lo = max(s1[2], s2[2])
        c = combos(f1, f2, lo * 1.3)
        tally[tuple(k for k, ok in sorted(c.items()) if ok)] += 1
    print('generic scenes: which (version, frame-2 mirror) combinations put T2 on the line:', dict(tally))
    # planar scenes: P in the plane RTQ
    for seed in range(200):
        rng = np.random.default_rng(10_000 + seed)
        X, f1, f2, z1, z2 = scene(seed)
        al, be = rng.normal(size=2)
        Xp = X.copy(); Xp[0] = X[2] + al * (X[3] - X[2]) + be * (X[1] - X[2])
        from scipy.spatial.transform import Rotation
        R1 = Rotation.random(random_state=seed).as_matrix(); R2 = Rotation.random(random_state=seed + 7).as_matrix()
        Y1 = Xp @ R1.T; Y2 = Xp @ R2.T
        g1 = [tuple(y[:2] - Y1[2, :2]) for y in Y1]; g2 = [tuple(y[:2] - Y2[2, :2]) for y in Y2]
        s1 = core.proj_sq(g1, core.ID); s2 = core.proj_sq(g2, core.ID)
        f = core.appendixA(s1, s2)
        if f['fcb']**2 - 4 * f['fb2'] * f['fc2'] <= 0: tally_planar['kappa<=0'] += 1; continue
        c = combos(g1, g2, max(s1[2], s2[2]) * 1.3)
        tally_planar[tuple(k for k, ok in sorted(c.items()) if ok)] += 1
    print('planar scenes:', dict(tally_planar))

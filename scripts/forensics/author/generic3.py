"""Item 6: which version passes under the program's convention (T depth > 0 in both frames):
the version whose root is the true b^2 if sign(zT1) = sign(zT2) in the true scene, the other one
otherwise -- i.e. the b sign trades against the frame-2 depth reflection."""
import numpy as np, collections
import program, core
from generic import scene, test
c = collections.Counter()
for seed in range(200):
    t = test(seed)
    x, row = t['res'][-1]
    works = [v for v in row if row[v] is not None and row[v] < 1e-7]
    pred = t['true_root'] if t['same_sign'] else -t['true_root']
    c[(len(works) == 1 and works[0] == pred)] += 1
print('prediction "version = true root if sign(zT1)=sign(zT2) else the other" correct in', dict(c))

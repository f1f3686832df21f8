"""Parse the hidden debug printouts of §5.2's example from the paper's LaTeX."""
import re, itertools
PAPER = __import__("os").environ["ORTHOCHECK_PAPER"]  # the paper's LaTeX source (not part of the project)
LINES = open(PAPER).read().split('\n')
NUM = r'[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?'

def frames():
    txt = '\n'.join(LINES[1325:1345])
    f1 = txt.split('Frame 1:')[1].split('Frame 2:')[0]
    f2 = txt.split('Frame 2:')[1].split('(the third')[0]
    g = lambda s: [tuple(float(v) for v in m) for m in re.findall(r'\((%s),(%s)\)' % (NUM, NUM), s)]
    return g(f1), g(f2)

def tokens():
    """Sequence of events in text order: ('block', dict, line) / ('fdg', value, line) / ('rootneg', line)."""
    ev = []
    cur = None
    for ln, L in enumerate(LINES[1369:2160], start=1370):
        for m in re.finditer(r'ERROR: Fdg_dg\s*/\s*Fdg_g2\s*=\s*(%s)' % NUM, L):
            ev.append(('fdg', m.group(1), ln))
        for m in re.finditer(r'ERROR: Root of deltab negative', L):
            ev.append(('rootneg', None, ln))
        m = re.search(r'\(gdb as db\)b=\s*(%s)/b0=(%s) \(d=(%s),d0=(%s)\)' % (NUM, NUM, NUM, NUM), L)
        if m:
            cur = dict(line=ln, b=m.group(1), b0=m.group(2), d=m.group(3), d0=m.group(4))
            ev.append(('block', cur, ln)); continue
        if cur is None: continue
        m = re.search(r'T1\(d\)\((%s),(%s)\)(%s), Q1\(d\)\((%s),(%s)\)(%s)' % ((NUM,)*6), L)
        if m: cur['T1'] = m.group(1, 2); cur['fT1'] = m.group(3); cur['Q1'] = m.group(4, 5); cur['fQ1'] = m.group(6)
        m = re.search(r'T2\(d\)\((%s),(%s)\)(%s), Q2\(d\)\((%s),(%s)\)(%s)' % ((NUM,)*6), L)
        if m: cur['T2'] = m.group(1, 2); cur['fT2'] = m.group(3); cur['Q2'] = m.group(4, 5); cur['fQ2'] = m.group(6)
        for key in ('PaK', 'PbK', 'Pa ', 'Pb '):
            m = re.match(r'\s*%s:\s*\((%s),(%s),(%s)\)' % (re.escape(key), NUM, NUM, NUM), L)
            if m: cur[key.strip()] = m.group(1, 2, 3)
        for key in ('P2', 'P1'):
            m = re.match(r'\s*%s :\s*\((%s),(%s)\)' % (key, NUM, NUM), L)
            if m: cur[key] = m.group(1, 2)
        m = re.search(r'\(Linie\)\s*(%s) = (%s) \(diff (%s)\)' % (NUM, NUM, NUM), L)
        if m: cur['lin'] = m.group(1, 2, 3)
        m = re.search(r'\(version (%s)\)' % NUM, L)
        if m: cur['version'] = m.group(1); cur = None
    return ev

def panels():
    out = []
    for ln, L in enumerate(LINES):
        if L.startswith('\\DreieckMitGerade%') and 1370 < ln < 2160:
            args = []
            k = ln + 1
            while len(args) < 6:
                args += re.findall(r'\{(%s),(%s)\}' % (NUM, NUM), LINES[k]); k += 1
            out.append(dict(line=ln + 1, pts=[tuple(map(float, a)) for a in args]))
    return out

def half_unit(s, digits=6):
    """half a unit in the last printed digit of a %g-style string (6 significant digits)."""
    s = s.strip().lstrip('+-')
    mant, _, exp = s.lower().partition('e')
    e = int(exp) if exp else 0
    if '.' in mant:
        dec = len(mant.split('.')[1])
    else:
        dec = 0
    return 0.5 * 10.0 ** (e - dec)

def blocks():
    return [e[1] for e in tokens() if e[0] == 'block']

def perms4():
    return [p for p in itertools.permutations(range(4))]

def assignment(blk, f2):
    """frame-2 listed indices (iP, iQ, iR, iT) of the program's P, Q, R, T for a block."""
    for p in perms4():
        iP, iQ, iR, iT = p
        o = f2[iR]
        ok = True
        for key, i in (('P2', iP), ('Q2', iQ), ('T2', iT)):
            v = [float(x) for x in blk[key]]
            w = (f2[i][0] - o[0], f2[i][1] - o[1])
            if any(abs(v[k] - w[k]) > half_unit(blk[key][k]) + 1e-6 for k in range(2)):
                ok = False
        if ok: return p
    return None

if __name__ == '__main__':
    f1, f2 = frames(); print(f1, f2)
    for e in tokens():
        if e[0] == 'block':
            b = e[1]; print(e[2], assignment(b, f2), b['version'], b['d0'], b['b0'], b['fT1'], b['fQ1'], b['fT2'], b['fQ2'], b['lin'])
        else:
            print(e)
    print(len(blocks()), len(panels()))

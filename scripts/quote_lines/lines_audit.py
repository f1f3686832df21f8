#!/usr/bin/env python3
"""Audit the `lines` of every quote of paper_cases/*.yaml against the LaTeX source.

For every mapping with both `lines` and `quote`: locate the quote verbatim (white space
removed) or, failing that, after the normalisation of normalize.py beside it; report the tightest
line range holding it, whether the stated range holds it and whether the stated range is
that tightest range.

Usage: lines_audit.py SOURCE [--cases DIR] [--json OUT] [--md OUT]

The same normaliser as src/cases/normalise (a side-by-side reference, never a dependency).
"""
import glob
import json
import os
import re
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import normalize as N  # noqa: E402

if len(sys.argv) < 2 or sys.argv[1].startswith('--'):
    sys.exit(__doc__)
SOURCE = sys.argv[1]
CASES = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'paper_cases')
if '--cases' in sys.argv:
    CASES = sys.argv[sys.argv.index('--cases') + 1]


def parse_ranges(s):
    out = []
    for r in str(s).split(','):
        r = r.strip()
        m = re.fullmatch(r'(\d+)\s*[-–]\s*(\d+)', r)
        if m:
            out.append((int(m.group(1)), int(m.group(2))))
        elif r.isdigit():
            out.append((int(r), int(r)))
        else:
            return None
    return out


def fmt(a, b):
    return str(a) if a == b else f'{a}-{b}'


def collect():
    rows = []

    def claim_of(m):
        c = m.get('claim')
        if isinstance(c, str):
            return c
        if isinstance(c, dict) and isinstance(c.get('claim'), str):
            return c['claim']
        return None

    def walk(o, path, ancestors, fid, fname):
        if isinstance(o, dict):
            if 'lines' in o and 'quote' in o:
                cid = claim_of(o)
                for anc in reversed(ancestors):
                    if cid:
                        break
                    cid = claim_of(anc)
                if not cid:
                    cid = fid
                rows.append(dict(file=fname, path='.'.join(path), claim=cid,
                                 lines=str(o['lines']), quote=o['quote']))
            for k, v in o.items():
                walk(v, path + [str(k)], ancestors + [o], fid, fname)
        elif isinstance(o, list):
            for i, v in enumerate(o):
                tag = f'{i}'
                if isinstance(v, dict) and 'id' in v:
                    tag = f"{i}[{v['id']}]"
                walk(v, path + [tag], ancestors, fid, fname)

    files = sorted(glob.glob(os.path.join(CASES, '*.yaml'))) + [os.path.join(CASES, 'paper.yml')]
    for f in files:
        doc = yaml.safe_load(open(f))
        walk(doc, [], [], doc.get('id') if isinstance(doc, dict) else None, os.path.basename(f))
    return rows


# ---------------------------------------------------------------- matching

def match_segments(s, spans, segs):
    """All minimal windows of `segs` (literals, N.GAP, N.BAL) in string s.
    Returns [(lo_line, hi_line, start, end)]."""
    lits = [x for x in segs if x not in (N.GAP, N.BAL)]
    if not lits:
        return []
    first = segs[0]
    wins = []
    start = s.find(first)
    while start != -1:
        pos = start + len(first)
        ok = True
        k = 1
        while k < len(segs):
            seg = segs[k]
            if seg == N.GAP:
                nxt = segs[k + 1]
                p = s.find(nxt, pos)
                if p == -1:
                    ok = False
                    break
                pos = p + len(nxt)
                k += 2
                continue
            if seg == N.BAL:
                if pos == 0 or s[pos - 1] != '(':
                    ok = False
                    break
                depth, q = 1, pos
                while q < len(s) and depth:
                    depth += (s[q] == '(') - (s[q] == ')')
                    q += 1
                if depth:
                    ok = False
                    break
                pos = q - 1          # at the matching ')'
                k += 1
                continue
            # a literal that must follow immediately
            if not s.startswith(seg, pos):
                ok = False
                break
            pos += len(seg)
            k += 1
        if ok:
            lo = min(sp[0] for sp in spans[start:pos])
            hi = max(sp[1] for sp in spans[start:pos])
            wins.append((lo, hi, start, pos))
        start = s.find(first, start + 1)
    # keep minimal windows (no other window strictly inside)
    wins = [w for w in wins if not any(v is not w and v[2] >= w[2] and v[3] <= w[3] and (v[2], v[3]) != (w[2], w[3]) for v in wins)]
    # distinct line ranges
    seen, out = set(), []
    for w in wins:
        if (w[0], w[1]) not in seen:
            seen.add((w[0], w[1]))
            out.append(w)
    return out


class Verbatim:
    def __init__(self, text):
        self.s, self.spans = [], []
        for n, line in enumerate(text.split('\n'), 1):
            for c in line:
                if not c.isspace():
                    self.s.append(c)
                    self.spans.append((n, n))
        self.s = ''.join(self.s)

    def locate(self, q):
        squash = lambda t: re.sub(r'\s+', '', t)
        whole = squash(q)
        w = match_segments(self.s, self.spans, [whole]) if whole else []
        if w:
            return w, 'verbatim'
        parts = [squash(p) for p in re.split(r'\s*(?:\.\.\.|…)\s*', q)]
        parts = [p for p in parts if p]
        if len(parts) > 1:
            segs = []
            for p in parts:
                if segs:
                    segs.append(N.GAP)
                segs.append(p)
            w = match_segments(self.s, self.spans, segs)
            if w:
                return w, 'verbatim (abridged)'
        return [], None


def choose(wins, stated):
    """The window overlapping the stated ranges (closest), else the first."""
    if not wins:
        return None, False
    lo_s = min(a for a, _ in stated) if stated else 0
    hi_s = max(b for _, b in stated) if stated else 0
    over = [w for w in wins if w[0] <= hi_s and w[1] >= lo_s]
    pool = over or wins
    best = min(pool, key=lambda w: (abs(w[0] - lo_s) + abs(w[1] - hi_s)))
    return best, len(wins) > 1


def main():
    text = open(SOURCE, encoding='utf-8').read()
    V = Verbatim(text)
    C = N.Canon(text)
    rows = collect()
    for r in rows:
        stated = parse_ranges(r['lines'])
        wins, how = V.locate(r['quote'])
        segs = None
        if not wins:
            segs = C.quote(r['quote'])
            wins = match_segments(C.s, [(c[1], c[2]) for c in C.chars], segs)
            how = 'normalised' if wins else 'NOT FOUND'
        best, amb = choose(wins, stated)
        r['how'] = how
        r['segments'] = segs
        r['all'] = [fmt(w[0], w[1]) for w in wins]
        r['ambiguous'] = amb
        if best:
            r['found'] = fmt(best[0], best[1])
            r['inside'] = any(a <= best[0] and best[1] <= b for a, b in stated) if stated else False
            r['tight'] = stated == [(best[0], best[1])]
        else:
            r['found'] = 'NOT FOUND'
            r['inside'] = None
            r['tight'] = None
    out = sys.argv[sys.argv.index('--json') + 1] if '--json' in sys.argv else None
    if out:
        with open(out, 'w') as f:
            json.dump(rows, f, indent=1, ensure_ascii=False)
    for r in rows:
        flag = 'ok' if r['tight'] else ('NOT TIGHT' if r['inside'] else ('WRONG' if r['inside'] is False else 'NF'))
        print(f"{flag:9} {r['how']:20} {r['file']:24} {r['claim'] or '-':28} stated={r['lines']:16} found={r['found']:10} all={','.join(r['all'])}")
    n = len(rows)
    print('total', n, {k: sum(1 for r in rows if r['how'] == k) for k in set(r['how'] for r in rows)})
    print('tight', sum(1 for r in rows if r['tight']))


if __name__ == '__main__':
    main()

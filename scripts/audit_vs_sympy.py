#!/usr/bin/env python3
"""Side by side: `orthocheck audit --all` (every identity, /expanded included) against SymPy
checking the same 64 identities in one Python process. A measuring tool, not a dependency.

The identities are read from the scripts `orthocheck audit --export all` writes (their
`defs[...] = parse(...)`, `lhs`, `rhs_text` and `k` lines), then decided by one route:

- `field`:  exact, in SymPy's sparse rational-function field over QQ (`sympy.polys.fields`),
            which cancels a gcd after every operation;
- `pair`:   exact, as unreduced numerator/denominator pairs in SymPy's sparse ring over QQ
            (`sympy.polys.rings`): no gcds, so some items grow large;
- `points`: Schwartz-Zippel, the chain of definitions evaluated at 64 seeded points modulo
            2^61 - 1 with Python integers (no certificate);
- `export`: the exported scripts as written (SymPy expressions, `together`, `expand`), one
            Python process per script.

`best-exact` is the sum over items of the faster exact route (field or pair).

usage: python3 scripts/audit_vs_sympy.py [--routes field,pair,points] [--repeats N]
           [--timeout S] [--binary target/release/orthocheck]
"""
import argparse
import ast
import random
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction
from pathlib import Path

from sympy import Rational
from sympy.polys.domains import QQ
from sympy.polys.fields import field
from sympy.polys.rings import ring

TOKEN = re.compile(r'[A-Za-z][A-Za-z0-9_]*|[0-9]+(?:\.[0-9]*)?|\*\*|\S')
PRIME = (1 << 61) - 1


def python_text(text):
    """The transcription syntax (juxtaposition multiplies, ^ is a power) as Python, every
    literal but an exponent wrapped as Q(...) so that division stays exact."""
    out = []
    for t in TOKEN.findall(text):
        if out and (out[-1][-1].isalnum() or out[-1][-1] in '_)') and (t[0].isalnum() or t == '('):
            out.append('*')
        if t[0].isdigit() and not (out and out[-1] == '**'):
            t = f'Q({t!r})'
        out.append('**' if t in ('^', '**') else t)
    return ' '.join(out)


def read_item(src):
    """(definitions, (lhs, kept), rhs, k, identifiers) of one exported script."""
    keep = lambda s: set(ast.literal_eval('[' + s + ']'))
    defs = [(n, t, keep(k)) for n, t, k in re.findall(
        r'^defs\["([^"]+)"\] = parse\("([^"]*)", defs, \[([^]]*)\]\)$', src, re.M)]
    lhs, kept = re.search(r'^lhs = parse\("([^"]*)", defs, \[([^]]*)\]\)$', src, re.M).groups()
    rhs = re.search(r'^rhs_text = "([^"]*)"$', src, re.M).group(1)
    k = re.search(r'^k = sympy.Rational\("([^"]*)"\)$', src, re.M).group(1)
    idents = set()
    for t in [d[1] for d in defs] + [lhs, rhs]:
        idents.update(re.findall(r'[A-Za-z][A-Za-z0-9_]*', t))
    return defs, (lhs, keep(kept)), rhs, k, sorted(idents)


def evaluate(item, symbols, const):
    """`lhs − k·rhs` of an item with its identifiers bound to `symbols` and literals to
    `const(text)`; the derived side names plain symbols only."""
    defs, (lhs, kept), rhs, k, idents = item
    env = {}

    def ev(text, keep):
        local = dict(symbols)
        local.update({n: v for n, v in env.items() if n not in keep})
        local['Q'] = const
        return eval(text, {'__builtins__': {}}, local)

    for name, text, keep in defs:
        env[name] = ev(text, keep)
    return ev(lhs, kept), const(k), ev(rhs, set(idents))


def by_field(item):
    K, *gens = field(','.join(item[4]), QQ)
    const = lambda v: K(QQ.from_sympy(Rational(v)))
    l, k, r = evaluate(item, dict(zip(item[4], gens)), const)
    return l - k * r == 0


class Pair:
    """An unreduced fraction of two ring elements."""
    __slots__ = ('n', 'd')

    def __init__(self, n, d):
        self.n, self.d = n, d

    def _c(self, o):
        return o if isinstance(o, Pair) else Pair(self.n.ring(o), self.n.ring(1))

    def __add__(self, o):
        o = self._c(o)
        if self.d == o.d:
            return Pair(self.n + o.n, self.d)
        return Pair(self.n * o.d + o.n * self.d, self.d * o.d)

    __radd__ = __add__

    def __neg__(self):
        return Pair(-self.n, self.d)

    def __pos__(self):
        return self

    def __sub__(self, o):
        return self + (-self._c(o))

    def __rsub__(self, o):
        return self._c(o) - self

    def __mul__(self, o):
        o = self._c(o)
        return Pair(self.n * o.n, self.d * o.d)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._c(o)
        return Pair(self.n * o.d, self.d * o.n)

    def __rtruediv__(self, o):
        return self._c(o) / self

    def __pow__(self, e):
        return Pair(self.n ** e, self.d ** e)


def by_pair(item):
    R, *gens = ring(','.join(item[4]), QQ)
    one = R(1)
    const = lambda v: Pair(R(QQ.from_sympy(Rational(v))), one)
    l, k, r = evaluate(item, {n: Pair(g, one) for n, g in zip(item[4], gens)}, const)
    if l.d == 0 or r.d == 0:  # a side undefined everywhere: no identity
        return False
    return l.n * r.d - k.n * r.n * l.d == 0


class Mod:
    """A residue modulo PRIME."""
    __slots__ = ('v',)

    def __init__(self, v):
        self.v = v % PRIME

    def _c(self, o):
        return o if isinstance(o, Mod) else Mod(o)

    def __add__(self, o):
        return Mod(self.v + self._c(o).v)

    __radd__ = __add__

    def __neg__(self):
        return Mod(-self.v)

    def __pos__(self):
        return self

    def __sub__(self, o):
        return Mod(self.v - self._c(o).v)

    def __rsub__(self, o):
        return Mod(self._c(o).v - self.v)

    def __mul__(self, o):
        return Mod(self.v * self._c(o).v)

    __rmul__ = __mul__

    def __truediv__(self, o):
        d = self._c(o).v
        if d == 0:
            raise ZeroDivisionError
        return Mod(self.v * pow(d, -1, PRIME))

    def __rtruediv__(self, o):
        return self._c(o) / self

    def __pow__(self, e):
        return Mod(pow(self.v, e, PRIME))


def mod_const(v):
    f = Fraction(v)
    return Mod(f.numerator) / Mod(f.denominator)


def by_points(item, points=64, seed=1):
    g = random.Random(seed)
    compiled = (
        [(n, compile(t, n, 'eval'), keep) for n, t, keep in item[0]],
        (compile(item[1][0], 'lhs', 'eval'), item[1][1]),
        compile(item[2], 'rhs', 'eval'), item[3], item[4])
    for _ in range(points):
        at = {n: Mod(g.randrange(PRIME)) for n in item[4]}
        try:
            l, k, r = evaluate(compiled, at, mod_const)
        except ZeroDivisionError:  # a denominator vanished at this point: counted as a failure
            return False
        if l.v != (k * r).v:
            return False
    return True


def as_python(item):
    defs, (lhs, kept), rhs, k, idents = item
    return ([(n, python_text(t), keep) for n, t, keep in defs], (python_text(lhs), kept),
            python_text(rhs), k, idents)


class Timeout(Exception):
    pass


def timed(route, item, timeout):
    """(seconds, ok) of one item, (None, None) past `timeout`."""
    def stop(*_):
        raise Timeout
    signal.signal(signal.SIGALRM, stop)
    signal.alarm(timeout)
    t = time.perf_counter()
    try:
        ok = route(item)
    except Timeout:
        return None, None
    finally:
        signal.alarm(0)
    return time.perf_counter() - t, ok


def run_export(scripts):
    t = time.perf_counter()
    for s in scripts:
        r = subprocess.run([sys.executable, str(s)], capture_output=True, text=True)
        if r.returncode != 0:
            print("FAILED", s.name, r.stdout, r.stderr[-400:])
    return time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--routes", default="field,pair,points")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--timeout", type=int, default=120, help="seconds per item and route")
    ap.add_argument("--binary", default="target/release/orthocheck")
    a = ap.parse_args()
    ours = []
    for _ in range(max(a.repeats, 5)):
        t = time.perf_counter()
        subprocess.run([a.binary, "audit", "--all", "--json"], check=True, capture_output=True)
        ours.append(time.perf_counter() - t)
    routes = {"field": by_field, "pair": by_pair, "points": by_points}
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "sympy"
        subprocess.run([a.binary, "audit", "--export", "all", "--out", str(out)], check=True,
                       capture_output=True)
        scripts = sorted(out.glob("*.py"))
        items = {s.name: as_python(read_item(s.read_text())) for s in scripts}
        per = {}
        for name in a.routes.split(","):
            if name == "export":
                per[name] = {"total": statistics.median(run_export(scripts) for _ in range(a.repeats))}
                continue
            per[name] = {}
            for s, item in items.items():
                runs = [timed(routes[name], item, a.timeout) for _ in range(a.repeats)]
                if any(ok is False for _, ok in runs):
                    print(f"FAILED {name} {s}: left out of the totals")
                    continue
                done = [t for t, _ in runs if t is not None]
                # an item past the timeout in any run counts as timed out
                per[name][s] = None if len(done) < len(runs) else statistics.median(done)
                shown = "timeout" if per[name][s] is None else f"{per[name][s]:.3f} s"
                print(f"  {name:6} {shown:>10}  {s}", flush=True)
    o = statistics.median(ours)
    print(f"orthocheck audit --all --json: median {o:.3f} s of {len(ours)} runs")
    for name, times in per.items():
        if "total" in times:
            total, late = times["total"], 0
        else:
            late = sum(t is None for t in times.values())
            total = sum(a.timeout if t is None else t for t in times.values())
        bound = f" (lower bound: {late} items past {a.timeout} s)" if late else ""
        print(f"SymPy {name}: {total:.2f} s{bound}, ratio {total / o:.0f}x")
    if "field" in per and "pair" in per:
        both = [s for s in per["field"] if s in per["pair"]]
        fastest = [min((t for t in (per["field"][s], per["pair"][s]) if t is not None),
                       default=None) for s in both]
        late = sum(t is None for t in fastest)
        best = sum(a.timeout if t is None else t for t in fastest)
        bound = f" (lower bound: {late} items past {a.timeout} s on both)" if late else ""
        print(f"SymPy best-exact (faster of field and pair per item): {best:.2f} s{bound}, "
              f"ratio {best / o:.0f}x")


if __name__ == "__main__":
    main()

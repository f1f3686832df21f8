"""Normalised comparison of a paper's LaTeX source and plain-notation quotes.

Both sides -- the LaTeX source (with a line span for every character) and a quote
(plain notation or LaTeX) -- are mapped to one canonical character stream by the same
pipeline; a quote is located when its canonical pieces occur, in order, in the canonical
source.  The steps, applied in this order:

 1. Comments (source only).  ``%`` up to the end of its line is dropped, unless the ``%`` is
    escaped (``\\%``).  Line ends survive, so line numbers are kept.

 2. Tokens.  The text is cut into: control words ``\\name`` (a following run of white space
    is swallowed, as TeX does), control symbols ``\\X`` (X one non-letter: ``\\\\``, ``\\,``,
    ``\\%``, ``\\ ``), macro parameters ``#1``..``#9``, ``{``, ``}``, and single characters.
    White space is dropped everywhere (the comparison is white-space blind).  Every token
    carries the span (first line, last line) of the source it stands for.

 3. Macro definitions (source only).  Every ``\\newcommand{\\name}[n]{body}`` (also the form
    with the body on the next line, and with ``\\name`` not in braces) is recorded and removed
    from the stream: a definition is not printed text.

 4. Quote identifiers for macro calls (quote only).  An identifier ``<macro><digits>`` where
    ``<macro>`` is a one-argument macro of the source (``faca1``, ``facCst3``) becomes the call
    ``\\<macro>{<digits>}`` -- the project's names for ``\\faca{1}`` etc.

 5. Macro expansion (both sides).  A call of a recorded macro with a non-empty body is
    replaced by its body with ``#k`` replaced by the k-th argument (a brace group, its braces
    removed, or a single token); expansion is repeated on the result (depth limit 50).  Tokens
    coming from the body get the span of the whole call (control word to last argument);
    tokens of an argument keep their own span.  A macro with an empty body (``\\Bem``,
    ``\\DreieckUP``) is *not* expanded: its control word is dropped and its arguments stay as
    ordinary text (the quotes do quote such hidden text).

 6. LaTeX constructs to plain notation (both sides).
      ``\\frac{A}{B}``  -> ``(A)/(B)``            ``\\sqrt{A}`` -> ``sqrt(A)``
      ``\\ref{X}`` -> ``X``    ``\\cite{X}`` -> ``[X]``    ``\\label{X}``, ``\\begin{X}``,
      ``\\end{X}``, ``\\setcounter{..}{..}``, ``\\special{..}`` -> nothing
      ``\\pm`` -> ``±``   ``\\mp`` -> ``∓``   ``\\le``/``\\leq`` -> ``<=``  ``\\ge``/``\\geq`` -> ``>=``
      ``\\times`` -> ``×``   ``\\%`` -> ``%``   ``\\l`` -> ``l``   ``\\&`` -> ``&``
      Greek letters ``\\Delta`` etc. -> their names (``Delta``).
      Dropped (spacing, layout, multiplication): ``$``, ``{``, ``}``, ``&``, ``~``, ``\\\\``,
      ``\\,`` ``\\;`` ``\\:`` ``\\!`` ``\\ `` ``\\quad`` ``\\qquad`` ``\\left`` ``\\right``
      ``\\nonumber`` ``\\cdot`` ``*`` ``\\hline`` ``\\item`` ``\\noindent`` and every other
      control word not named here (its arguments stay as text).
      Subscripts: inside ``_{...}`` commas are dropped (``d_{a,1}`` -> ``da1``); the
      subscript marker ``_`` itself is dropped everywhere, and braces are dropped, so
      ``d_{a,1}`` = ``d_a1`` = ``da1``, ``{a_i}^2`` = ``a_i^2`` = ``ai^2``, ``f_{b ^2}`` =
      ``f_{b^2}``, ``b{^2}`` = ``b^2``, ``$T2_aT2_b$`` = ``T2aT2b``.  ``^`` is kept.
      Plain-notation characters: ``−`` -> ``-``, ``×`` kept, ``Δ`` -> ``Delta``,
      ``ł`` -> ``l``, ``²`` -> ``^2``, ``√`` -> ``sqrt``.
      ``;`` is dropped on both sides (the plain quotes use it as a table-row separator where
      the source has ``\\\\``, itself dropped).

 7. Redundant parentheses (both sides, on the canonical characters, repeated to a fixed
    point).  The balanced groups are found with a stack (unmatched parentheses are plain
    characters); innermost first, a group ``( X )`` is replaced by ``X`` when
      (a) X is a single atom (only letters, digits, ``.``, ``^``), or
      (b) X is itself one group, optionally followed by ``^`` and an atom, or
      (c) product numerator: the group is followed by ``/``, X has no ``+ - ± ∓`` outside
          inner parentheses, and the group is not preceded by ``sqrt`` or ``^``.
    So ``\\frac{(p)}{(q)^2}`` -> ``((p))/(((q)^2))`` -> ``(p)/((q)^2)`` -> ``(p)/(q)^2`` and
    ``\\frac{(p) * x}{(q)}`` -> ``((p)x)/((q))`` -> ``(p)x/(q)`` (as ``(p)*x/(q)`` reads).
    Groups holding an abridging marker are never unwrapped.

 8. Unit factor.  ``)1/`` -> ``)/`` (a product with ``\\frac{1}{X}`` written as a division).

 9. Abridging (quote only).  `` ... ``, ``...`` and ``…`` separate pieces that must occur in
    order with anything between; ``(...)`` stands for a balanced parenthesised group of any
    content (the piece before it ends with ``(`` and the next piece starts at its matching
    ``)``).

Matching (lines_audit.match_segments): the whole source is canonicalised once, every
canonical character keeping the (first, last) source line it stands for; a quote's pieces are
searched in that string, and the range reported is (min first line, max last line) over the
matched characters -- the tightest range holding the quote.  When a quote stands more than
once, all minimal windows are reported and the one nearest the stated range is chosen.

Every step can be switched off through ``STEPS`` (used for the ablation in the report).
"""

import re

GREEK = {
    'alpha', 'beta', 'gamma', 'delta', 'epsilon', 'zeta', 'eta', 'theta', 'iota', 'kappa',
    'lambda', 'mu', 'nu', 'xi', 'pi', 'rho', 'sigma', 'tau', 'upsilon', 'phi', 'chi', 'psi',
    'omega', 'Gamma', 'Delta', 'Theta', 'Lambda', 'Xi', 'Pi', 'Sigma', 'Upsilon', 'Phi',
    'Psi', 'Omega',
}
SYMBOLS = {'pm': '±', 'mp': '∓', 'le': '<=', 'leq': '<=', 'ge': '>=', 'geq': '>=',
           'times': '×', 'l': 'l', 'L': 'L'}
# control words whose (first) brace argument is dropped with them
DROP_WITH_ARG = {'label': 1, 'begin': 1, 'end': 1, 'setcounter': 2, 'special': 1,
                 'pagestyle': 1, 'documentstyle': 1, 'unitlength': 0, 'setlength': 0,
                 'hspace': 1, 'vspace': 1, 'put': 0}
PLAIN_CHARS = {'−': '-', '–': '-', 'Δ': 'Delta', 'ł': 'l', '²': '^2', '√': 'sqrt',
               '·': '', '\u00a0': ''}

# Every step can be switched off (for the ablation in lines_audit.py).
STEPS = dict(
    identifiers=True,      # step 4
    macros=True,           # step 5
    frac=True,             # step 6: \frac{A}{B} -> (A)/(B)
    sqrt=True,             # step 6: \sqrt{A} -> sqrt(A)
    ref_cite=True,         # step 6: \ref{X} -> X, \cite{X} -> [X]
    symbols=True,          # step 6: \pm -> ±, \le -> <=, Greek names, plain characters
    drop_mult=True,        # step 6: * and \cdot dropped
    subscript_commas=True, # step 6: commas inside _{...} dropped
    drop_underscore=True,  # step 6: the subscript marker _ dropped
    drop_semicolon=True,   # step 6: ; dropped
    redundant_parens=True, # step 7: ( atom ), ( (group) ), ( (group)^atom ) unwrapped
    product_numerator=True,# step 7: ( product ) / unwrapped
    unit_factor=True,      # step 8: )1/ -> )/
    balanced=True,         # step 9: (...) matches one balanced group
)

GAP = '\x00'    # "..." : anything
BAL = '\x01'    # "(...)" : a balanced group's content


class Tok:
    __slots__ = ('t', 'lo', 'hi')

    def __init__(self, t, lo, hi):
        self.t, self.lo, self.hi = t, lo, hi

    def __repr__(self):
        return f'{self.t!r}@{self.lo}-{self.hi}'


def strip_comments(text):
    """Step 1."""
    return re.sub(r'(?<!\\)%[^\n]*', '', text)


def tokenize(text, first_line=1):
    """Step 2: tokens with line spans; white space dropped."""
    toks = []
    line = first_line
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == '\n':
            line += 1
            i += 1
            continue
        if c.isspace():
            i += 1
            continue
        if c == '\\' and i + 1 < n:
            m = re.match(r'\\([A-Za-z]+)', text[i:])
            if m:
                toks.append(Tok('\\' + m.group(1), line, line))
                i += len(m.group(0))
                continue
            d = text[i + 1]
            if d == '\n':
                toks.append(Tok('\\ ', line, line))
                line += 1
                i += 2
                continue
            toks.append(Tok('\\' + d, line, line))
            i += 2
            continue
        if c == '#' and i + 1 < n and text[i + 1].isdigit():
            toks.append(Tok('#' + text[i + 1], line, line))
            i += 2
            continue
        toks.append(Tok(c, line, line))
        i += 1
    return toks


def group_end(toks, i):
    """Index after the brace group starting at toks[i] == '{'."""
    depth = 0
    for j in range(i, len(toks)):
        if toks[j].t == '{':
            depth += 1
        elif toks[j].t == '}':
            depth -= 1
            if depth == 0:
                return j + 1
    return len(toks)


def read_arg(toks, i):
    """An argument at toks[i]: (tokens without braces, index after, last line)."""
    if i >= len(toks):
        return [], i, None
    if toks[i].t == '{':
        e = group_end(toks, i)
        return toks[i + 1:e - 1], e, toks[e - 1].hi
    return [toks[i]], i + 1, toks[i].hi


def extract_macros(toks):
    """Step 3: record and remove \\newcommand definitions."""
    macros, out, i = {}, [], 0
    while i < len(toks):
        t = toks[i]
        if t.t == '\\newcommand':
            j = i + 1
            if j < len(toks) and toks[j].t == '{':
                e = group_end(toks, j)
                name = ''.join(x.t for x in toks[j + 1:e - 1])
                j = e
            else:
                name = toks[j].t
                j += 1
            nargs = 0
            if j < len(toks) and toks[j].t == '[':
                k = j
                while toks[k].t != ']':
                    k += 1
                nargs = int(''.join(x.t for x in toks[j + 1:k]))
                j = k + 1
            body, j, _ = read_arg(toks, j)
            macros[name] = (nargs, body)
            i = j
            continue
        out.append(t)
        i += 1
    return macros, out


def expand(toks, macros, depth=0):
    """Step 5: expand macro calls with non-empty bodies; drop empty-bodied control words."""
    out, i = [], 0
    while i < len(toks):
        t = toks[i]
        if t.t in macros and (STEPS['macros'] or not macros[t.t][1]):
            nargs, body = macros[t.t]
            j, args, last = i + 1, [], t.hi
            for _ in range(nargs):
                a, j, l = read_arg(toks, j)
                args.append(a)
                if l is not None:
                    last = l
            if not body:              # \Bem{...}: keep the argument text
                for a in args:
                    out.extend(a)
                i = j
                continue
            new = []
            for b in body:
                if b.t.startswith('#') and len(b.t) == 2 and b.t[1].isdigit():
                    new.extend(args[int(b.t[1]) - 1])
                else:
                    new.append(Tok(b.t, t.lo, last))
            if depth < 50:
                new = expand(new, macros, depth + 1)
            out.extend(new)
            i = j
            continue
        out.append(t)
        i += 1
    return out


def render(toks):
    """Step 6: tokens -> canonical characters [(c, lo, hi)]."""
    out = []

    def emit(s, t):
        for ch in s:
            out.append((ch, t.lo, t.hi))

    i = 0
    while i < len(toks):
        t = toks[i]
        s = t.t
        if s.startswith('\\') and len(s) > 1 and s[1:].isalpha():
            name = s[1:]
            if name == 'frac' and STEPS['frac']:
                a, j, _ = read_arg(toks, i + 1)
                b, j, _ = read_arg(toks, j)
                emit('(', t)
                out.extend(render(a))
                emit(')/(', t)
                out.extend(render(b))
                emit(')', toks[j - 1])
                i = j
                continue
            if name == 'sqrt' and STEPS['sqrt']:
                a, j, _ = read_arg(toks, i + 1)
                emit('sqrt(', t)
                out.extend(render(a))
                emit(')', toks[j - 1])
                i = j
                continue
            if name == 'ref' and STEPS['ref_cite']:
                a, j, _ = read_arg(toks, i + 1)
                out.extend(render(a))
                i = j
                continue
            if name == 'cite' and STEPS['ref_cite']:
                a, j, _ = read_arg(toks, i + 1)
                emit('[', t)
                out.extend(render(a))
                emit(']', toks[j - 1])
                i = j
                continue
            if name in DROP_WITH_ARG:
                j = i + 1
                for _ in range(DROP_WITH_ARG[name]):
                    _, j, _ = read_arg(toks, j)
                i = j
                continue
            if name == 'cdot' and not STEPS['drop_mult']:
                emit('*', t)
            elif name in SYMBOLS and STEPS['symbols']:
                emit(SYMBOLS[name], t)
            elif name in GREEK and STEPS['symbols']:
                emit(name, t)
            # every other control word: dropped
            i += 1
            continue
        if s.startswith('\\'):
            if s in ('\\%', '\\&', '\\_', '\\#', '\\$'):
                emit(s[1], t)
            elif s in ('\\{', '\\}'):
                pass
            i += 1
            continue
        if s == '_' and i + 1 < len(toks) and toks[i + 1].t == '{':
            a, j, _ = read_arg(toks, i + 1)
            if not STEPS['drop_underscore']:
                emit('_', t)
            out.extend(c for c in render(a) if c[0] != ',' or not STEPS['subscript_commas'])
            i = j
            continue
        dropped = {'$', '{', '}', '&', '~'}
        if STEPS['drop_mult']:
            dropped.add('*')
        if STEPS['drop_semicolon']:
            dropped.add(';')
        if STEPS['drop_underscore']:
            dropped.add('_')
        if s in dropped:
            i += 1
            continue
        emit(PLAIN_CHARS.get(s, s) if STEPS['symbols'] else s, t)
        i += 1
    return out


ATOM = re.compile(r'[A-Za-z0-9._^]+\Z')


def simplify_parens(chars):
    """Step 7 (and step 8): drop redundant parentheses; `)1/` -> `)/`."""
    changed = True
    while changed:
        changed = False
        stack, pairs = [], []
        for k, (c, _, _) in enumerate(chars):
            if c == '(':
                stack.append(k)
            elif c == ')' and stack:
                pairs.append((stack.pop(), k))
        drop = set()
        # innermost first (pairs are produced in closing order)
        for a, b in pairs:
            if a in drop or b in drop:
                continue
            inner = ''.join(chars[k][0] for k in range(a + 1, b) if k not in drop)
            if not inner:
                continue
            redundant = STEPS['redundant_parens'] and bool(ATOM.match(inner))
            if not redundant and STEPS['redundant_parens'] and inner[0] == '(':
                # one group, optionally ^atom
                depth, end = 0, None
                for q, ch in enumerate(inner):
                    depth += (ch == '(') - (ch == ')')
                    if depth == 0:
                        end = q
                        break
                rest = inner[end + 1:]
                redundant = rest == '' or (rest.startswith('^') and bool(ATOM.match(rest[1:])))
            if not redundant and STEPS['product_numerator']:
                # a product numerator: ( X ) / with no top-level + - ± in X
                nxt = next((k for k in range(b + 1, len(chars)) if k not in drop), None)
                before = ''.join(chars[k][0] for k in range(max(0, a - 4), a) if k not in drop)
                if nxt is not None and chars[nxt][0] == '/' and not before.endswith(('sqrt', '^')):
                    depth, top = 0, False
                    for ch in inner:
                        if ch == '(':
                            depth += 1
                        elif ch == ')':
                            depth -= 1
                        elif depth == 0 and ch in '+-±∓':
                            top = True
                    redundant = not top
            if redundant and not any(GAP in x or BAL in x for x in inner):
                drop.update((a, b))
        if drop:
            chars = [c for k, c in enumerate(chars) if k not in drop]
            changed = True
    # step 8
    if STEPS['unit_factor']:
        s = ''.join(c[0] for c in chars)
        for m in reversed([m.start() for m in re.finditer(r'\)1/', s)]):
            del chars[m + 1]
    return chars


class Canon:
    """The canonical source: characters with line spans."""

    def __init__(self, text):
        toks = tokenize(strip_comments(text))
        self.macros, toks = extract_macros(toks)
        toks = expand(toks, self.macros)
        self.chars = simplify_parens(render(toks))
        self.s = ''.join(c[0] for c in self.chars)
        self.onearg = sorted((k[1:] for k, (n, b) in self.macros.items() if n == 1 and b),
                             key=len, reverse=True)

    def quote(self, q):
        """Steps 4-9 for a quote: a list of pieces, each a canonical string or BAL."""
        q = q.replace('…', ' ... ')
        if STEPS['balanced']:
            q = q.replace('(...)', '(' + BAL + ')')
        q = re.sub(r'\.\.\.+', GAP, q)
        if self.onearg and STEPS['identifiers']:
            pat = r'(?<![A-Za-z\\])(' + '|'.join(map(re.escape, self.onearg)) + r')(\d+)(?![A-Za-z0-9])'
            q = re.sub(pat, lambda m: '\\' + m.group(1) + '{' + m.group(2) + '}', q)
        toks = tokenize(q)
        toks = expand(toks, self.macros)
        chars = simplify_parens(render(toks))
        s = ''.join(c[0] for c in chars)
        # pieces: GAP separates; BAL is a piece of its own
        pieces = []
        for part in s.split(GAP):
            sub = part.split(BAL)
            for k, p in enumerate(sub):
                if k:
                    pieces.append(BAL)
                if p:
                    pieces.append(p)
            pieces.append(GAP)
        while pieces and pieces[-1] == GAP:
            pieces.pop()
        while pieces and pieces[0] == GAP:
            pieces.pop(0)
        return pieces

//! Steps 6-8: tokens written in plain notation, redundant parentheses removed.

use super::*;

/// A group's opening brace.
const OPEN: char = '{';

/// Step 6: tokens into canonical characters. A work stack instead of recursion, so that
/// deeply nested groups cannot exhaust the call stack.
pub(super) fn render(toks: &[Tok]) -> Vec<CChar> {
    let mut r = Renderer {
        toks,
        close: brace_pairs(toks),
        out: Vec::new(),
        subscript: 0,
    };
    let mut work = vec![Work::Range(0, toks.len())];
    while let Some(w) = work.pop() {
        match w {
            Work::Emit(s, k) => r.emit(s, k),
            Work::LeaveSubscript => r.subscript = r.subscript.saturating_sub(1),
            Work::Range(mut i, end) => {
                while i < end {
                    match r.step(i, end) {
                        Flow::Next(j) => i = j,
                        Flow::Then(j, then) => {
                            work.push(Work::Range(j, end));
                            work.extend(then.into_iter().rev());
                            break;
                        }
                    }
                }
            }
        }
    }
    r.out
}

pub(super) struct Renderer<'a> {
    toks: &'a [Tok],
    close: Vec<Option<usize>>,
    out: Vec<CChar>,
    /// Inside how many `_{..}` groups (their commas are dropped).
    subscript: usize,
}

impl<'a> Renderer<'a> {
    /// `s` emitted with the lines of token `k`.
    fn emit(&mut self, s: &str, k: usize) {
        let toks: &'a [Tok] = self.toks;
        let Some(t) = toks.get(k) else { return };
        let strip = self.subscript > 0;
        let chars = s.chars().filter(|&c| !(strip && c == ','));
        self.out.extend(chars.map(|c| (c, t.lo, t.hi)));
    }

    fn arg(&self, i: usize, end: usize) -> Arg {
        read_arg(self.toks, &self.close, i, end)
    }

    /// Render the token `toks[i]` of the range ending at `end`.
    fn step(&mut self, i: usize, end: usize) -> Flow {
        let toks: &'a [Tok] = self.toks;
        let Some(t) = toks.get(i) else {
            return Flow::Next(end);
        };
        match &t.text {
            Text::Word(w) => match w.strip_prefix('\\') {
                Some(name) if name.chars().all(char::is_alphabetic) => self.word(i, end, name),
                Some(sym) => {
                    if let Some(c) = sym.chars().next().filter(|c| "%&_#$".contains(*c)) {
                        self.emit(c.encode_utf8(&mut [0; 4]), i);
                    }
                    Flow::Next(i + 1)
                }
                None => {
                    self.emit(w, i);
                    Flow::Next(i + 1)
                }
            },
            Text::Ch('_') if toks.get(i + 1).is_some_and(|t| t.is(OPEN)) && i + 1 < end => {
                let a = self.arg(i + 1, end);
                self.subscript += 1;
                Flow::Then(
                    a.next,
                    vec![Work::Range(a.start, a.stop), Work::LeaveSubscript],
                )
            }
            Text::Ch('\\' | '$' | '{' | '}' | '&' | '~' | '*' | ';' | '_') => Flow::Next(i + 1),
            Text::Ch(c) => {
                match plain_char(*c) {
                    Some(s) => self.emit(s, i),
                    None => self.emit(c.encode_utf8(&mut [0; 4]), i),
                }
                Flow::Next(i + 1)
            }
        }
    }

    /// Render the control word `\name` at `toks[i]`.
    fn word(&mut self, i: usize, end: usize, name: &'a str) -> Flow {
        let a = self.arg(i + 1, end);
        let range = Work::Range(a.start, a.stop);
        match name {
            "frac" => {
                let b = self.arg(a.next, end);
                self.emit("(", i);
                let then = vec![
                    range,
                    Work::Emit(")/(", i),
                    Work::Range(b.start, b.stop),
                    Work::Emit(")", b.next.saturating_sub(1)),
                ];
                Flow::Then(b.next, then)
            }
            "sqrt" => {
                self.emit("sqrt(", i);
                Flow::Then(
                    a.next,
                    vec![range, Work::Emit(")", a.next.saturating_sub(1))],
                )
            }
            "ref" => Flow::Then(a.next, vec![range]),
            "cite" => {
                self.emit("[", i);
                Flow::Then(
                    a.next,
                    vec![range, Work::Emit("]", a.next.saturating_sub(1))],
                )
            }
            _ => {
                if let Some(n) = dropped_args(name) {
                    let mut j = i + 1;
                    for _ in 0..n {
                        j = self.arg(j, end).next;
                    }
                    return Flow::Next(j);
                }
                if let Some(s) = symbol(name) {
                    self.emit(s, i);
                } else if GREEK.contains(&name) {
                    self.emit(name, i);
                }
                Flow::Next(i + 1)
            }
        }
    }
}

/// Steps 7 and 8: redundant parentheses removed to a fixed point, then `)1/` read as `)/`.
pub(super) fn simplify_parens(mut chars: Vec<CChar>) -> Vec<CChar> {
    for _ in 0..MAX_PAREN_PASSES {
        let drop = paren_pass(&chars);
        if !drop.contains(&true) {
            break;
        }
        chars = chars
            .into_iter()
            .zip(drop)
            .filter(|(_, d)| !d)
            .map(|(c, _)| c)
            .collect();
    }
    let unit: Vec<bool> = (0..chars.len())
        .map(|k| {
            k > 0
                && chars[k - 1].0 == ')'
                && chars[k].0 == '1'
                && chars.get(k + 1).is_some_and(|c| c.0 == '/')
        })
        .collect();
    chars
        .into_iter()
        .zip(unit)
        .filter(|(_, d)| !d)
        .map(|(c, _)| c)
        .collect()
}

/// One pass of step 7: the parentheses to drop. Groups are examined innermost first (in
/// the order they close), each seeing the groups inside it already unwrapped.
pub(super) fn paren_pass(chars: &[CChar]) -> Vec<bool> {
    let n = chars.len();
    let mut partner = vec![usize::MAX; n];
    let (mut pairs, mut open) = (Vec::new(), Vec::new());
    for (k, c) in chars.iter().enumerate() {
        if c.0 == '(' {
            open.push(k);
        } else if c.0 == ')'
            && let Some(a) = open.pop()
        {
            (partner[a], partner[k]) = (k, a);
            pairs.push((a, k));
        }
    }
    // nesting among matched groups only, and the abridging marks before each character
    let (mut depth, mut level) = (vec![0; n], 0usize);
    let mut marks = vec![0usize; n + 1];
    for (k, c) in chars.iter().enumerate() {
        if partner[k] != usize::MAX {
            if c.0 == '(' {
                depth[k] = level;
                level += 1;
            } else {
                level = level.saturating_sub(1);
            }
        }
        marks[k + 1] = marks[k] + usize::from(c.0 == GAP || c.0 == BAL);
    }
    let mut drop = vec![false; n];
    for (a, b) in pairs {
        if depth[a] >= MAX_PAREN_DEPTH || marks[b] != marks[a + 1] {
            continue;
        }
        let g = Group {
            chars,
            drop: &drop,
            partner: &partner,
            a,
            b,
        };
        if g.redundant() {
            (drop[a], drop[b]) = (true, true);
        }
    }
    drop
}

/// A parenthesised group `chars[a]` .. `chars[b]` during a pass of step 7.
pub(super) struct Group<'p> {
    chars: &'p [CChar],
    drop: &'p [bool],
    partner: &'p [usize],
    a: usize,
    b: usize,
}

pub(super) fn is_atom(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '^')
}

impl Group<'_> {
    /// The characters kept in `from..to`, with their indices.
    fn kept(&self, from: usize, to: usize) -> impl Iterator<Item = (usize, char)> + '_ {
        (from..to)
            .filter(|&k| !self.drop[k])
            .map(|k| (k, self.chars[k].0))
    }

    /// Whether the group's parentheses add nothing: (a) it holds one atom, (b) one group,
    /// optionally `^atom`, or (c) a product followed by `/` (not after `sqrt` or `^`).
    fn redundant(&self) -> bool {
        let Some((first, c)) = self.kept(self.a + 1, self.b).next() else {
            return false;
        };
        if self.kept(first, self.b).all(|(_, c)| is_atom(c)) {
            return true;
        }
        if c == '(' && self.one_group(first) {
            return true;
        }
        self.product_numerator()
    }

    /// Whether the group holds the group opening at `first`, then nothing or `^atom`.
    fn one_group(&self, first: usize) -> bool {
        let Some(&close) = self.partner.get(first).filter(|&&p| p < self.b) else {
            return false;
        };
        let mut rest = self.kept(close + 1, self.b).map(|(_, c)| c);
        match rest.next() {
            None => true,
            Some('^') => {
                let mut atom = rest.peekable();
                atom.peek().is_some() && atom.all(is_atom)
            }
            Some(_) => false,
        }
    }

    /// Whether the group is followed by `/`, not preceded by `sqrt` or `^`, and holds no
    /// `+ - ± ∓` outside inner parentheses.
    fn product_numerator(&self) -> bool {
        let next = self.kept(self.b + 1, self.chars.len()).next();
        if next.is_none_or(|(_, c)| c != '/') {
            return false;
        }
        let before: String = self
            .kept(self.a.saturating_sub(4), self.a)
            .map(|(_, c)| c)
            .collect();
        if before.ends_with("sqrt") || before.ends_with('^') {
            return false;
        }
        let mut k = self.a + 1;
        while k < self.b {
            let c = self.chars[k].0;
            if !self.drop[k] && c == '(' && self.partner[k] < self.b {
                k = self.partner[k];
            } else if !self.drop[k] && "+-±∓".contains(c) {
                return false;
            }
            k += 1;
        }
        true
    }
}

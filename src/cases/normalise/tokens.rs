//! Steps 1-5: comments, tokens, the source's macro definitions and their expansion.

use super::*;

/// Step 1: a line without its comment (`%` to the end, unless escaped as `\%`).
pub(super) fn strip_comment(line: &str) -> &str {
    let mut prev = None;
    for (k, c) in line.char_indices() {
        if c == '%' && prev != Some('\\') {
            return &line[..k];
        }
        prev = Some(c);
    }
    line
}

/// Step 2: the tokens of `text`, with their lines; white space dropped.
pub(super) fn tokenize(text: &str) -> Vec<Tok> {
    let cs: Vec<char> = text.chars().collect();
    let (mut toks, mut line, mut i) = (Vec::new(), 1, 0);
    let mut push = |text, line| {
        toks.push(Tok {
            text,
            lo: line,
            hi: line,
        })
    };
    while let Some(&c) = cs.get(i) {
        let next = cs.get(i + 1).copied();
        i += 1;
        if c == '\n' {
            line += 1;
        } else if is_space(c) {
            // white space is dropped: the comparison is blind to it
        } else if let (true, Some(d)) = (c == '\\', next) {
            let run = cs[i..]
                .iter()
                .take_while(|c| c.is_ascii_alphabetic())
                .count();
            if run > 0 {
                let word: String = std::iter::once('\\')
                    .chain(cs[i..i + run].iter().copied())
                    .collect();
                push(Text::Word(word.into()), line);
                i += run;
            } else {
                // `\` at a line's end is a control space; the line still ends
                let word = if d == '\n' {
                    "\\ ".to_string()
                } else {
                    format!("\\{d}")
                };
                push(Text::Word(word.into()), line);
                line += usize::from(d == '\n');
                i += 1;
            }
        } else if let (true, Some(d)) = (c == '#', next.filter(|d| is_digit(*d))) {
            push(Text::Word(format!("#{d}").into()), line);
            i += 1;
        } else {
            push(Text::Ch(c), line);
        }
    }
    toks
}

/// For every `{` of `toks`, the index of the `}` that closes it, if one does.
pub(super) fn brace_pairs(toks: &[Tok]) -> Vec<Option<usize>> {
    let mut close = vec![None; toks.len()];
    let mut open = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        if t.is('{') {
            open.push(k);
        } else if t.is('}')
            && let Some(a) = open.pop()
        {
            close[a] = Some(k);
        }
    }
    close
}

/// For every `(` of `s` (a byte), the byte of the `)` that closes it, if one does.
pub(super) fn paren_pairs(s: &str) -> HashMap<usize, usize> {
    let mut close = HashMap::new();
    let mut open = Vec::new();
    for (k, b) in s.bytes().enumerate() {
        if b == b'(' {
            open.push(k);
        } else if b == b')'
            && let Some(a) = open.pop()
        {
            close.insert(a, k);
        }
    }
    close
}

/// A macro argument: tokens `start..stop`, the token after it, the last line it covers.
pub(super) struct Arg {
    pub(super) start: usize,
    pub(super) stop: usize,
    pub(super) next: usize,
    pub(super) last: Option<usize>,
}

/// The argument at `toks[i]` within `toks[..end]`: a brace group (braces removed; an
/// unclosed one runs to `end`, its last token left out as the reference does) or one
/// token; none at `end`.
pub(super) fn read_arg(toks: &[Tok], close: &[Option<usize>], i: usize, end: usize) -> Arg {
    let Some(t) = toks.get(i).filter(|_| i < end) else {
        return Arg {
            start: i,
            stop: i,
            next: i,
            last: None,
        };
    };
    if !t.is('{') {
        return Arg {
            start: i,
            stop: i + 1,
            next: i + 1,
            last: Some(t.hi),
        };
    }
    let next = match close.get(i).copied().flatten() {
        Some(m) if m < end => m + 1,
        _ => end,
    };
    Arg {
        start: i + 1,
        stop: (next - 1).max(i + 1),
        next,
        last: toks.get(next - 1).map(|t| t.hi),
    }
}

/// Step 3: the `\newcommand` definitions of `toks`, and the tokens without them.
pub(super) fn extract_macros(toks: &[Tok]) -> (Macros, Vec<Tok>) {
    let close = brace_pairs(toks);
    // the next `]` at or after each token, for the `[n]` of a definition
    let mut next_bracket = vec![None; toks.len() + 1];
    for k in (0..toks.len()).rev() {
        next_bracket[k] = if toks[k].is(']') {
            Some(k)
        } else {
            next_bracket[k + 1]
        };
    }
    let (mut macros, mut out, mut i) = (Macros::new(), Vec::new(), 0);
    while let Some(t) = toks.get(i) {
        if !matches!(&t.text, Text::Word(w) if &**w == "\\newcommand") {
            out.push(t.clone());
            i += 1;
            continue;
        }
        let (name, mut j) = macro_name(toks, &close, i + 1);
        let mut nargs = 0;
        let bracket = next_bracket.get(j).copied().flatten();
        if let (Some(true), Some(k)) = (toks.get(j).map(|t| t.is('[')), bracket) {
            nargs = arity(&join(toks.get(j + 1..k).unwrap_or_default()));
            j = k + 1;
        }
        let body = read_arg(toks, &close, j, toks.len());
        macros.insert(
            name.into(),
            Macro {
                nargs,
                body: slice(toks, &body).to_vec(),
            },
        );
        i = body.next;
    }
    (macros, out)
}

/// The number of arguments `[n]` declares: at most `MAX_MACRO_ARGS`, none when it is not
/// a number (the reference fails on it).
pub(super) fn arity(n: &str) -> usize {
    match n.parse::<i64>() {
        Ok(n) => usize::try_from(n.clamp(0, MAX_MACRO_ARGS as i64)).unwrap_or(0),
        Err(_) if !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()) => MAX_MACRO_ARGS,
        Err(_) => 0,
    }
}

/// The tokens of an argument.
pub(super) fn slice<'t>(toks: &'t [Tok], arg: &Arg) -> &'t [Tok] {
    toks.get(arg.start..arg.stop).unwrap_or_default()
}

/// The name a `\newcommand` defines at `toks[j]` (`{\name}` or `\name`), and the token
/// after it.
pub(super) fn macro_name(toks: &[Tok], close: &[Option<usize>], j: usize) -> (String, usize) {
    match toks.get(j) {
        Some(t) if t.is('{') => {
            let arg = read_arg(toks, close, j, toks.len());
            (join(slice(toks, &arg)), arg.next)
        }
        Some(t) => (join(std::slice::from_ref(t)), j + 1),
        None => (String::new(), j),
    }
}

/// The texts of `toks` joined.
pub(super) fn join(toks: &[Tok]) -> String {
    let mut buf = [0; 4];
    toks.iter()
        .map(|t| t.as_str(&mut buf).to_string())
        .collect()
}

/// Step 5: macro expansion, within a budget of created tokens.
pub(super) struct Expander<'m> {
    macros: &'m Macros,
    budget: usize,
}

impl<'m> Expander<'m> {
    pub(super) fn new(macros: &'m Macros, input: usize) -> Self {
        Expander {
            macros,
            budget: EXPANSION_FLOOR.saturating_add(input.saturating_mul(8)),
        }
    }

    /// `toks` with the calls of macros with a body expanded (the result expanded again, to
    /// `MAX_EXPANSION_DEPTH`), and those of empty-bodied macros replaced by their arguments.
    pub(super) fn expand(&mut self, toks: &[Tok]) -> Vec<Tok> {
        let mut out = Vec::with_capacity(toks.len());
        self.expand_into(toks, 0, &mut out);
        out
    }

    /// [`Self::expand`] at nesting `depth`, appending to `out`: an expansion reads its own
    /// tokens only (no arguments from after the call), and is written straight to `out`, not
    /// copied up through every level.
    fn expand_into(&mut self, toks: &[Tok], depth: usize, out: &mut Vec<Tok>) {
        let close = brace_pairs(toks);
        let mut i = 0;
        while let Some(t) = toks.get(i) {
            let Some(m) = self.lookup(t) else {
                out.push(t.clone());
                i += 1;
                continue;
            };
            let (mut args, mut next, mut last) = (Vec::new(), i + 1, t.hi);
            for _ in 0..m.nargs {
                let a = read_arg(toks, &close, next, toks.len());
                args.push(slice(toks, &a));
                last = a.last.unwrap_or(last);
                next = a.next;
            }
            if m.body.is_empty() {
                args.iter().for_each(|a| out.extend_from_slice(a));
            } else if let Some(new) = self.substitute(m, &args, (t.lo, last)) {
                if depth < MAX_EXPANSION_DEPTH {
                    self.expand_into(&new, depth + 1, out);
                } else {
                    out.extend(new);
                }
            } else {
                // out of budget: the call stays, to be dropped as an unknown control word
                out.push(t.clone());
                next = i + 1;
            }
            i = next;
        }
    }

    /// The body of `m` with its parameters replaced by `args`, the body's tokens standing
    /// for the lines `span` of the whole call; none beyond the budget.
    fn substitute(&mut self, m: &Macro, args: &[&[Tok]], span: (usize, usize)) -> Option<Vec<Tok>> {
        let size: usize = m
            .body
            .iter()
            .map(|b| param(b, args).map_or(1, <[Tok]>::len))
            .sum();
        self.budget = self.budget.checked_sub(size)?;
        let mut new = Vec::with_capacity(size);
        for b in &m.body {
            match param(b, args) {
                Some(a) => new.extend_from_slice(a),
                None if is_param(b) => {}
                None => new.push(Tok {
                    text: b.text.clone(),
                    lo: span.0,
                    hi: span.1,
                }),
            }
        }
        Some(new)
    }

    fn lookup(&self, t: &Tok) -> Option<&'m Macro> {
        let mut buf = [0; 4];
        self.macros.get(t.as_str(&mut buf))
    }
}

/// Whether a body token is a parameter `#k`.
pub(super) fn is_param(t: &Tok) -> bool {
    matches!(&t.text, Text::Word(w) if w.starts_with('#') && w.chars().count() == 2)
}

/// The argument a body token `#k` stands for: none for other tokens, and for a parameter
/// the call lacks (the reference fails on it; `#0` is the last argument, as it reads it).
pub(super) fn param<'t>(t: &Tok, args: &[&'t [Tok]]) -> Option<&'t [Tok]> {
    let Text::Word(w) = &t.text else { return None };
    let k = w.strip_prefix('#')?.parse::<usize>().ok()?;
    let k = if k == 0 {
        args.len().checked_sub(1)?
    } else {
        k - 1
    };
    args.get(k).copied()
}

/// Deferred work of step 6.
pub(super) enum Work {
    /// Render `toks[a..b]`.
    Range(usize, usize),
    /// Emit this text with the lines of token `k`.
    Emit(&'static str, usize),
    /// A subscript's group ends.
    LeaveSubscript,
}

/// What rendering a token leaves to do: go on at a token, or first the work listed.
pub(super) enum Flow {
    Next(usize),
    Then(usize, Vec<Work>),
}

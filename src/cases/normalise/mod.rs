//! Quotes of the paper's LaTeX source located in one normalised notation, so that a formula
//! transcribed into plain notation (`d_a1 = (faca1 - faca3)`) is found where the source
//! writes it with its macros (`\diffa{1} = (\faca{1}-\faca{3})`).
//!
//! The source and a quote are read into one canonical character stream by the same steps,
//! every character of the source keeping the lines it stands for:
//!
//! 1. comments dropped (source only);
//! 2. tokens: control words, control symbols, `#1`..`#9`, single characters; white space
//!    dropped;
//! 3. `\newcommand` definitions recorded and removed (source only);
//! 4. an identifier `faca1`, `faca` a one-argument macro of the source, read as `\faca{1}`
//!    (quote only);
//! 5. macros expanded (a macro with an empty body keeps its arguments as text);
//! 6. LaTeX written in plain notation (`\frac{A}{B}` → `(A)/(B)`, `\sqrt{A}` → `sqrt(A)`,
//!    `\pm` → `±`, Greek letters by name); layout, multiplication, braces, `_` and `;`
//!    dropped, commas dropped inside `_{..}`;
//! 7. redundant parentheses removed; 8. `)1/` read as `)/`;
//! 9. `...` and `…` separate pieces found in order, `(...)` stands for one balanced group
//!    (quote only).
//!
//! `scripts/quote_lines.py` is the same normaliser in Python, for side-by-side checks. The
//! limits below keep hostile input from running away; no paper comes near them.

use std::collections::HashMap;
use std::rc::Rc;

use super::SourceText;

mod render;
mod tokens;

use render::*;
use tokens::*;

/// Separates the pieces of an abridged quote (`...`).
const GAP: char = '\0';
/// Stands for the content of one balanced group (`(...)`).
const BAL: char = '\u{1}';
/// Nested expansions followed (the reference's limit): a recursive macro stops there.
const MAX_EXPANSION_DEPTH: usize = 50;
/// Tokens macro expansion may create beyond a multiple of the input: a macro doubling
/// itself at every level would otherwise create 2^50 of them.
const EXPANSION_FLOOR: usize = 1 << 16;
/// Arguments a macro takes at most, as in TeX.
const MAX_MACRO_ARGS: usize = 9;
/// Parenthesised groups nested deeper are kept as written: each character is then examined
/// for at most this many enclosing groups.
const MAX_PAREN_DEPTH: usize = 64;
/// Passes of step 7 at most (each pass unwraps at least one group; LaTeX needs a few).
const MAX_PAREN_PASSES: usize = 64;

const GREEK: [&str; 34] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi",
    "Omega",
];

/// A control word written as a symbol.
fn symbol(name: &str) -> Option<&'static str> {
    Some(match name {
        "pm" => "±",
        "mp" => "∓",
        "le" | "leq" => "<=",
        "ge" | "geq" => ">=",
        "times" => "×",
        "l" => "l",
        "L" => "L",
        _ => return None,
    })
}

/// A control word dropped together with this many arguments.
fn dropped_args(name: &str) -> Option<usize> {
    Some(match name {
        "label" | "begin" | "end" | "special" | "pagestyle" | "documentstyle" | "hspace"
        | "vspace" => 1,
        "setcounter" => 2,
        "unitlength" | "setlength" | "put" => 0,
        _ => return None,
    })
}

/// A character of plain notation read as its canonical text.
fn plain_char(c: char) -> Option<&'static str> {
    Some(match c {
        '−' | '–' => "-",
        'Δ' => "Delta",
        'ł' => "l",
        '²' => "^2",
        '√' => "sqrt",
        '·' | '\u{a0}' => "",
        _ => return None,
    })
}

/// White space as the reference (Python's `str.isspace`) reads it.
fn is_space(c: char) -> bool {
    c.is_whitespace() || ('\u{1c}'..='\u{1f}').contains(&c)
}

/// A digit after `#` (Python's `str.isdigit`, for the digits a paper can hold).
fn is_digit(c: char) -> bool {
    c.is_ascii_digit() || "⁰¹²³⁴⁵⁶⁷⁸⁹₀₁₂₃₄₅₆₇₈₉".contains(c)
}

/// A canonical character with the first and last source line it stands for.
type CChar = (char, usize, usize);

/// The text of a token: one character, or a control sequence or parameter (`\frac`, `\,`,
/// `#1`).
#[derive(Clone, Debug, PartialEq)]
enum Text {
    Ch(char),
    Word(Rc<str>),
}

/// A token with the (first, last) source line it stands for.
#[derive(Clone, Debug)]
struct Tok {
    text: Text,
    lo: usize,
    hi: usize,
}

impl Tok {
    fn is(&self, c: char) -> bool {
        self.text == Text::Ch(c)
    }

    /// The token's text, a one-character token written into `buf`.
    fn as_str<'a>(&'a self, buf: &'a mut [u8; 4]) -> &'a str {
        match &self.text {
            Text::Ch(c) => c.encode_utf8(buf),
            Text::Word(w) => w,
        }
    }
}

/// A macro of the source: its number of arguments and its body.
#[derive(Debug)]
struct Macro {
    nargs: usize,
    body: Vec<Tok>,
}

type Macros = HashMap<Box<str>, Macro>;

/// The whole source read in the canonical notation, each canonical character with the
/// (first, last) source line it stands for. Built once per source.
pub struct Canonical {
    /// The canonical characters.
    text: String,
    /// The (first, last) source line of every byte of `text`.
    spans: Vec<(usize, usize)>,
    /// The byte of the `)` that closes the `(` at a byte of `text`.
    close: HashMap<usize, usize>,
    macros: Macros,
    /// The names of the one-argument macros (without `\`), longest first.
    one_arg: Vec<Vec<char>>,
}

impl Canonical {
    /// Canonicalise the source (steps 1-3, 5-8 of the module's list): its own
    /// `\newcommand` macros are read from the text itself.
    pub fn of_source(text: &SourceText) -> Canonical {
        let stripped: Vec<&str> = text.lines.iter().map(|l| strip_comment(l)).collect();
        let toks = tokenize(&stripped.join("\n"));
        let (macros, toks) = extract_macros(&toks);
        let toks = Expander::new(&macros, toks.len()).expand(&toks);
        let chars = simplify_parens(render(&toks));
        let mut canon = String::with_capacity(chars.len());
        let mut spans = Vec::with_capacity(chars.len());
        for &(c, lo, hi) in &chars {
            canon.push(c);
            spans.extend(std::iter::repeat_n((lo, hi), c.len_utf8()));
        }
        let mut one_arg: Vec<Vec<char>> = macros
            .iter()
            .filter(|(_, m)| m.nargs == 1 && !m.body.is_empty())
            .map(|(name, _)| name.chars().skip(1).collect())
            .collect();
        one_arg.sort_by_key(|n| std::cmp::Reverse(n.len()));
        Canonical {
            close: paren_pairs(&canon),
            text: canon,
            spans,
            macros,
            one_arg,
        }
    }

    /// Every tightest range (first line, last line) of the source that holds `quote`
    /// (steps 4-9 applied to the quote with the source's macros; pieces in order; `(...)`
    /// a balanced group). Empty when it stands nowhere.
    pub fn ranges_of(&self, quote: &str) -> Vec<(usize, usize)> {
        let pieces = self.pieces(quote);
        let starts = windows(&self.text, &self.close, &pieces);
        let mut out: Vec<(usize, usize)> = Vec::new();
        for (start, end) in starts {
            let spans = self.spans.get(start..end).unwrap_or_default();
            let lo = spans.iter().map(|s| s.0).min();
            let hi = spans.iter().map(|s| s.1).max();
            if let (Some(lo), Some(hi)) = (lo, hi)
                && !out.contains(&(lo, hi))
            {
                out.push((lo, hi));
            }
        }
        out
    }

    /// Steps 4-9 for a quote: its pieces, each a canonical string, `GAP` or `BAL`.
    fn pieces(&self, quote: &str) -> Vec<String> {
        let q = quote.replace('…', " ... ").replace("(...)", "(\u{1})");
        let mut q = collapse_dots(&q);
        if !self.one_arg.is_empty() {
            q = mark_identifiers(&q, &self.one_arg);
        }
        let toks = tokenize(&q);
        let toks = Expander::new(&self.macros, toks.len()).expand(&toks);
        let canon: String = simplify_parens(render(&toks)).iter().map(|c| c.0).collect();
        let mut pieces = Vec::new();
        for part in canon.split(GAP) {
            for (k, p) in part.split(BAL).enumerate() {
                if k > 0 {
                    pieces.push(BAL.to_string());
                }
                if !p.is_empty() {
                    pieces.push(p.to_string());
                }
            }
            pieces.push(GAP.to_string());
        }
        let gap = GAP.to_string();
        let first = pieces
            .iter()
            .position(|p| *p != gap)
            .unwrap_or(pieces.len());
        let last = pieces
            .iter()
            .rposition(|p| *p != gap)
            .map_or(first, |k| k + 1);
        pieces.get(first..last).unwrap_or_default().to_vec()
    }
}

/// Runs of three or more dots read as `GAP`.
fn collapse_dots(q: &str) -> String {
    let mut out = String::with_capacity(q.len());
    let mut dots = 0;
    for c in q.chars().chain(std::iter::once(GAP)) {
        if c == '.' {
            dots += 1;
            continue;
        }
        if dots >= 3 {
            out.push(GAP);
        } else {
            out.extend(std::iter::repeat_n('.', dots));
        }
        dots = 0;
        out.push(c);
    }
    out.pop();
    out
}

/// Step 4: `name<digits>` (`name` a one-argument macro, not after a letter or `\`, not
/// followed by a letter or digit) read as `\name{<digits>}`.
fn mark_identifiers(q: &str, names: &[Vec<char>]) -> String {
    let cs: Vec<char> = q.chars().collect();
    let mut out = String::with_capacity(q.len());
    let mut i = 0;
    while let Some(&c) = cs.get(i) {
        let after_word = i > 0 && (cs[i - 1].is_ascii_alphabetic() || cs[i - 1] == '\\');
        let hit = names.iter().filter(|_| !after_word).find_map(|name| {
            let digits = i + name.len();
            if !cs[i..].starts_with(name) {
                return None;
            }
            let end = digits
                + cs[digits..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit())
                    .count();
            let free = cs.get(end).is_none_or(|c| !c.is_ascii_alphanumeric());
            (end > digits && free).then_some((name, digits, end))
        });
        match hit {
            Some((name, digits, end)) => {
                out.push('\\');
                out.extend(name.iter());
                out.push('{');
                out.extend(&cs[digits..end]);
                out.push('}');
                i = end;
            }
            None => {
                out.push(c);
                i += 1;
            }
        }
    }
    out
}

/// Every minimal window (start, end byte) of `s` holding the pieces in order: a literal
/// right after the previous one, `GAP` anything, `BAL` (after a `(`) up to the `)` closing
/// it. No window holds another.
fn windows(s: &str, close: &HashMap<usize, usize>, pieces: &[String]) -> Vec<(usize, usize)> {
    let (gap, bal) = (GAP.to_string(), BAL.to_string());
    let Some(first) = pieces.first() else {
        return Vec::new();
    };
    if pieces.iter().all(|p| *p == gap || *p == bal) {
        return Vec::new();
    }
    let mut found: HashMap<&str, Vec<usize>> = HashMap::new();
    found.insert(first, occurrences(s, first));
    for w in pieces.windows(2).filter(|w| w[0] == gap) {
        found
            .entry(w[1].as_str())
            .or_insert_with(|| occurrences(s, &w[1]));
    }
    let bytes = s.as_bytes();
    let run = |start: usize| -> Option<usize> {
        let (mut pos, mut k) = (start + first.len(), 1);
        while let Some(p) = pieces.get(k) {
            if *p == gap {
                let next = pieces.get(k + 1)?;
                let at = found.get(next.as_str())?;
                pos = at.get(at.partition_point(|&x| x < pos))? + next.len();
                k += 2;
            } else if *p == bal {
                if pos == 0 || bytes.get(pos - 1) != Some(&b'(') {
                    return None;
                }
                pos = *close.get(&(pos - 1))?;
                k += 1;
            } else {
                bytes.get(pos..).filter(|b| b.starts_with(p.as_bytes()))?;
                pos += p.len();
                k += 1;
            }
        }
        Some(pos)
    };
    let starts = found.get(first.as_str()).map_or(&[][..], Vec::as_slice);
    let all: Vec<(usize, usize)> = starts
        .iter()
        .filter_map(|&st| run(st).map(|e| (st, e)))
        .collect();
    // minimal: no window starting later ends at or before this one's end
    let mut keep = vec![false; all.len()];
    let mut min_end = usize::MAX;
    for (k, &(_, end)) in all.iter().enumerate().rev() {
        keep[k] = end < min_end;
        min_end = min_end.min(end);
    }
    all.into_iter()
        .zip(keep)
        .filter(|(_, k)| *k)
        .map(|(w, _)| w)
        .collect()
}

/// The starts of every occurrence of `pat` in `s`, overlapping ones included.
fn occurrences(s: &str, pat: &str) -> Vec<usize> {
    let mut out = Vec::new();
    let mut from = 0;
    let step = pat.chars().next().map_or(1, char::len_utf8);
    while let Some(at) = s.get(from..).and_then(|t| t.find(pat)) {
        out.push(from + at);
        from += at + step;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn source(lines: &[&str]) -> Canonical {
        Canonical::of_source(&SourceText {
            lines: lines.iter().map(|l| l.to_string()).collect(),
        })
    }

    /// A source in the paper's style: macros, a formula over two lines, a fraction, a comment
    /// and a remark hidden in an empty-bodied macro.
    fn paper() -> Canonical {
        source(&[
            r"\newcommand{\faca}[1]{ 2(-{a_#1}^2+{b_#1}^2) }",
            r"\newcommand{\diffa}[1]{d_{a,#1}}",
            r"\newcommand{\Bem}[1]{}",
            r"Some text. % a comment with y = 1",
            r"\begin{eqnarray}",
            r"\diffa{1} = (\faca{1}",
            r"  -\faca{3}) \nonumber \\",
            r"\end{eqnarray}",
            r"and $x = \frac{p}{q^2}$ holds \Bem{hidden words}.",
        ])
    }

    #[test]
    fn a_formula_in_plain_notation_is_found_at_its_lines() {
        let p = paper();
        assert_eq!(p.ranges_of("d_a1 = (faca1 - faca3)"), vec![(6, 7)]);
        assert_eq!(
            p.ranges_of(r"\diffa{1} = (\faca{1} -\faca{3})"),
            vec![(6, 7)]
        );
        assert_eq!(p.ranges_of("x = p/q²"), vec![(9, 9)]);
        assert_eq!(p.ranges_of("x = (p)/(q^2)"), vec![(9, 9)]);
        assert_eq!(p.ranges_of("holds hidden words"), vec![(9, 9)]);
    }

    #[test]
    fn a_changed_sign_or_index_is_not_found() {
        let p = paper();
        assert!(p.ranges_of("d_a1 = (faca1 + faca3)").is_empty());
        assert!(p.ranges_of("d_a2 = (faca1 - faca3)").is_empty());
        assert!(p.ranges_of("d_a1 = (faca1 - faca2)").is_empty());
        assert!(p.ranges_of("x = p/q^3").is_empty());
        // a comment is not text
        assert!(p.ranges_of("a comment with y = 1").is_empty());
    }

    #[test]
    fn an_abridged_quote_is_found() {
        let p = paper();
        assert_eq!(p.ranges_of("d_a1 = (faca1 ... faca3)"), vec![(6, 7)]);
        assert_eq!(p.ranges_of("Some text … holds"), vec![(4, 9)]);
        assert_eq!(p.ranges_of("d_a1 = (...)"), vec![(6, 7)]);
        // the pieces must stand in order
        assert!(p.ranges_of("holds ... Some text").is_empty());
        assert!(p.ranges_of("...").is_empty());
    }

    #[test]
    fn malformed_input_does_not_panic_or_run_away() {
        let quotes = [r"\frac{ {( x", "(...) ... (", r"#1 \x{ \y", "}}}", r"\", ""];
        // definitions unclosed, recursive, with arities out of range
        let p = source(&[
            r"\newcommand{\y}{\y\y} \y \newcommand{\z}[99999999999999999999999]{#1#0#7} \z{a}",
            r"\newcommand{\x}[1]{{ \frac{a",
            r"\sqrt{ b } } \newcommand",
            r"(( ) \x{ \newcommand{\w}[",
            r"\",
        ]);
        quotes.iter().for_each(|q| drop(p.ranges_of(q)));
        // nesting far deeper than any paper's, rendered without recursion
        let deep = [
            "{".repeat(20_000),
            format!("{}x{}/", "(".repeat(10_000), ")".repeat(10_000)),
            format!("{}x", r"\frac{_{\sqrt{".repeat(10_000)),
        ];
        let p = source(&deep.iter().map(String::as_str).collect::<Vec<_>>());
        quotes.iter().for_each(|q| drop(p.ranges_of(q)));
        deep.iter().for_each(|q| drop(p.ranges_of(q)));
        // an unclosed brace is dropped, what follows it is text
        assert_eq!(source(&["a {b", "c"]).ranges_of("a b c"), vec![(1, 2)]);
    }

    /// Every quote of the paper's cases, when `ORTHOCHECK_PAPER` names the paper's source.
    #[test]
    fn the_quotes_of_the_paper_cases_are_found() {
        let Some(Ok(raw)) = std::env::var_os("ORTHOCHECK_PAPER").map(std::fs::read_to_string)
        else {
            return;
        };
        let canon = Canonical::of_source(&SourceText {
            lines: raw.split('\n').map(str::to_string).collect(),
        });
        let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/paper_cases"));
        let mut paths: Vec<_> = std::fs::read_dir(dir)
            .expect("paper_cases")
            .flatten()
            .map(|e| e.path())
            .collect();
        paths.sort();
        let mut quotes = Vec::new();
        for path in paths
            .iter()
            .filter(|p| p.extension().is_some_and(|e| e == "yaml" || e == "yml"))
        {
            let text = std::fs::read_to_string(path).expect("a case file");
            let v: serde_json::Value = crate::cases::parse_yaml(&text, path).expect("YAML");
            collect_quotes(&v, &mut quotes);
        }
        let missing: Vec<&String> = quotes
            .iter()
            .filter(|q| canon.ranges_of(q).is_empty())
            .collect();
        println!(
            "{} of {} quotes located; not: {missing:#?}",
            quotes.len() - missing.len(),
            quotes.len()
        );
        assert!(quotes.len() - missing.len() >= 190);
    }

    fn collect_quotes(v: &serde_json::Value, out: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(m) => {
                if let (Some(_), Some(serde_json::Value::String(q))) =
                    (m.get("lines"), m.get("quote"))
                {
                    out.push(q.clone());
                }
                m.values().for_each(|x| collect_quotes(x, out));
            }
            serde_json::Value::Array(a) => a.iter().for_each(|x| collect_quotes(x, out)),
            _ => {}
        }
    }
}

//! Formulas as a reader wants them: the paper's LaTeX (and the plain `a_1^2` notation the
//! checks write) turned into Unicode mathematics. The paper's own `\newcommand` macros are
//! expanded from their definitions (`paper_cases/paper.yml`), fractions become `(p)/(q)`,
//! roots `√(x)`, Greek letters their glyphs, and sub- and superscripts Unicode where Unicode
//! has the glyphs (HTML `<sub>`/`<sup>` elsewhere, `_(…)` in plain text). No backslash macro
//! survives: an unknown one is shown by its name.
//!
//! A script without braces takes one character in LaTeX. In plain notation it takes a number
//! (`2a^2b^2` is 2a²b², `x^0.5`) or a name, letters and their trailing digits (`d_Cst1`,
//! `d_a2`, `a_i`): see `plain_script`.
//!
//! Quotes of the paper's source used as text go through [`prose_text`] instead: words keep
//! their spaces, `$…$` is mathematics, references and layout commands read as text.

use std::collections::BTreeMap;

use crate::numfmt::{subscript, superscript};

/// HTML-escape text.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Expansion depth limit: the paper's macros nest three deep; a definition that calls itself
/// stops here instead of looping.
const MAX_DEPTH: usize = 12;

/// How a macro definition starts in the source.
const NEWCOMMAND: &str = "\\newcommand{\\";

/// The paper's `\newcommand` macros by name.
#[derive(Clone, Debug, Default)]
pub struct Macros {
    defs: BTreeMap<String, (usize, String)>,
}

impl Macros {
    /// Read every `\newcommand{\name}[n]{body}` of `latex` (other text is ignored).
    pub fn parse(latex: &str) -> Macros {
        let mut defs = BTreeMap::new();
        let mut rest = latex;
        while let Some(at) = rest.find(NEWCOMMAND) {
            rest = &rest[at + NEWCOMMAND.len()..];
            let Some(end) = rest.find('}') else { break };
            let name = rest[..end].to_string();
            rest = &rest[end + 1..];
            let mut args = 0;
            if let Some(r) = rest.strip_prefix('[')
                && let Some(close) = r.find(']')
            {
                args = r[..close].trim().parse().unwrap_or(0);
                rest = &r[close + 1..];
            }
            let trimmed = rest.trim_start();
            if let Some((body, after)) = group(trimmed) {
                defs.insert(name, (args, body.to_string()));
                rest = after;
            }
        }
        Macros { defs }
    }

    /// How many macros are known.
    pub fn len(&self) -> usize {
        self.defs.len()
    }

    /// True when no macro is known.
    pub fn is_empty(&self) -> bool {
        self.defs.is_empty()
    }

    /// Expand every known macro of `s` (arguments in braces or single characters); with
    /// `names`, also a plain-notation name such as `facCst1` that is a one-argument macro
    /// followed by its argument.
    pub fn expand(&self, s: &str, names: bool) -> String {
        self.expand_at(s, names, 0)
    }

    fn expand_at(&self, s: &str, names: bool, depth: usize) -> String {
        if depth > MAX_DEPTH {
            return s.to_string();
        }
        let mut out = String::with_capacity(s.len());
        let mut rest = s;
        while let Some(c) = rest.chars().next() {
            if c == '\\' {
                let name = letters(&rest[1..]);
                if let Some((n, body)) = self.defs.get(name) {
                    let mut after = &rest[1 + name.len()..];
                    let mut call = body.clone();
                    for k in 1..=*n {
                        let (arg, r) = argument(after);
                        call = call.replace(&format!("#{k}"), arg);
                        after = r;
                    }
                    out.push_str(self.expand_at(&call, names, depth + 1).trim());
                    rest = after;
                    continue;
                }
                out.push('\\');
                out.push_str(name);
                rest = &rest[1 + name.len()..];
                continue;
            }
            let boundary = !out
                .chars()
                .last()
                .is_some_and(|p| p.is_ascii_alphanumeric() || p == '_' || p == '\\');
            if names && boundary && c.is_ascii_alphabetic() {
                let word = letters(rest);
                let digits: &str = {
                    let r = &rest[word.len()..];
                    &r[..r.find(|d: char| !d.is_ascii_digit()).unwrap_or(r.len())]
                };
                let next = rest[word.len() + digits.len()..].chars().next();
                if let Some((1, body)) = self.defs.get(word)
                    && !digits.is_empty()
                    && !next.is_some_and(|n| n.is_ascii_alphanumeric())
                {
                    let call = body.replace("#1", digits);
                    out.push_str(self.expand_at(&call, names, depth + 1).trim());
                    rest = &rest[word.len() + digits.len()..];
                    continue;
                }
                out.push_str(word);
                rest = &rest[word.len()..];
                continue;
            }
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
        out
    }
}

/// The leading ASCII letters of `s`.
fn letters(s: &str) -> &str {
    &s[..s
        .find(|c: char| !c.is_ascii_alphabetic())
        .unwrap_or(s.len())]
}

/// A braced group at the start of `s`: its inside and what follows it.
fn group(s: &str) -> Option<(&str, &str)> {
    if !s.starts_with('{') {
        return None;
    }
    let mut depth = 0usize;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some((&s[1..i], &s[i + 1..]));
                }
            }
            _ => {}
        }
    }
    None
}

/// One macro argument: a braced group or a single character (after spaces).
fn argument(s: &str) -> (&str, &str) {
    let t = s.trim_start();
    if let Some(g) = group(t) {
        return g;
    }
    match t.chars().next() {
        Some(c) => t.split_at(c.len_utf8()),
        None => ("", t),
    }
}

/// A piece of rendered mathematics.
#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Text(String),
    Sub(String),
    Sup(String),
}

/// A LaTeX command without arguments (or one whose argument is shown as is) as text.
fn symbol(name: &str) -> Option<&'static str> {
    Some(match name {
        "alpha" => "α",
        "beta" => "β",
        "gamma" => "γ",
        "delta" => "δ",
        "epsilon" | "varepsilon" => "ε",
        "lambda" => "λ",
        "mu" => "μ",
        "pi" => "π",
        "sigma" => "σ",
        "phi" | "varphi" => "φ",
        "theta" => "θ",
        "omega" => "ω",
        "Delta" => "Δ",
        "Gamma" => "Γ",
        "Lambda" => "Λ",
        "Sigma" => "Σ",
        "Phi" => "Φ",
        "Omega" => "Ω",
        "cdot" => "·",
        "times" => "×",
        "pm" => "±",
        "mp" => "∓",
        "leq" | "le" => "≤",
        "geq" | "ge" => "≥",
        "neq" | "ne" => "≠",
        "approx" => "≈",
        "infty" => "∞",
        "ldots" | "dots" => "…",
        "cdots" => "⋯",
        "sum" => "∑",
        "prod" => "∏",
        "partial" => "∂",
        "in" => "∈",
        "to" | "rightarrow" => "→",
        "Rightarrow" => "⇒",
        "quad" | "qquad" | ";" | " " => " ",
        "," => "\u{2009}",
        "nonumber" | "left" | "right" | "!" | "displaystyle" | "big" | "Big" => "",
        "{" => "{",
        "}" => "}",
        "sin" | "cos" | "tan" | "log" | "exp" | "det" | "arctan" | "min" | "max" => {
            return Some(match name {
                "sin" => "sin ",
                "cos" => "cos ",
                "tan" => "tan ",
                "log" => "log ",
                "exp" => "exp ",
                "det" => "det ",
                "arctan" => "arctan ",
                "min" => "min ",
                _ => "max ",
            })
        }
        _ => return None,
    })
}

/// Commands whose braced argument is shown as it is (fonts, text).
fn is_font(name: &str) -> bool {
    matches!(
        name,
        "mathrm" | "mathit" | "mathbf" | "text" | "textrm" | "mbox" | "hat" | "bar" | "tilde"
    )
}

/// Commands that print their argument and nothing else in running text.
fn is_text_font(name: &str) -> bool {
    matches!(
        name,
        "emph" | "textbf" | "textit" | "texttt" | "textsc" | "textsf" | "underline"
    )
}

/// The length of an unbraced script in plain notation at the start of `t`: a number when it
/// starts with a digit (its digits, and a decimal fraction: `x^0.5`; never a letter, so that
/// `2a^2b^2` is 2a²b²); a name when it starts with a letter (its letters, then their trailing
/// digits: `d_Cst1`, `d_a2`, `a_i`); else one character.
fn plain_script(t: &str) -> usize {
    let digits = |s: &str| s.find(|c: char| !c.is_ascii_digit()).unwrap_or(s.len());
    let Some(first) = t.chars().next() else {
        return 0;
    };
    if first.is_ascii_digit() {
        let whole = digits(t);
        let fraction = t[whole..].strip_prefix('.').map_or(0, digits);
        return if fraction > 0 {
            whole + 1 + fraction
        } else {
            whole
        };
    }
    if first.is_ascii_alphabetic() {
        let name = letters(t).len();
        return name + digits(&t[name..]);
    }
    first.len_utf8()
}

struct Renderer {
    /// Plain notation (`d_Cst1`): a script without braces is read by [`plain_script`].
    plain: bool,
    out: Vec<Piece>,
}

impl Renderer {
    fn text(&mut self, t: &str) {
        if let Some(Piece::Text(s)) = self.out.last_mut() {
            s.push_str(t);
        } else {
            self.out.push(Piece::Text(t.to_string()));
        }
    }

    fn last_char(&self) -> Option<char> {
        match self.out.last() {
            Some(Piece::Text(s)) => s.chars().last(),
            Some(_) => Some('x'),
            None => None,
        }
    }

    fn run(&mut self, s: &str) {
        let mut rest = s;
        while let Some(c) = rest.chars().next() {
            rest = &rest[c.len_utf8()..];
            match c {
                '$' | '&' => {}
                '{' | '}' => {}
                '~' => self.text(" "),
                '=' if !self.plain => self.text(" = "),
                '*' => self.text("·"),
                '-' => {
                    let word = self.last_char().is_some_and(|p| p.is_alphabetic())
                        && rest.chars().next().is_some_and(|n| n.is_alphabetic());
                    self.text(if word && self.plain { "-" } else { "−" });
                }
                // LaTeX ignores spaces in mathematics; plain notation keeps one
                c if c.is_whitespace() => {
                    let next = rest.trim_start().chars().next();
                    if self.plain
                        && !matches!(self.last_char(), None | Some(' ' | '('))
                        && next != Some(')')
                    {
                        self.text(" ");
                    }
                }
                '^' | '_' => rest = self.script(c == '^', rest),
                '\\' => rest = self.command(rest),
                c => self.text(c.encode_utf8(&mut [0; 4])),
            }
        }
    }

    /// A sub- or superscript; returns what follows it.
    fn script<'a>(&mut self, sup: bool, s: &'a str) -> &'a str {
        let t = s.trim_start();
        let (body, rest) = if let Some(g) = group(t) {
            g
        } else if self.plain {
            t.split_at(plain_script(t))
        } else {
            argument(t)
        };
        let inner = flatten(body, self.plain);
        let map = if sup { superscript } else { subscript };
        let mapped: Option<String> = inner.chars().map(map).collect();
        match mapped {
            Some(m) if !inner.is_empty() => self.text(&m),
            _ if sup => self.out.push(Piece::Sup(inner)),
            _ => self.out.push(Piece::Sub(inner)),
        }
        rest
    }

    /// A backslash command; returns what follows it.
    fn command<'a>(&mut self, s: &'a str) -> &'a str {
        let name = letters(s);
        let (name, rest) = if name.is_empty() {
            match s.chars().next() {
                Some(c) => s.split_at(c.len_utf8()),
                None => return s,
            }
        } else {
            (name, &s[name.len()..])
        };
        match name {
            "\\" => {
                self.text(" ");
                rest
            }
            "frac" => {
                let (num, r) = argument(rest);
                let (den, r) = argument(r);
                self.wrapped(num);
                self.text("/");
                self.wrapped(den);
                r
            }
            "sqrt" => {
                let r = rest.trim_start();
                let r = match r.strip_prefix('[').and_then(|x| x.split_once(']')) {
                    Some((_, after)) => after,
                    None => r,
                };
                let (arg, r) = argument(r);
                self.text("√");
                self.wrapped(arg);
                r
            }
            n if is_font(n) => {
                let (arg, r) = argument(rest);
                self.run(arg);
                r
            }
            n => {
                match symbol(n) {
                    Some(t) => self.text(t),
                    // an unknown command shows its name, never its backslash
                    None => {
                        self.text(n);
                        if rest.trim_start().starts_with(|c: char| c.is_alphanumeric()) {
                            self.text(" ");
                        }
                    }
                }
                rest
            }
        }
    }

    /// `x` as is when it is one symbol, else in parentheses.
    fn wrapped(&mut self, x: &str) {
        let inner = flatten(x, self.plain);
        let atomic = inner.chars().all(|c| c.is_alphanumeric() || c == '.')
            || (inner.starts_with('(') && inner.ends_with(')') && balanced_outer(&inner));
        if atomic {
            self.run(x);
        } else {
            self.text("(");
            self.run(x.trim());
            self.text(")");
        }
    }
}

/// True when the outer parentheses of `s` enclose all of it.
fn balanced_outer(s: &str) -> bool {
    let mut depth = 0i32;
    let n = s.chars().count();
    for (i, c) in s.chars().enumerate() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth == 0 && i + 1 < n {
            return false;
        }
    }
    depth == 0
}

fn pieces(s: &str, plain: bool) -> Vec<Piece> {
    let mut r = Renderer {
        plain,
        out: Vec::new(),
    };
    r.run(s);
    finished(r.out)
}

/// Rendered pieces with their ends trimmed and the empty texts dropped.
fn finished(mut out: Vec<Piece>) -> Vec<Piece> {
    if let Some(Piece::Text(t)) = out.first_mut() {
        *t = t.trim_start().to_string();
    }
    if let Some(Piece::Text(t)) = out.last_mut() {
        *t = t.trim_end().to_string();
    }
    out.retain(|p| !matches!(p, Piece::Text(t) if t.is_empty()));
    out
}

/// Rendered mathematics as one plain string (scripts without a Unicode glyph as `_(…)`).
fn flatten(s: &str, plain: bool) -> String {
    text_of(&pieces(s, plain))
}

/// Pieces as one plain string. A script without a Unicode glyph is written `_x` (`^x`), in
/// parentheses when it is more than letters and digits or when a letter or digit follows
/// it: `f_(cb)f_b`, never `f_cbf_b`, which would read as one script.
fn text_of(pieces: &[Piece]) -> String {
    let mut out = String::new();
    for (i, p) in pieces.iter().enumerate() {
        let glued = matches!(
            pieces.get(i + 1),
            Some(Piece::Text(t)) if t.starts_with(|c: char| c.is_ascii_alphanumeric())
        );
        match p {
            Piece::Text(t) => out.push_str(t),
            Piece::Sub(t) => push_script(&mut out, '_', t, glued),
            Piece::Sup(t) => push_script(&mut out, '^', t, glued),
        }
    }
    out
}

fn push_script(out: &mut String, mark: char, t: &str, enclose: bool) {
    out.push(mark);
    if !enclose && t.chars().all(|c| c.is_ascii_alphanumeric()) {
        out.push_str(t);
    } else {
        out.push('(');
        out.push_str(t);
        out.push(')');
    }
}

/// Pieces as HTML (escaped; `<sub>`/`<sup>` for scripts without a Unicode glyph).
fn html_of(pieces: &[Piece]) -> String {
    let mut out = String::new();
    for p in pieces {
        let (open, t, close) = match p {
            Piece::Text(t) => ("", t, ""),
            Piece::Sub(t) => ("<sub>", t, "</sub>"),
            Piece::Sup(t) => ("<sup>", t, "</sup>"),
        };
        out.push_str(open);
        out.push_str(&escape(t));
        out.push_str(close);
    }
    out
}

/// True when `s` reads as LaTeX (a backslash command) rather than plain notation. A braced
/// group alone does not make LaTeX: plain transcriptions group scripts with braces too
/// (`f_{b²}`) and keep the spaces between their words.
fn is_latex(s: &str) -> bool {
    s.contains('\\')
}

/// A formula as plain Unicode text; `names` also expands plain-notation macro names
/// (`facCst1`).
pub fn math_text(s: &str, macros: &Macros, names: bool) -> String {
    let expanded = macros.expand(s, names);
    flatten(&expanded, !is_latex(s))
}

/// A formula as HTML (escaped; `<sub>`/`<sup>` for scripts Unicode cannot write).
pub fn math_html(s: &str, macros: &Macros, names: bool) -> String {
    let expanded = macros.expand(s, names);
    html_of(&pieces(&expanded, !is_latex(s)))
}

/// Backslash commands left in `s` (what no reader should see): their names.
pub fn raw_macros(s: &str) -> Vec<&str> {
    let mut found = Vec::new();
    let mut rest = s;
    while let Some(at) = rest.find('\\') {
        let name = letters(&rest[at + 1..]);
        if !name.is_empty() {
            found.push(name);
        }
        rest = &rest[at + 1 + name.len()..];
    }
    found
}

mod prose;
pub use prose::{is_prose, prose_html, prose_text, prose_text_in, quote_html, quote_text};

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn paper_like() -> Macros {
        Macros::parse(
            "\\newcommand{\\nn}{\\nonumber}\n\
             \\newcommand{\\faca}[1]{ 2(-{a_#1}^2+{b_#1}^2+{c_#1}^2) }\n\
             \\newcommand{\\diffCst}[1]{d_{Cst,#1}}\n\
             \\newcommand{\\deltab}{\\Delta_b}\n\
             \\newcommand{\\AFcbbdwa}{f_{b ^2}}\n",
        )
    }

    #[test]
    fn macros_are_read_with_their_arguments() {
        let m = paper_like();
        assert_eq!(m.len(), 5);
        assert_eq!(m.expand("\\diffCst{1}", false), "d_{Cst,1}");
        assert_eq!(m.expand("\\faca 3", false), "2(-{a_3}^2+{b_3}^2+{c_3}^2)");
        // a plain name is expanded only when asked, and only as a whole word
        assert_eq!(m.expand("faca1 - xfaca1", false), "faca1 - xfaca1");
        assert_eq!(
            m.expand("faca1 - xfaca1", true),
            "2(-{a_1}^2+{b_1}^2+{c_1}^2) - xfaca1"
        );
    }

    #[test]
    fn latex_becomes_unicode() {
        let m = paper_like();
        assert_eq!(math_text("\\faca{1}", &m, false), "2(−a₁²+b₁²+c₁²)");
        assert_eq!(
            math_text("\\diffCst{1} = (x\\nn,$$ $$-y) ,", &m, false),
            "d_(Cst,1) = (x,−y),"
        );
        assert_eq!(math_text("\\frac{a+b}{c}", &m, false), "(a+b)/c");
        assert_eq!(math_text("\\sqrt{\\deltab}", &m, false), "√(Δ_b)");
        assert_eq!(math_text("\\AFcbbdwa", &m, false), "f_(b²)");
        assert_eq!(math_text("\\unknownthing x", &m, false), "unknownthing x");
        assert!(raw_macros(&math_text("\\diffCst{2} \\nn", &m, false)).is_empty());
    }

    #[test]
    fn plain_notation_becomes_unicode() {
        let m = paper_like();
        assert_eq!(math_text("2*a_i^2*b_1^4", &m, false), "2·aᵢ²·b₁⁴");
        assert_eq!(math_text("d_Cst1 - d_a2", &m, false), "d_Cst1 − dₐ₂");
        assert_eq!(math_text("well-posed", &m, false), "well-posed");
        // braces group a script; the words keep their spaces
        assert_eq!(
            math_text("symbols f_cb f_b, f_{b²}", &m, false),
            "symbols f_cb f_b, f_(b²)"
        );
        assert_eq!(
            math_text("(faca1-faca3)", &m, true),
            "(2(−a₁²+b₁²+c₁²)−2(−a₃²+b₃²+c₃²))"
        );
    }

    #[test]
    fn html_uses_sub_and_sup_where_unicode_has_no_glyph() {
        let m = paper_like();
        assert_eq!(math_html("\\diffCst{1}", &m, false), "d<sub>Cst,1</sub>");
        assert_eq!(math_html("a_1^2 < b", &m, false), "a₁² &lt; b");
    }

    #[test]
    fn an_unbraced_plain_script_is_a_number_or_a_name() {
        let m = paper_like();
        // a number ends at its last digit: the letter after it is the next factor
        assert_eq!(
            math_text("a^4-2a^2b^2-2a^2c^2", &m, false),
            "a⁴−2a²b²−2a²c²"
        );
        assert_eq!(math_html("-2a_3^2b_3^2", &m, false), "−2a₃²b₃²");
        assert_eq!(
            math_html("2a^2f^2 + x^0.5 + y_2.", &m, false),
            "2a²f² + x<sup>0.5</sup> + y₂."
        );
        // a name runs over its letters and their trailing digits
        assert_eq!(
            math_html("d_Cst1 d_a2 a_i^2 A_Cst", &m, false),
            "d<sub>Cst1</sub> dₐ₂ aᵢ² A<sub>Cst</sub>"
        );
        assert_eq!(plain_script("12.5x"), 4);
        assert_eq!(plain_script("1.x"), 1);
        assert_eq!(plain_script("Cst12b"), 5);
        assert_eq!(plain_script("-1"), 1);
        assert_eq!(plain_script(""), 0);
        // in LaTeX an unbraced script is one character, as before
        assert_eq!(math_text("\\nn a^22", &m, false), "a²2");
    }

    #[test]
    fn a_script_without_a_glyph_never_runs_into_the_next_symbol() {
        let m = Macros::parse("\\newcommand{\\AFcbcb}{f_{cb}}\n\\newcommand{\\AFcbb}{f_{b}}\n");
        assert_eq!(math_text("\\AFcbcb\\AFcbb", &m, false), "f_(cb)f_b");
        assert_eq!(math_text("f_cb f_b", &m, false), "f_cb f_b");
    }
}

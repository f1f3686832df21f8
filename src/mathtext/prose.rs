//! Quotes of the paper's source read as running text: words keep their spaces, `$…$` is the
//! paper's mathematics, references and layout commands become words.

use super::*;

/// Commands of running text that refer to a label or a citation: whether a space parts them
/// from the word before (`\Zitat` is the paper's `~\cite`), and the text before and after
/// the argument. The paper prints a number for a label (`\rFig{x}` is `fig.~\ref{x}`, "fig.
/// 3"); without the numbers the label stands for it: "fig. zweiframeseins", "(p4f2)".
fn reference(name: &str) -> Option<(bool, &'static str, &'static str)> {
    Some(match name {
        "rFig" => (false, "fig. ", ""),
        "rTab" => (false, "tab. ", ""),
        "rEq" | "eqref" => (false, "(", ")"),
        "ref" | "pageref" => (false, "", ""),
        "cite" => (false, "[", "]"),
        "Zitat" => (true, "[", "]"),
        "label" => (true, "(label ", ")"),
        _ => return None,
    })
}

/// Layout commands of running text: each reads as a space between words.
fn is_layout(name: &str) -> bool {
    matches!(
        name,
        "item"
            | "noindent"
            | "indent"
            | "par"
            | "newline"
            | "linebreak"
            | "newpage"
            | "smallskip"
            | "medskip"
            | "bigskip"
            | "hfill"
            | "vfill"
            | "centering"
    )
}

/// Font switches (`{\bf x}`): they print nothing.
fn is_switch(name: &str) -> bool {
    matches!(
        name,
        "bf" | "it"
            | "em"
            | "rm"
            | "tt"
            | "sc"
            | "sf"
            | "sl"
            | "small"
            | "large"
            | "Large"
            | "footnotesize"
            | "normalsize"
    )
}

/// Commands that occur only in running text or around it, never inside a formula.
fn is_text_command(name: &str) -> bool {
    reference(name).is_some()
        || is_layout(name)
        || is_text_font(name)
        || matches!(
            name,
            "put"
                | "begin"
                | "end"
                | "newcommand"
                | "caption"
                | "section"
                | "subsection"
                | "footnote"
                | "documentstyle"
                | "documentclass"
        )
}

/// Quoted source read as running text: words keep their spaces, `$…$` is LaTeX mathematics
/// (the paper's macros expanded), scripts outside it are plain notation.
struct Prose<'m> {
    macros: &'m Macros,
    r: Renderer,
}

impl Prose<'_> {
    /// One space between words: none at the start, never two.
    fn space(&mut self) {
        if !matches!(self.r.last_char(), None | Some(' ')) {
            self.r.text(" ");
        }
    }

    /// The space a command stands for: none after an opening bracket or quote either.
    fn gap(&mut self) {
        if !matches!(self.r.last_char(), Some('(' | '[' | '"' | '“' | '‘')) {
            self.space();
        }
    }

    fn run(&mut self, s: &str) {
        let mut rest = s;
        while let Some(c) = rest.chars().next() {
            rest = &rest[c.len_utf8()..];
            match c {
                '$' => rest = self.math(rest),
                '\\' => rest = self.command(rest),
                '^' | '_' => rest = self.r.script(c == '^', rest),
                '{' | '}' => {}
                '~' => self.space(),
                // TeX's dashes: `--` an en dash (ranges), `---` an em dash
                '-' if rest.starts_with("--") => {
                    self.r.text("—");
                    rest = &rest[2..];
                }
                '-' if rest.starts_with('-') => {
                    self.r.text("–");
                    rest = &rest[1..];
                }
                c if c.is_whitespace() => self.space(),
                c => self.r.text(c.encode_utf8(&mut [0; 4])),
            }
        }
    }

    /// Mathematics after its opening `$` (or `$$`) up to the closing one; returns what
    /// follows it. A dollar without its partner is the sign itself ("several $$ displays").
    fn math<'a>(&mut self, s: &'a str) -> &'a str {
        let (close, s) = match s.strip_prefix('$') {
            Some(t) => ("$$", t),
            None => ("$", s),
        };
        let Some(at) = s.find(close) else {
            self.r.text(close);
            return s;
        };
        let (inner, rest) = (&s[..at], &s[at + close.len()..]);
        for p in pieces(&self.macros.expand(inner, false), false) {
            match p {
                Piece::Text(t) => self.r.text(&t),
                p => self.r.out.push(p),
            }
        }
        rest
    }

    /// A backslash command of running text; returns what follows it.
    fn command<'a>(&mut self, s: &'a str) -> &'a str {
        let name = letters(s);
        if name.is_empty() {
            return self.escaped(s);
        }
        let rest = &s[name.len()..];
        // a reference without its braced label is a mention of the command: its name
        if let (Some((spaced, open, close)), Some((label, after))) =
            (reference(name), group(rest.trim_start()))
        {
            if spaced {
                self.gap();
            }
            let label: Vec<&str> = label.split(',').map(str::trim).collect();
            self.r.text(&format!("{open}{}{close}", label.join(", ")));
            return after;
        }
        match name {
            "put" => self.put(rest),
            "newcommand" | "renewcommand" => {
                // the name defined, not a call of it
                let (defined, after) = argument(rest);
                self.r.text(name);
                self.space();
                self.r.text(defined.trim().trim_start_matches('\\'));
                self.arguments(after)
            }
            "vspace" | "hspace" => {
                self.gap();
                argument(rest).1
            }
            // as in TeX, the spaces after the command are its own
            n if is_layout(n) => {
                self.gap();
                rest.trim_start()
            }
            n if is_switch(n) => rest,
            n if is_font(n) || is_text_font(n) => {
                let (arg, after) = argument(rest);
                self.run(arg);
                after
            }
            "l" => {
                self.r.text("ł");
                rest
            }
            "L" => {
                self.r.text("Ł");
                rest
            }
            n => match symbol(n) {
                Some(t) => {
                    self.r.text(t);
                    rest
                }
                None => self.unknown(n, rest),
            },
        }
    }

    /// A one-character command (`\%`, `\\`, `\,` …); returns what follows it. A per cent
    /// sign after a number is set apart from it: `20\%` reads "20 %".
    fn escaped<'a>(&mut self, s: &'a str) -> &'a str {
        let Some(c) = s.chars().next() else {
            return s;
        };
        match c {
            '%' => {
                if self.r.last_char().is_some_and(|p| p.is_ascii_digit()) {
                    self.r.text(" ");
                }
                self.r.text("%");
            }
            '&' | '#' | '_' | '$' | '{' | '}' => self.r.text(c.encode_utf8(&mut [0; 4])),
            '\\' | ' ' | ',' | ';' | ':' => self.space(),
            // `\-`, `\/`, `\!` and the accents print nothing of their own
            _ => {}
        }
        &s[c.len_utf8()..]
    }

    /// `\put(x,y){…}` of a picture: "label … at (x, y)".
    fn put<'a>(&mut self, s: &'a str) -> &'a str {
        let Some((at, after)) = s
            .trim_start()
            .strip_prefix('(')
            .and_then(|t| t.split_once(')'))
        else {
            return self.unknown("put", s);
        };
        let (label, rest) = argument(after);
        self.gap();
        self.r.text("label ");
        self.run(label);
        let at: Vec<&str> = at.split(',').map(str::trim).collect();
        self.r.text(&format!(" at ({})", at.join(", ")));
        rest
    }

    /// A command this reader does not know: its name, then its options and arguments as
    /// text (`\begin{table}[H]` reads "begin table[H]").
    fn unknown<'a>(&mut self, name: &str, s: &'a str) -> &'a str {
        if self.r.last_char().is_some_and(char::is_alphanumeric) {
            self.space();
        }
        self.r.text(name);
        self.arguments(s)
    }

    /// The options and braced arguments at the start of `s`, as text; returns what follows.
    fn arguments<'a>(&mut self, s: &'a str) -> &'a str {
        let mut rest = s;
        loop {
            let t = rest.trim_start();
            if let Some((arg, after)) = group(t) {
                if !arg.trim().is_empty() {
                    self.space();
                    self.run(arg);
                }
                rest = after;
            } else if let Some((option, after)) =
                t.strip_prefix('[').and_then(|o| o.split_once(']'))
            {
                self.r.text(&format!("[{option}]"));
                rest = after;
            } else {
                return rest;
            }
        }
    }
}

fn prose_pieces(s: &str, macros: &Macros) -> Vec<Piece> {
    let mut p = Prose {
        macros,
        r: Renderer {
            plain: true,
            out: Vec::new(),
        },
    };
    p.run(s);
    finished(p.r.out)
}

/// Quoted LaTeX source (or a sentence in the checks' plain notation) as readable text, with
/// the spaces between its words: `$…$` becomes mathematics (the paper's macros unexpanded:
/// see [`prose_text_in`]), `20\%` "20 %", `\rFig{x}` "fig. x", `\rTab{x}` "tab. x",
/// `\rEq{x}` "(x)", `\ref{x}` "x", `\cite{a,b}` "[a, b]", `\label{x}` "(label x)",
/// `\put(x,y){…}` "label … at (x, y)"; `\item`, `\noindent`, `\\` and `~` are spaces; an
/// unknown command shows its name and its arguments. Outside `$…$` no macro is expanded: a
/// text that names `\faca` means the macro, not its expansion.
pub fn prose_text(s: &str) -> String {
    prose_text_in(s, &Macros::default())
}

/// [`prose_text`] with the paper's macros expanded inside `$…$`.
pub fn prose_text_in(s: &str, macros: &Macros) -> String {
    text_of(&prose_pieces(s, macros))
}

/// [`prose_text_in`] as HTML (escaped; `<sub>`/`<sup>` for scripts without a glyph).
pub fn prose_html(s: &str, macros: &Macros) -> String {
    html_of(&prose_pieces(s, macros))
}

/// True when quoted source `s` reads as running text: it has a word of two or more letters
/// outside its mathematics, its command names and its scripts, or a command only text uses
/// (`\item`, `\rFig`, `\put`, `\label`, `\%` …). A formula quoted from a display without
/// `$` (`2{b}^2(-{a_i}^2+…`, `\sqrt{\deltab} ) / (2*\AFcbbdwa ) }.`) does not.
pub fn is_prose(s: &str) -> bool {
    let (mut rest, mut run) = (s, 0usize);
    while let Some(c) = rest.chars().next() {
        rest = &rest[c.len_utf8()..];
        match c {
            // mathematics up to its closing dollar is no text (a lone dollar is a sign)
            '$' => {
                let (close, t) = match rest.strip_prefix('$') {
                    Some(t) => ("$$", t),
                    None => ("$", rest),
                };
                rest = t.find(close).map_or(t, |at| &t[at + close.len()..]);
                run = 0;
            }
            '\\' => {
                let name = letters(rest);
                if is_text_command(name) || rest.starts_with('%') {
                    return true;
                }
                let n = match rest.chars().next() {
                    Some(c) if name.is_empty() => c.len_utf8(),
                    _ => name.len(),
                };
                rest = &rest[n..];
                run = 0;
            }
            '^' | '_' => {
                let t = rest.trim_start();
                rest = group(t).map_or_else(|| &t[plain_script(t)..], |(_, after)| after);
                run = 0;
            }
            c if c.is_ascii_alphabetic() => {
                run += 1;
                if run >= 2 {
                    return true;
                }
            }
            _ => run = 0,
        }
    }
    false
}

/// A quote of the paper's source as text: running text by [`prose_text_in`], a formula
/// quoted from a display by [`math_text`] (see [`is_prose`]).
pub fn quote_text(s: &str, macros: &Macros) -> String {
    if is_prose(s) {
        prose_text_in(s, macros)
    } else {
        math_text(s, macros, false)
    }
}

/// [`quote_text`] as HTML.
pub fn quote_html(s: &str, macros: &Macros) -> String {
    if is_prose(s) {
        prose_html(s, macros)
    } else {
        math_html(s, macros, false)
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::paper_like;
    use super::*;

    #[test]
    fn quoted_text_keeps_its_words_apart() {
        assert_eq!(
            prose_text(
                "However, the average performance was with 20\\% from deviation of correct values."
            ),
            "However, the average performance was with 20 % from deviation of correct values."
        );
        assert_eq!(
            prose_text("which means errors of well above 20 \\%."),
            "which means errors of well above 20 %."
        );
        assert_eq!(
            prose_text("$ k*2*p$ pieces of information available from k images."),
            "k·2·p pieces of information available from k images."
        );
        assert_eq!(
            prose_text("\\item If four frames or four points are available,"),
            "If four frames or four points are available,"
        );
        // the source's own slip stays visible
        assert_eq!(
            prose_text("assuming knowledge of$c$"),
            "assuming knowledge ofc"
        );
        assert_eq!(
            prose_text("Let us denote with $T_a$ the point"),
            "Let us denote with Tₐ the point"
        );
        assert_eq!(
            prose_text("the traced points, and $P_i,\\, Q_I,\\, R_i$ their"),
            "the traced points, and Pᵢ,\u{2009}Q_I,\u{2009}Rᵢ their"
        );
    }

    #[test]
    fn references_layout_and_pictures_read_as_text() {
        assert_eq!(
            prose_text("and three parallel lines p2, q2, r2 (see \\rFig{zweiframeseins})."),
            "and three parallel lines p2, q2, r2 (see fig. zweiframeseins)."
        );
        assert_eq!(
            prose_text(
                "Then from \\rEq{p4f2} we obtain the linear equation system for i=2, 3:\\\\"
            ),
            "Then from (p4f2) we obtain the linear equation system for i=2, 3:"
        );
        assert_eq!(
            prose_text("in \\rTab{bspp3f3tab} and\\Zitat{Tsai:1,Tsai:2}."),
            "in tab. bspp3f3tab and [Tsai:1, Tsai:2]."
        );
        assert_eq!(
            prose_text("\\put(1.094,0.796){$Q'$} \\put(1.065,1.148){$R'$}"),
            "label Q' at (1.094, 0.796) label R' at (1.065, 1.148)"
        );
        assert_eq!(
            prose_text("\\begin{table}[H] \\label{bspp3f3tab}"),
            "begin table[H] (label bspp3f3tab)"
        );
        assert_eq!(
            prose_text("K{\\l}opotek, \\noindent pages 3--5"),
            "Kłopotek, pages 3–5"
        );
        // a command named, not called; a macro defined, not called
        assert_eq!(
            prose_text("put each \\label after its \\caption"),
            "put each label after its caption"
        );
        assert_eq!(
            prose_text("\\newcommand{\\Zitat}[1]{~\\cite{#1}}"),
            "newcommand Zitat[1] [#1]"
        );
        assert_eq!(
            prose_text("\"\\item If\" or \"\\label{x}\""),
            "\"If\" or \"(label x)\""
        );
        assert_eq!(prose_text("(\\facCst{2}\\nn"), "(facCst 2 nn");
        assert_eq!(
            prose_text("\"\\newcommand{\\Bem}[1]{}\""),
            "\"newcommand Bem[1]\""
        );
        // a dollar without its partner is the sign
        assert_eq!(
            prose_text("several $$ displays, the breaks"),
            "several $$ displays, the breaks"
        );
    }

    #[test]
    fn quotes_expand_the_macros_only_inside_their_mathematics() {
        let m = paper_like();
        assert_eq!(
            prose_text_in("symbols $ \\deltab,\\AFcbbdwa$, not \\deltab", &m),
            "symbols Δ_b,f_(b²), not deltab"
        );
        assert_eq!(
            prose_html("within 20\\% of $\\diffCst{1}$ \\& <", &m),
            "within 20 % of d<sub>Cst,1</sub> &amp; &lt;"
        );
    }

    #[test]
    fn a_quote_is_text_or_a_formula() {
        let m = paper_like();
        for text in [
            "PQ QR RS TR TP TQ",
            "\\put(1,2){$Q$}",
            "\\label{x}",
            "$P_i$, $Q_I$ their",
            "20\\%",
        ] {
            assert!(is_prose(text), "{text}");
        }
        for formula in [
            "2{b}^2(-{a_i}^2+{b_i}^2 $$ $$ +{c_1}^2)+",
            "\\sqrt{\\deltab} ) / (2*\\AFcbbdwa ) }.",
            "+ 2* (\\facCst{2} \\nn\\\\ \\la -\\facCst{1})",
            "$b = \\sqrt{\\deltab}$",
            "d_Cst1 - A_Cst",
        ] {
            assert!(!is_prose(formula), "{formula}");
        }
        assert_eq!(quote_text("\\sqrt{\\deltab} )", &m), "√(Δ_b))");
        assert_eq!(
            quote_text("Then from \\rEq{p4f2} we", &m),
            "Then from (p4f2) we"
        );
        assert_eq!(quote_html("x_1 and y", &m), "x₁ and y");
    }
}

//! Every formula of the paper's cases, typeset: no sub- or superscript swallows a symbol, and
//! every symbol of the source reaches the reader in its order. The checker reads the source
//! and the output with scanners of its own (`checker`), not with the renderer's tokenizer.

use orthocheck::check::Value;
use orthocheck::claims::formula_audit::FormulaAuditCase;
use orthocheck::claims::CaseCheck;
use orthocheck::report::math::{math_html, math_text, Macros};

use crate::common;

/// An independent reading of LaTeX and plain-notation formulas and of their rendered forms.
mod checker {
    /// Which way a script goes.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Kind {
        Sup,
        Sub,
    }

    /// What a formula says: its scripts in reading order (outer before inner), each with the
    /// letters and digits it holds, and all its letters and digits in order.
    #[derive(Debug, Default, PartialEq, Eq)]
    pub struct Reading {
        pub scripts: Vec<(Kind, String)>,
        pub symbols: String,
    }

    /// The Unicode superscript glyphs, and what each stands for.
    const SUPERSCRIPTS: (&str, &str) = ("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱ", "0123456789+-=()ni");

    /// The Unicode subscript glyphs, and what each stands for.
    const SUBSCRIPTS: (&str, &str) = (
        "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜᵢⱼᵣᵤᵥ",
        "0123456789+-=()aeoxhklmnpstijruv",
    );

    /// Commands that print a glyph or nothing, never letters of their own: their names are
    /// no symbols. Every other command prints its name (a function such as `\sin`, or an
    /// unknown command), so its name counts.
    const SILENT: &str = "frac sqrt cdot times pm mp nonumber left right displaystyle big Big \
        quad qquad leq le geq ge neq ne approx infty ldots dots cdots sum prod partial in to \
        rightarrow Rightarrow alpha beta gamma delta epsilon varepsilon lambda mu pi sigma phi \
        varphi theta omega Delta Gamma Lambda Sigma Phi Omega mathrm mathit mathbf text textrm \
        mbox hat bar tilde";

    fn silent(name: &str) -> bool {
        SILENT.split_whitespace().any(|n| n == name)
    }

    fn glyph(c: char) -> Option<(Kind, char)> {
        let find = |(glyphs, plain): (&str, &str)| {
            let at = glyphs.chars().position(|g| g == c)?;
            plain.chars().nth(at)
        };
        find(SUPERSCRIPTS)
            .map(|a| (Kind::Sup, a))
            .or_else(|| find(SUBSCRIPTS).map(|a| (Kind::Sub, a)))
    }

    /// A run of script glyphs of one kind at the start of `s` (a comma between two subscript
    /// glyphs belongs to it, as in `ₐ,₁`): its kind, what it stands for, its length in bytes.
    fn glyph_run(s: &str) -> Option<(Kind, String, usize)> {
        let (kind, _) = glyph(s.chars().next()?)?;
        let (mut plain, mut len) = (String::new(), 0);
        let mut chars = s.chars().peekable();
        while let Some(c) = chars.next() {
            match glyph(c) {
                Some((k, a)) if k == kind => plain.push(a),
                _ if c == ',' && kind == Kind::Sub => {
                    if !chars
                        .peek()
                        .is_some_and(|n| glyph(*n).is_some_and(|g| g.0 == kind))
                    {
                        break;
                    }
                    plain.push(c);
                }
                _ => break,
            }
            len += c.len_utf8();
        }
        Some((kind, plain, len))
    }

    /// The inside of a `{…}` (or `(…)`) group at the start of `s`, and what follows it.
    fn enclosed(s: &str, open: char, close: char) -> Option<(&str, &str)> {
        if !s.starts_with(open) {
            return None;
        }
        let mut depth = 0usize;
        for (i, c) in s.char_indices() {
            if c == open {
                depth += 1;
            } else if c == close {
                depth -= 1;
                if depth == 0 {
                    return Some((&s[open.len_utf8()..i], &s[i + close.len_utf8()..]));
                }
            }
        }
        None
    }

    /// How far an unbraced script of the source reaches: one character in LaTeX; in plain
    /// notation a number (digits, a decimal fraction) or a name (letters, then digits).
    pub fn unbraced(t: &str, plain: bool) -> usize {
        let Some(first) = t.chars().next() else {
            return 0;
        };
        if !plain || !first.is_ascii_alphanumeric() {
            return first.len_utf8();
        }
        let bytes = t.as_bytes();
        let mut n = 0;
        let run = |n: &mut usize, f: fn(&u8) -> bool| {
            while bytes.get(*n).is_some_and(f) {
                *n += 1;
            }
        };
        if first.is_ascii_digit() {
            run(&mut n, u8::is_ascii_digit);
            if bytes.get(n) == Some(&b'.') && bytes.get(n + 1).is_some_and(u8::is_ascii_digit) {
                n += 1;
                run(&mut n, u8::is_ascii_digit);
            }
        } else {
            run(&mut n, u8::is_ascii_alphabetic);
            run(&mut n, u8::is_ascii_digit);
        }
        n
    }

    impl Reading {
        /// A script whose body `read` adds: recorded before the scripts inside it.
        fn script(&mut self, kind: Kind, read: impl FnOnce(&mut Reading)) {
            let (at, from) = (self.scripts.len(), self.symbols.len());
            self.scripts.push((kind, String::new()));
            read(self);
            self.scripts[at].1 = self.symbols[from..].to_string();
        }

        /// A character of the text: a symbol when it is a letter or digit.
        fn symbol(&mut self, c: char) {
            if c.is_ascii_alphanumeric() {
                self.symbols.push(c);
            }
        }

        /// A run of glyphs at the start of `s`, if any: one script; returns its length.
        fn glyphs(&mut self, s: &str) -> Option<usize> {
            let (kind, plain, len) = glyph_run(s)?;
            self.script(kind, |r| plain.chars().for_each(|c| r.symbol(c)));
            Some(len)
        }
    }

    /// The (macro-expanded) source of a formula; `plain` for plain notation.
    pub fn source(s: &str, plain: bool) -> Reading {
        let mut r = Reading::default();
        read_source(s, plain, &mut r);
        r
    }

    fn read_source(s: &str, plain: bool, r: &mut Reading) {
        let mut rest = s;
        while let Some(c) = rest.chars().next() {
            if let Some(n) = r.glyphs(rest) {
                rest = &rest[n..];
                continue;
            }
            rest = &rest[c.len_utf8()..];
            match c {
                '^' | '_' => {
                    let kind = if c == '^' { Kind::Sup } else { Kind::Sub };
                    let t = rest.trim_start();
                    let (body, after) =
                        enclosed(t, '{', '}').unwrap_or_else(|| t.split_at(unbraced(t, plain)));
                    r.script(kind, |r| read_source(body, plain, r));
                    rest = after;
                }
                '\\' => {
                    let n = rest
                        .find(|c: char| !c.is_ascii_alphabetic())
                        .unwrap_or(rest.len());
                    let name = &rest[..n];
                    if !silent(name) {
                        name.chars().for_each(|c| r.symbol(c));
                    }
                    // a one-character command (`\\`, `\,`, `\%`) is no symbol either
                    let n = if n == 0 {
                        rest.chars().next().map_or(0, char::len_utf8)
                    } else {
                        n
                    };
                    rest = &rest[n..];
                }
                c => r.symbol(c),
            }
        }
    }

    /// The HTML of a formula: `<sub>`/`<sup>` bodies and glyph runs are its scripts.
    pub fn html(h: &str) -> Reading {
        let mut r = Reading::default();
        let mut open: Vec<(usize, usize)> = Vec::new();
        let mut rest = h;
        while let Some(c) = rest.chars().next() {
            if let Some(n) = r.glyphs(rest) {
                rest = &rest[n..];
                continue;
            }
            let tag = ["<sub>", "<sup>", "</sub>", "</sup>"]
                .into_iter()
                .find(|t| rest.starts_with(t));
            match tag {
                Some(t) if t.starts_with("</") => {
                    let (at, from) = open.pop().unwrap_or_else(|| panic!("unopened {t}: {h}"));
                    r.scripts[at].1 = r.symbols[from..].to_string();
                }
                Some(t) => {
                    let kind = if t == "<sup>" { Kind::Sup } else { Kind::Sub };
                    open.push((r.scripts.len(), r.symbols.len()));
                    r.scripts.push((kind, String::new()));
                }
                None if c == '<' => panic!("markup other than sub and sup: {h}"),
                // an entity (`&amp;`, `&#39;`) is one character, never a letter or digit
                None if c == '&' => {
                    let end = rest.find(';').unwrap_or_else(|| panic!("a bare &: {h}"));
                    rest = &rest[end + 1..];
                    continue;
                }
                None => r.symbol(c),
            }
            rest = &rest[tag.map_or(c.len_utf8(), str::len)..];
        }
        assert!(open.is_empty(), "unclosed script: {h}");
        r
    }

    /// The plain text of a formula: `_x`, `^x` (letters and digits) and `_(…)`, `^(…)` are
    /// scripts, and so are glyph runs. A script written without parentheses is read as far
    /// as letters and digits go, as a reader would: one followed by a letter swallows it.
    pub fn text(t: &str) -> Reading {
        let mut r = Reading::default();
        read_text(t, &mut r);
        r
    }

    fn read_text(t: &str, r: &mut Reading) {
        let mut rest = t;
        while let Some(c) = rest.chars().next() {
            if let Some(n) = r.glyphs(rest) {
                rest = &rest[n..];
                continue;
            }
            rest = &rest[c.len_utf8()..];
            if c != '^' && c != '_' {
                r.symbol(c);
                continue;
            }
            let kind = if c == '^' { Kind::Sup } else { Kind::Sub };
            let (body, after) = enclosed(rest, '(', ')').unwrap_or_else(|| {
                let n = rest
                    .find(|c: char| !c.is_ascii_alphanumeric())
                    .unwrap_or(rest.len());
                rest.split_at(n)
            });
            r.script(kind, |r| read_text(body, r));
            rest = after;
        }
    }

    /// The first difference between the source's reading and the output's, if any.
    pub fn difference(source: &Reading, output: &Reading) -> Option<String> {
        if source.symbols != output.symbols {
            return Some(format!(
                "symbols {:?} became {:?}",
                source.symbols, output.symbols
            ));
        }
        let n = source.scripts.len().max(output.scripts.len());
        (0..n).find_map(|i| match (source.scripts.get(i), output.scripts.get(i)) {
            (a, b) if a == b => None,
            (a, b) => Some(format!(
                "script {} is {a:?} in the source, {b:?} shown",
                i + 1
            )),
        })
    }
}

use checker::{difference, Kind};

/// The paper's macros (`paper_cases/paper.yml`).
fn macros() -> Macros {
    let inputs = common::inputs().expect("the paper's cases load");
    Macros::parse(&inputs.paper.macros)
}

/// Each macro of the paper called with the arguments `{1}`, `{2}` …: its names read from the
/// definitions by this test, not by the renderer.
fn macro_calls(latex: &str) -> Vec<String> {
    let mut calls = Vec::new();
    for part in latex.split("\\newcommand{\\").skip(1) {
        let Some((name, rest)) = part.split_once('}') else {
            continue;
        };
        let args: usize = rest
            .strip_prefix('[')
            .and_then(|r| r.split_once(']'))
            .and_then(|(n, _)| n.trim().parse().ok())
            .unwrap_or(0);
        let args: String = (1..=args).map(|k| format!("{{{k}}}")).collect();
        calls.push(format!("\\{name}{args}"));
    }
    calls
}

/// The formulas of the formula audit: definitions, displayed formulas (printed, as printed in
/// LaTeX, corrected), the quotes they transcribe, printed arithmetic, computed statements.
fn audit_formulas(a: &FormulaAuditCase, add: &mut dyn FnMut(String, &str)) {
    for d in &a.definitions {
        add(format!("definition {}", d.name), &d.printed);
        add(format!("definition {}, LaTeX", d.name), &d.latex);
    }
    for f in &a.formulas {
        add(format!("{}/{} quote", f.claim.claim, f.id), &f.claim.quote);
        let forms = [
            ("printed", &f.printed),
            ("as printed", &f.printed_text),
            ("corrected", &f.corrected),
        ];
        for (what, s) in forms {
            if let Some(s) = s {
                add(format!("{}/{} {what}", f.claim.claim, f.id), s);
            }
        }
    }
    for x in &a.arithmetic {
        add(
            format!("{}/{} steps", x.claim.claim, x.id),
            &x.steps.join(" = "),
        );
    }
    for x in &a.computed {
        add(format!("{}/{} printed", x.claim.claim, x.id), &x.printed);
    }
}

/// Every formula the paper's cases transcribe, and each macro of the paper called, each with
/// where it comes from.
fn case_formulas() -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for case in common::cases().expect("the paper's cases load") {
        let mut add = |what: String, s: &str| out.push((format!("{}: {what}", case.id), s.into()));
        match &case.check {
            CaseCheck::FormulaAudit(a) => audit_formulas(a, &mut add),
            CaseCheck::TwofoldSquared(t) => add("polynomial".into(), &t.polynomial.printed),
            CaseCheck::DofIdentifiability(d) => {
                add("unknowns".into(), &d.formula.unknowns);
                add("measurements".into(), &d.formula.measurements);
            }
            _ => {}
        }
    }
    let inputs = common::inputs().expect("the paper's cases load");
    for call in macro_calls(&inputs.paper.macros) {
        out.push((format!("paper.yml: {call}"), call));
    }
    out
}

/// What is wrong with the typesetting of `s` in HTML and in plain text (what Markdown shows,
/// escaped for Markdown without touching letters, digits or glyphs), if anything.
fn typesetting_errors(what: &str, s: &str, macros: &Macros) -> Vec<String> {
    let plain = !s.contains('\\');
    let source = checker::source(&macros.expand(s, true), plain);
    let html = math_html(s, macros, true);
    let text = math_text(s, macros, true);
    [
        ("HTML", &html, checker::html(&html)),
        ("text", &text, checker::text(&text)),
    ]
    .into_iter()
    .filter_map(|(form, shown, read)| {
        difference(&source, &read).map(|d| format!("{what}: {form} {shown:?} of {s:?}: {d}"))
    })
    .collect()
}

/// The checker itself: it reads a swallowed symbol, and a text script run into the next
/// symbol, as the errors they are, and the correct forms as correct.
#[test]
fn the_checker_sees_a_swallowed_symbol() {
    let source = checker::source("2a^2b^2", true);
    assert_eq!(
        source.scripts,
        vec![(Kind::Sup, "2".to_string()), (Kind::Sup, "2".to_string())]
    );
    assert_eq!(source.symbols, "2a2b2");
    // the renderer's old reading: the exponent took the b
    assert!(difference(&source, &checker::html("2a<sup>2b</sup>²")).is_some());
    assert!(difference(&source, &checker::text("2a^2b²")).is_some());
    assert_eq!(difference(&source, &checker::html("2a²b²")), None);
    // a plain name takes its letters and digits; LaTeX takes one character
    let source = checker::source("d_Cst1 - f_{b ^2}", true);
    assert_eq!(
        difference(&source, &checker::html("d<sub>Cst1</sub> − f<sub>b²</sub>")),
        None
    );
    assert_eq!(difference(&source, &checker::text("d_Cst1 − f_(b²)")), None);
    assert_eq!(checker::unbraced("Cst1)", true), 4);
    assert_eq!(checker::unbraced("0.5+", true), 3);
    assert_eq!(checker::unbraced("ab", false), 1);
    // an unknown command shows its name, so its name counts; `\cdot` prints none
    assert_eq!(
        checker::source("\\AFcbcb\\cdot x", false).symbols,
        "AFcbcbx"
    );
    // `f_cbf_b` reads as one script: a text form must not write it so
    let expanded = checker::source("f_{cb}f_{b}", false);
    assert!(difference(&expanded, &checker::text("f_cbf_b")).is_some());
    assert_eq!(difference(&expanded, &checker::text("f_(cb)f_b")), None);
    assert_eq!(
        difference(&expanded, &checker::html("f<sub>cb</sub>f<sub>b</sub>")),
        None
    );
}

/// Every formula of every case and every macro of the paper, in HTML and in plain text: no
/// script swallows a symbol, no symbol is lost, moved or added.
#[test]
fn every_formula_of_the_cases_is_typeset_symbol_for_symbol() {
    let macros = macros();
    let formulas = case_formulas();
    assert!(
        formulas.len() > 80,
        "only {} formulas found",
        formulas.len()
    );
    let errors: Vec<String> = formulas
        .iter()
        .flat_map(|(what, s)| typesetting_errors(what, s, &macros))
        .collect();
    assert!(
        errors.is_empty(),
        "{} errors:\n{}",
        errors.len(),
        errors.join("\n")
    );
}

/// Every formula the report shows (printed, computed, evidence) and every correction, as the
/// report renders them.
#[test]
fn every_formula_of_the_report_is_typeset_symbol_for_symbol() {
    let macros = macros();
    let report = common::report().expect("the paper runs");
    let mut errors = Vec::new();
    let mut seen = 0usize;
    for c in &report.claims {
        let values = c
            .printed
            .iter()
            .chain(&c.computed)
            .chain(&c.evidence.details);
        for q in values {
            if let Value::Formula { text } = &q.value {
                seen += 1;
                errors.extend(typesetting_errors(
                    &format!("{} {}", c.id, q.name),
                    text,
                    &macros,
                ));
            }
        }
        if let Some(t) = &c.correction {
            seen += 1;
            errors.extend(typesetting_errors(
                &format!("{} correction", c.id),
                t,
                &macros,
            ));
        }
    }
    assert!(seen > 80, "only {seen} formulas in the report");
    assert!(
        errors.is_empty(),
        "{} errors:\n{}",
        errors.len(),
        errors.join("\n")
    );
}

/// The paper's eq. p3f3sqr as the formula audit transcribes it (Appendix A's first item):
/// `2a^2b^2` is 2a²b², not a to the power 2b.
#[test]
fn eq_p3f3sqr_reads_2a2b2() {
    let macros = macros();
    let all = common::cases().expect("the paper's cases load");
    let item = all
        .iter()
        .find_map(|c| match &c.check {
            CaseCheck::FormulaAudit(a) => a
                .formulas
                .iter()
                .find(|f| f.place.label.as_deref() == Some("p3f3sqr")),
            _ => None,
        })
        .expect("the formula audit transcribes eq. p3f3sqr");
    let printed = item.printed.as_deref().expect("a printed transcription");
    assert!(printed.starts_with("a^4+b^4+c^4-2a^2b^2"), "{printed}");
    let html = math_html(printed, &macros, true);
    let text = math_text(printed, &macros, true);
    for shown in [&html, &text] {
        assert!(
            shown.starts_with("a⁴+b⁴+c⁴−2a²b²−2a²c²−2b²c² + "),
            "{shown}"
        );
        assert!(!shown.contains("<sup>") && !shown.contains('^'), "{shown}");
    }
    // the macros of the same item expand into the same notation: −2a₁²b₁², not a₁ to 2b₁
    assert!(html.contains("−2a₁²b₁²"), "{html}");
    // and the twofold-squared case's own transcription of the equation
    let twofold = all
        .iter()
        .find_map(|c| match &c.check {
            CaseCheck::TwofoldSquared(t) => Some(&t.polynomial.printed),
            _ => None,
        })
        .expect("the twofold-squared case");
    let html = math_html(twofold, &macros, true);
    assert!(
        html.contains("−2a²b²") && html.contains("−2aᵢ²bᵢ²"),
        "{html}"
    );
    assert!(!html.contains("<sup>"), "{html}");
}

//! The lines of the paper's LaTeX source, and quotes located in them.

/// The lines of the LaTeX source.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SourceText {
    /// Line `n` (1-based) is `lines[n - 1]`.
    pub lines: Vec<String>,
}

/// A line range `a-b` (or `a`), 1-based, inclusive.
pub fn parse_lines(s: &str) -> Option<(usize, usize)> {
    let s = s.trim();
    let (a, b) = match s.split_once(['-', '–']) {
        Some((a, b)) => (a.trim().parse().ok()?, b.trim().parse().ok()?),
        None => {
            let a = s.parse().ok()?;
            (a, a)
        }
    };
    (a >= 1 && a <= b).then_some((a, b))
}

/// Whether `quote` (white space collapsed) stands in `lines[first..=last]`, starting on the
/// first line and ending on the last: a quote at the wrong lines, or at lines wider than it,
/// is not found.
pub fn quote_at(text: &SourceText, first: usize, last: usize, quote: &str) -> bool {
    let want: Vec<char> = collapse(quote).chars().collect();
    if want.is_empty() || first == 0 || last > text.lines.len() || first > last {
        return false;
    }
    // the collapsed text of the range, each character with its source line
    let mut chars: Vec<(char, usize)> = Vec::new();
    for n in first..=last {
        for w in text.lines[n - 1].split_whitespace() {
            if !chars.is_empty() {
                chars.push((' ', n));
            }
            chars.extend(w.chars().map(|c| (c, n)));
        }
    }
    chars.windows(want.len()).any(|win| {
        win[0].1 == first
            && win[want.len() - 1].1 == last
            && win.iter().zip(&want).all(|((c, _), w)| c == w)
    })
}

/// Whether `needle` (white space collapsed) stands anywhere within `lines[first..=last]`.
pub fn quote_within(text: &SourceText, first: usize, last: usize, needle: &str) -> bool {
    let want = collapse(needle);
    if want.is_empty() || first == 0 || last > text.lines.len() || first > last {
        return false;
    }
    collapse(&text.lines[first - 1..last].join("\n")).contains(&want)
}

/// White space runs as one space, trimmed.
fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// How a quote reads for the comparison: its text, a function of it.
pub type Notation<'a> = &'a dyn Fn(&str) -> String;

/// The pieces of a quote abridged with "..." or "…", each read by `read` (empty ones dropped).
fn pieces(quote: &str, read: Notation<'_>) -> Vec<String> {
    quote
        .split(" ... ")
        .flat_map(|p| p.split('…'))
        .map(read)
        .filter(|p| !p.is_empty())
        .collect()
}

/// Whether the pieces stand in order in `lines[first..=last]`, both read alike.
fn holds(
    text: &SourceText,
    first: usize,
    last: usize,
    pieces: &[String],
    read: Notation<'_>,
) -> bool {
    if pieces.is_empty() || first == 0 || last > text.lines.len() || first > last {
        return false;
    }
    let hay = read(&text.lines[first - 1..last].join("\n"));
    let mut from = 0;
    pieces.iter().all(|p| match hay[from..].find(p.as_str()) {
        Some(at) => {
            from += at + p.len();
            true
        }
        None => false,
    })
}

/// Whether `quote` stands in `lines[first..=last]` and the range is the tightest that holds
/// it: neither the range less its first line nor less its last holds it. A quote abridged
/// with "..." stands there when its pieces do, in order.
pub fn quote_tight(
    text: &SourceText,
    first: usize,
    last: usize,
    quote: &str,
    read: Notation<'_>,
) -> bool {
    let p = pieces(quote, read);
    holds(text, first, last, &p, read)
        && (first == last
            || (!holds(text, first + 1, last, &p, read) && !holds(text, first, last - 1, &p, read)))
}

/// The verbatim reading: white space collapsed.
pub fn verbatim(s: &str) -> String {
    collapse(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text() -> SourceText {
        SourceText {
            lines: ["one two", "  three\tfour ", "five", ""]
                .iter()
                .map(|s| s.to_string())
                .collect(),
        }
    }

    #[test]
    fn line_ranges_parse() {
        assert_eq!(parse_lines("119-122"), Some((119, 122)));
        assert_eq!(parse_lines("157"), Some((157, 157)));
        assert_eq!(parse_lines("12–10"), None);
        assert_eq!(parse_lines("0"), None);
        assert_eq!(parse_lines("x"), None);
    }

    #[test]
    fn a_quote_is_found_only_at_its_own_lines() {
        let t = text();
        assert!(quote_at(&t, 1, 2, "two three four"));
        assert!(quote_at(&t, 2, 2, "three four"));
        assert!(quote_at(&t, 1, 3, "two\n three four five"));
        // wider or shifted ranges, a changed word, an empty quote: not found
        assert!(!quote_at(&t, 1, 3, "two three four"));
        assert!(!quote_at(&t, 2, 3, "two three four"));
        assert!(!quote_at(&t, 1, 2, "two three fours"));
        assert!(!quote_at(&t, 1, 2, "  "));
        assert!(!quote_at(&t, 3, 9, "five"));
    }

    #[test]
    fn a_tight_range_is_found_and_a_shifted_or_wider_one_is_not() {
        let t = text();
        assert!(quote_tight(&t, 1, 2, "two three four", &verbatim));
        assert!(quote_tight(&t, 1, 3, "one ... five", &verbatim));
        // one line too many at either end, shifted by one, pieces out of order
        assert!(!quote_tight(&t, 1, 3, "two three four", &verbatim));
        assert!(!quote_tight(&t, 2, 3, "two three four", &verbatim));
        assert!(!quote_tight(&t, 1, 3, "five ... one", &verbatim));
    }
}

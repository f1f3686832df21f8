//! Numbers are written plain and in decimal: `trials: 200`, never `trials: "200"` or
//! `trials: 0xC8`.
//!
//! The YAML deserializer reads a typed number from a scalar of any style, and from any radix
//! YAML allows, so a quoted or hexadecimal number would pass unnoticed. Before the text is
//! deserialized, every untagged scalar that is a number only by a lenient reading (quoted
//! digits, a radix prefix, digit separators) is tagged `!!str`. A text field reads it as the
//! same text, so nothing changes there; a number field refuses it, and the refusal is
//! translated back to the scalar as the user wrote it.
//!
//! The same pass over the parser's events collects the file's `claim:` names, so that a
//! case file is parsed twice in all (here, and typed), not once more for its names.

use std::collections::{BTreeMap, BTreeSet};

use granit_parser::{Event, Parser, ScalarStyle};

/// The tag inserted before a marked scalar.
const TAG: &str = "!!str ";

/// A scalar tagged `!!str` because it is a number only by a lenient reading.
#[derive(Clone, Debug, PartialEq)]
struct Marked {
    /// 1-based line of the scalar.
    line: usize,
    /// 1-based column of the inserted tag in the rewritten text.
    column: usize,
    /// The scalar as written, quotes included.
    written: String,
    /// Why it is not a plain decimal number.
    quoted: bool,
}

/// The text with lenient numbers tagged, and where they are.
pub(super) struct Tagged {
    /// The rewritten text: the original where nothing was marked.
    pub text: String,
    marked: Vec<Marked>,
    /// The value of every `claim` key anywhere in the file, as written (a scalar alias
    /// resolved): up to the first syntax error, which the typed parse then reports.
    pub claims: BTreeSet<String>,
}

/// Where the parser stands in a collection: a sequence, or a mapping about to read a key or
/// the value of the key it read (`claim` or another).
enum Frame {
    Sequence,
    Key,
    Value { claim: bool },
}

/// The `claim:` values of a stream of events.
#[derive(Default)]
struct ClaimNames {
    frames: Vec<Frame>,
    /// Anchored scalars, for a `claim: *name`.
    anchored: BTreeMap<usize, String>,
    names: BTreeSet<String>,
}

impl ClaimNames {
    /// Take one event; `scalar` is the text of a scalar node or of the scalar an alias names.
    fn event(&mut self, event: &Event) {
        let scalar = match event {
            Event::Scalar(value, style, anchor, _) => {
                if *anchor != 0 {
                    self.anchored.insert(*anchor, value.to_string());
                }
                // a null value names no claim (the typed case refuses it)
                let null = *style == ScalarStyle::Plain
                    && matches!(value.as_ref(), "" | "~" | "null" | "Null" | "NULL");
                (!null).then_some(value.as_ref())
            }
            Event::Alias(id) => self.anchored.get(id).map(String::as_str),
            Event::SequenceStart(..) | Event::MappingStart(..) => None,
            Event::SequenceEnd | Event::MappingEnd => {
                self.frames.pop();
                return;
            }
            _ => return,
        };
        let next = match self.frames.last_mut() {
            Some(Frame::Key) => Some(Frame::Value {
                claim: scalar == Some("claim"),
            }),
            Some(Frame::Value { claim }) => {
                if let (true, Some(name)) = (*claim, scalar) {
                    self.names.insert(name.to_string());
                }
                Some(Frame::Key)
            }
            _ => None,
        };
        if let (Some(next), Some(top)) = (next, self.frames.last_mut()) {
            *top = next;
        }
        match event {
            Event::SequenceStart(..) => self.frames.push(Frame::Sequence),
            Event::MappingStart(..) => self.frames.push(Frame::Key),
            _ => {}
        }
    }
}

impl Tagged {
    /// Tag the lenient numbers of `text`. Text the parser cannot read is returned as it is,
    /// so that the deserializer reports the syntax error in its own words.
    pub fn new(text: &str) -> Tagged {
        let mut inserts = Vec::new();
        let mut claims = ClaimNames::default();
        for event in Parser::new_from_str(text) {
            let Ok((event, span)) = event else { break };
            claims.event(&event);
            let (value, style) = match event {
                Event::Scalar(value, style, _, None) => (value, style),
                _ => continue,
            };
            let quoted = matches!(style, ScalarStyle::SingleQuoted | ScalarStyle::DoubleQuoted);
            let lenient = match style {
                ScalarStyle::Plain => radix_or_separated(&value),
                _ if quoted => decimal(value.trim()) || radix_or_separated(value.trim()),
                _ => false,
            };
            if let (true, Some(range)) = (lenient, span.byte_range()) {
                inserts.push((range.start, range.end, quoted));
            }
        }
        Tagged {
            claims: claims.names,
            ..Tagged::rewrite(text, &inserts)
        }
    }

    fn rewrite(text: &str, inserts: &[(usize, usize, bool)]) -> Tagged {
        let mut out = String::with_capacity(text.len() + TAG.len() * inserts.len());
        let mut marked = Vec::with_capacity(inserts.len());
        let mut done = 0;
        // lines counted as the text is copied: once over the text, however many marks
        let mut line = 1;
        for &(start, end, quoted) in inserts {
            if start < done || end > text.len() || !text.is_char_boundary(start) {
                continue;
            }
            line += text[done..start].matches('\n').count();
            out.push_str(&text[done..start]);
            let line_start = out.rfind('\n').map_or(0, |i| i + 1);
            marked.push(Marked {
                line,
                column: out[line_start..].chars().count() + 1,
                written: text.get(start..end).unwrap_or_default().to_string(),
                quoted,
            });
            out.push_str(TAG);
            done = start;
        }
        out.push_str(&text[done..]);
        Tagged {
            text: out,
            marked,
            claims: BTreeSet::new(),
        }
    }

    /// The column in the original text of a column of the rewritten one, on `line`.
    pub fn original_column(&self, line: usize, column: usize) -> usize {
        let before = self
            .marked
            .iter()
            .filter(|m| m.line == line && m.column < column)
            .count();
        column.saturating_sub(before * TAG.len())
    }

    /// The refusal of a marked scalar at (`line`, `column`) of the rewritten text, if the
    /// deserializer refused one there: the position must fall within the marked scalar as
    /// rewritten (its tag, quotes and text), not merely after one on the same line.
    pub fn refusal(&self, line: usize, column: usize) -> Option<String> {
        let m = self
            .marked
            .iter()
            .filter(|m| m.line == line && m.column <= column)
            .max_by_key(|m| m.column)
            .filter(|m| column <= m.column + TAG.chars().count() + m.written.chars().count() + 2)?;
        Some(if m.quoted {
            format!(
                "{} is quoted text: a number here is written without quotes",
                m.written
            )
        } else {
            format!(
                "`{}`: a number here is written in decimal digits, without a radix prefix or separators",
                m.written
            )
        })
    }
}

/// Whether `s` reads as a decimal number: an optional sign, digits with at most one point,
/// an optional exponent (what a plain number field accepts).
fn decimal(s: &str) -> bool {
    let s = s.strip_prefix(['+', '-']).unwrap_or(s);
    let (mantissa, exponent) = match s.split_once(['e', 'E']) {
        Some((m, e)) => (m, Some(e.strip_prefix(['+', '-']).unwrap_or(e))),
        None => (s, None),
    };
    let digits = mantissa.chars().filter(char::is_ascii_digit).count();
    let points = mantissa.chars().filter(|&c| c == '.').count();
    digits > 0
        && points <= 1
        && mantissa.chars().all(|c| c.is_ascii_digit() || c == '.')
        && exponent.is_none_or(|e| !e.is_empty() && e.chars().all(|c| c.is_ascii_digit()))
}

/// Whether `s` is a number only in a radix or with separators: `0xC8`, `0o310`, `0b11`,
/// `1_000` (YAML allows them, and a reader of the file may not see a number in them).
fn radix_or_separated(s: &str) -> bool {
    let t = s.strip_prefix(['+', '-']).unwrap_or(s);
    let radix = [
        ("0x", 16),
        ("0X", 16),
        ("0o", 8),
        ("0O", 8),
        ("0b", 2),
        ("0B", 2),
    ]
    .iter()
    .any(|(p, r)| {
        t.strip_prefix(p)
            .is_some_and(|d| !d.is_empty() && d.chars().all(|c| c == '_' || c.is_digit(*r)))
    });
    let separated =
        t.contains('_') && t.chars().any(|c| c.is_ascii_digit()) && decimal(&t.replace('_', ""));
    radix || separated
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lenient_numbers_are_tagged_and_plain_ones_kept() {
        let t = Tagged::new("a: \"200\"\nb: 0xC8\nc: 200\nd: \"p3f3\"\ne: [\"4\", '9', 1_000]\n");
        assert_eq!(
            t.text,
            "a: !!str \"200\"\nb: !!str 0xC8\nc: 200\nd: \"p3f3\"\ne: [!!str \"4\", !!str '9', !!str 1_000]\n"
        );
        assert_eq!(t.original_column(5, 19), 7);
        assert!(t.refusal(1, 4).unwrap().contains("\"200\" is quoted"));
        assert!(t.refusal(2, 4).unwrap().contains("`0xC8`"));
        assert!(t.refusal(5, 19).unwrap().contains("'9'"));
        assert_eq!(t.refusal(3, 4), None);
    }

    #[test]
    fn claim_names_are_collected_wherever_a_claim_key_is() {
        let t = Tagged::new(
            "claim: a\nlist:\n  - {claim: b, x: [claim, 1]}\n  - claim: &c c\n  - claim: *c\n\
             m: {claim: [d]}\nn: {? [claim]\n   : e, claim: 1.0}\no: {claim: ~}\n",
        );
        let names: Vec<&str> = t.claims.iter().map(String::as_str).collect();
        assert_eq!(names, ["1.0", "a", "b", "c"]);
    }

    #[test]
    fn decimal_and_radix_forms() {
        for s in ["200", "-0.5", ".25", "1.5e-14", "+3"] {
            assert!(decimal(s), "{s}");
        }
        for s in ["", ".", "1.2.3", "1e", "0x10", "abc", "1 2"] {
            assert!(!decimal(s), "{s}");
        }
        for s in ["0xC8", "-0o17", "0b101", "1_000"] {
            assert!(radix_or_separated(s), "{s}");
        }
        for s in ["0x", "200", "a_b", "x_1", "0xZZ"] {
            assert!(!radix_or_separated(s), "{s}");
        }
    }
}

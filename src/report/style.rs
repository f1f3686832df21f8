//! The page's look: the stylesheet, the verdict badge colours and the contrast rule they obey
//! (WCAG 2.1 AA: text at least 4.5:1 against its background, figure series at least 3:1
//! against the white page).

use crate::check::standing::Standing;
use crate::check::Verdict;

/// WCAG AA for normal text.
pub const TEXT_CONTRAST: f64 = 4.5;
/// WCAG AA for graphical objects (figure series, legend swatches).
pub const GRAPHIC_CONTRAST: f64 = 3.0;

/// The badge background of a verdict (its text is white).
pub fn badge_background(v: Verdict) -> &'static str {
    match v {
        Verdict::Reproduced => "#2e7d32",
        Verdict::ReproducedWithinRounding => "#33691e",
        Verdict::IdentityVerified => "#1565c0",
        Verdict::HoldsGenerically => "#00695c",
        Verdict::StatisticalHolds => "#4a148c",
        Verdict::StatisticalFails => "#ad1457",
        Verdict::Erratum => "#a84300",
        Verdict::Note => "#455a64",
        Verdict::Inconclusive => "#5d4037",
        Verdict::NotReproducible => "#616161",
        Verdict::Contradicted => "#c62828",
    }
}

/// The badge background of a main result's standing (its text is white): the colour of the
/// verdict that decides it.
pub fn standing_background(s: Standing) -> &'static str {
    match s {
        Standing::Holds => badge_background(Verdict::Reproduced),
        Standing::HoldsOnceCorrected => badge_background(Verdict::Erratum),
        Standing::Fails => badge_background(Verdict::Contradicted),
        Standing::Undecided => badge_background(Verdict::Inconclusive),
    }
}

/// The badge text colour.
pub const BADGE_TEXT: &str = "#ffffff";

/// A CSS colour `#rrggbb` or `rgb(r, g, b)` as its three channels.
pub fn parse_colour(css: &str) -> Option<[u8; 3]> {
    let s = css.trim();
    if let Some(hex) = s.strip_prefix('#') {
        if hex.len() != 6 {
            return None;
        }
        let ch = |i: usize| u8::from_str_radix(hex.get(i..i + 2)?, 16).ok();
        return Some([ch(0)?, ch(2)?, ch(4)?]);
    }
    let inner = s.strip_prefix("rgb(")?.strip_suffix(')')?;
    let parts: Vec<u8> = inner
        .split(',')
        .map(|p| p.trim().parse().ok())
        .collect::<Option<_>>()?;
    match parts.as_slice() {
        [r, g, b] => Some([*r, *g, *b]),
        _ => None,
    }
}

/// Relative luminance (WCAG 2.1): the sRGB channels linearised, weighted 0.2126 / 0.7152 /
/// 0.0722.
pub fn luminance(c: [u8; 3]) -> f64 {
    let lin = |v: u8| {
        let s = f64::from(v) / 255.0;
        if s <= 0.04045 {
            s / 12.92
        } else {
            ((s + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2])
}

/// The WCAG contrast ratio of two colours, (L₁ + 0.05) / (L₂ + 0.05) with L₁ the lighter:
/// from 1 (same colour) to 21 (black on white).
pub fn contrast_ratio(a: [u8; 3], b: [u8; 3]) -> f64 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

const BASE: &str = "
*, *::before, *::after { box-sizing: border-box; }
body { font-family: system-ui, sans-serif; margin: 0 auto; max-width: 72rem; padding: 1rem 2rem; color: #222; background: #fff; line-height: 1.45; overflow-wrap: break-word; }
h1 { font-size: 1.6rem; margin-bottom: .2rem; } h2 { border-bottom: 1px solid #ccc; margin-top: 2.2rem; }
a { color: #0b57a4; } .meta { color: #555; font-size: .9rem; } code { background: #f3f3f3; padding: 0 .25rem; border-radius: 3px; }
table { border-collapse: collapse; margin: .6rem 0; max-width: 100%; } td, th { border: 1px solid #ddd; padding: .25rem .55rem; text-align: left; vertical-align: top; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
.scroll { overflow-x: auto; max-width: 100%; }
.scroll:focus-visible { outline: 2px solid #1565c0; outline-offset: 2px; }
ol.main { padding-left: 1.4rem; } ol.main li { margin: .45rem 0; } .carries { color: #444; font-size: .92rem; }
figure.map { margin: 1rem 0 1rem calc(50% - 50vw + 1rem); width: calc(100vw - 2rem); max-width: none; } figure.map svg { display: block; margin: 0 auto; }
article { border: 1px solid #e2e2e2; border-radius: 6px; padding: .6rem 1rem; margin: .9rem 0; }
article > .h { font-size: 1.02rem; margin: .2rem 0 .4rem; font-family: ui-monospace, monospace; }
a.permalink { color: inherit; text-decoration: none; } a.permalink:hover, a.permalink:focus { text-decoration: underline; }
blockquote { margin: .3rem 0; padding-left: .8rem; border-left: 3px solid #bbb; color: #444; font-style: italic; }
.badge { display: inline-block; padding: .05rem .5rem; border-radius: 1rem; font-size: .8rem; font-family: system-ui, sans-serif; font-style: normal; color: #fff; vertical-align: middle; white-space: nowrap; }
dl { display: grid; grid-template-columns: 9rem minmax(0, 1fr); gap: .15rem .8rem; margin: .3rem 0; } dt { color: #555; } dd { margin: 0; min-width: 0; }
.math { font-family: 'STIX Two Math', 'Cambria Math', 'Latin Modern Math', serif; overflow-wrap: anywhere; }
.fix { display: grid; grid-template-columns: minmax(0, 1fr) auto minmax(0, 1fr); gap: .5rem; align-items: start; margin: .3rem 0; }
.fix > div { border: 1px solid #ddd; border-radius: 4px; padding: .3rem .5rem; min-width: 0; }
.fix .label { display: block; color: #555; font-size: .8rem; font-family: system-ui, sans-serif; }
.fix .arrow { align-self: center; font-size: 1.2rem; }
details { margin-top: .4rem; } summary { cursor: pointer; color: #0b57a4; }
figure { margin: .8rem 0; max-width: 100%; } figcaption { color: #444; font-size: .88rem; margin-top: .2rem; }
.panels { display: flex; flex-wrap: wrap; gap: .5rem; } .panels svg { border: 1px solid #eee; max-width: 100%; height: auto; }
.strip { display: flex; flex-wrap: wrap; gap: .6rem; margin: 1rem 0; padding: 0; list-style: none; }
.strip > li { border: 1px solid #ddd; border-radius: 6px; padding: .4rem .7rem; flex: 1 1 10rem; }
.strip .group { font-weight: 600; display: block; } .strip .total { font-size: 1.5rem; font-weight: 700; }
.strip ul, .toc ul, .vlist ul { margin: .2rem 0; padding-left: 1.1rem; }
.toc ul.sections { list-style: none; padding-left: 0; } .toc li { margin: .1rem 0; } .toc li.sub { margin-left: 1.4rem; }
.toc details { margin: 0 0 .15rem 1.2rem; }
.filter a { margin-right: .4rem; white-space: nowrap; }
.vlist { display: none; border: 1px solid #ccc; border-radius: 6px; padding: .4rem .9rem; margin: .6rem 0; }
.vlist:target { display: block; }
#findings { border: 1px solid #ccc; border-radius: 6px; padding: .2rem 1rem .6rem; margin: 1rem 0; background: #fafafa; }
#findings p { margin: .5rem 0 .2rem; } ul.findings { margin: .1rem 0 .4rem; padding-left: 1.3rem; } ul.findings li { margin: .15rem 0; }
p.defect { margin: .3rem 0; padding: .3rem .6rem; border-left: 4px solid #b3261e; background: #fdf3f2; }
mark { background: #ffe08a; color: inherit; padding: 0 .1em; border-radius: 2px; }
dl.verdicts dd { margin-bottom: .25rem; }
#search { font: inherit; padding: .25rem .5rem; width: 100%; max-width: 24rem; margin: .5rem 0; }
@media (max-width: 40rem) {
  body { padding: .5rem .8rem; }
  dl { grid-template-columns: minmax(0, 1fr); } dt { font-weight: 600; margin-top: .3rem; }
  .fix { grid-template-columns: minmax(0, 1fr); } .fix .arrow { transform: rotate(90deg); justify-self: center; }
}
@media print {
  .filter, #search, .vlist, .permalink-hint { display: none !important; }
  details::details-content { content-visibility: visible !important; display: block !important; }
  details.evidence > summary { list-style: none; } details.evidence > summary::-webkit-details-marker { display: none; }
  .panels svg { break-inside: avoid; }
  article { break-inside: avoid-page; }
  a { color: inherit; text-decoration: none; }
  body { max-width: none; padding: 0; }
}
";

/// The whole stylesheet: the base, the badge colours, and the verdict filter (a verdict's list
/// at the URL's fragment hides the claims of every other verdict).
pub fn css() -> String {
    let mut s = String::from(BASE);
    for st in [
        Standing::Holds,
        Standing::HoldsOnceCorrected,
        Standing::Fails,
        Standing::Undecided,
    ] {
        s.push_str(&format!(
            ".badge.s-{} {{ background: {}; color: {BADGE_TEXT}; }}\n",
            st.name(),
            standing_background(st)
        ));
    }
    for v in Verdict::ALL {
        s.push_str(&format!(
            ".badge.v-{n} {{ background: {bg}; color: {BADGE_TEXT}; }}\n\
             body:has(#{a}:target) article.claim:not(.v-{n}) {{ display: none; }}\n",
            n = v.name(),
            bg = badge_background(v),
            a = super::layout::verdict_anchor(v),
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contrast_ratio_matches_the_wcag_examples() {
        let (white, black) = ([255, 255, 255], [0, 0, 0]);
        assert!((contrast_ratio(white, black) - 21.0).abs() < 1e-9);
        assert!((contrast_ratio(white, white) - 1.0).abs() < 1e-12);
        // #767676 on white is the classic just-passing grey (4.54:1); #777777 just fails
        assert!(contrast_ratio([0x76; 3], white) >= TEXT_CONTRAST);
        assert!(contrast_ratio([0x77; 3], white) < TEXT_CONTRAST);
        // the old erratum badge, white on #ef6c00, failed AA (about 3.1:1)
        let old = parse_colour("#ef6c00").unwrap_or([0; 3]);
        assert!(contrast_ratio(old, white) < TEXT_CONTRAST);
        assert!(contrast_ratio(old, white) > GRAPHIC_CONTRAST);
    }

    #[test]
    fn colours_parse_in_both_notations() {
        assert_eq!(parse_colour("#1565c0"), Some([0x15, 0x65, 0xc0]));
        assert_eq!(parse_colour("rgb(31, 119, 180)"), Some([31, 119, 180]));
        assert_eq!(parse_colour("rgb(31, 119)"), None);
        assert_eq!(parse_colour("blue"), None);
    }

    #[test]
    fn every_badge_passes_aa_for_text() {
        let text = parse_colour(BADGE_TEXT).unwrap_or([0; 3]);
        for v in Verdict::ALL {
            let bg = parse_colour(badge_background(v));
            assert!(bg.is_some(), "{}", v.name());
            let ratio = contrast_ratio(bg.unwrap_or([255; 3]), text);
            assert!(ratio >= TEXT_CONTRAST, "{}: {ratio:.2}:1", v.name());
        }
    }
}

//! `report.html` in a real browser: headless Chromium loads the page of the whole paper, runs
//! its script, every in-page link (the table of contents, the verdict counts, the claim ids)
//! lands on an element, the page is no wider than a 400 px phone, and screenshots at 1400 px
//! and 400 px are not blank; and axe-core finds no violation of WCAG 2.1 A or AA on it at
//! either width (`tests/browser/axe.mjs`, with Node.js and the packages `npm ci` installs in
//! `tests/browser`). Without Chromium, Node.js or those packages a test says SKIPPED on the
//! terminal (and fails when `ORTHOCHECK_REQUIRE_BROWSER` is set, as `.ci/run` does).

use std::collections::BTreeSet;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The browser: `$ORTHOCHECK_CHROMIUM`, else the first of the usual names on `PATH`.
fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("ORTHOCHECK_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    on_path(&["chromium", "chromium-browser", "google-chrome", "chrome"])
}

/// The first of `names` found on `PATH`.
fn on_path(names: &[&str]) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    for name in names {
        for dir in std::env::split_paths(&path) {
            let p = dir.join(name);
            if p.is_file() {
                return Some(p);
            }
        }
    }
    None
}

/// Say that `test` was skipped and why, straight to the terminal (the test harness hides what
/// a passing test prints); fail instead when `ORTHOCHECK_REQUIRE_BROWSER` is set.
fn skip(test: &str, why: &str) {
    let msg = format!("SKIPPED: {test} — {why}");
    let _ = writeln!(std::io::stderr(), "\n*** {msg} ***\n");
    assert!(
        std::env::var_os("ORTHOCHECK_REQUIRE_BROWSER").is_none(),
        "{msg}, but ORTHOCHECK_REQUIRE_BROWSER is set"
    );
}

/// The page of the whole paper, as `orthocheck report` writes it.
fn report_page() -> String {
    let r = crate::common::report().expect("the paper runs");
    let paper = orthocheck::cases::load_paper(Path::new(crate::common::CASES_DIR)).unwrap();
    orthocheck::report::html::render(&r.clone().with_paper(paper))
}

fn headless(browser: &Path, profile: &Path, extra: &[&str], url: &str) -> std::process::Output {
    let mut cmd = Command::new(browser);
    cmd.args([
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--hide-scrollbars",
        "--no-first-run",
        // the machine's network is closed: no background connections, no update checks
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-quic",
        "--virtual-time-budget=5000",
    ])
    .arg(format!("--user-data-dir={}", profile.display()))
    .args(extra)
    .arg(url);
    cmd.output().expect("chromium runs")
}

#[test]
fn report_html_in_headless_chromium() {
    let Some(browser) = chromium() else {
        skip(
            "report_html_in_headless_chromium",
            "no chromium on PATH (apt-get install -y chromium; .ci/run installs it)",
        );
        return;
    };
    let r = crate::common::report().expect("the paper runs");
    let page = report_page();
    let dir = tempfile::tempdir().unwrap();
    // one profile per launch: the five launches run at once
    let chrome = |name: &str| Browser {
        path: browser.clone(),
        profile: dir.path().join(format!("profile-{name}")),
    };
    let html = dir.path().join("report.html");
    std::fs::write(&html, &page).unwrap();
    // a copy that records its own width once laid out (the report itself stays as it is)
    let probe = dir.path().join("probe.html");
    std::fs::write(
        &probe,
        page.replace(
            "</body>",
            "<script>document.body.setAttribute('data-width', \
             document.documentElement.scrollWidth + ' ' + \
             document.documentElement.clientWidth)</script></body>",
        ),
    )
    .unwrap();
    std::thread::scope(|s| {
        s.spawn(|| {
            let out = chrome("dom").run(&["--dump-dom"], &html);
            check_links(&String::from_utf8_lossy(&out.stdout), r.claims.len());
        });
        for width in [1400, 400] {
            let (chrome, probe, html, dir) = (&chrome, &probe, &html, dir.path());
            s.spawn(move || check_width(&chrome(&format!("width-{width}")), probe, width));
            s.spawn(move || {
                check_screenshot(
                    &chrome(&format!("shot-{width}")),
                    html,
                    &dir.join(format!("shot-{width}.png")),
                    width,
                )
            });
        }
    });
}

/// axe-core (the rules tagged WCAG 2.0 and 2.1, levels A and AA) finds no violation on the
/// page at 1400 px or at 400 px: `node tests/browser/axe.mjs report.html` says which elements
/// break which rule.
#[test]
fn report_html_meets_wcag_21_aa_by_axe() {
    const TEST: &str = "report_html_meets_wcag_21_aa_by_axe";
    let Some(browser) = chromium() else {
        skip(
            TEST,
            "no chromium on PATH (apt-get install -y chromium; .ci/run installs it)",
        );
        return;
    };
    let Some(node) = on_path(&["node", "nodejs"]) else {
        skip(TEST, "no node (Node.js) on PATH");
        return;
    };
    let tool = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/browser");
    let modules = tool.join("node_modules");
    if !modules.join("axe-core/axe.min.js").is_file()
        || !modules.join("playwright-core/package.json").is_file()
    {
        skip(
            TEST,
            "axe-core and playwright-core are not installed \
             ((cd tests/browser && npm ci); .ci/run installs them)",
        );
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let html = dir.path().join("report.html");
    std::fs::write(&html, report_page()).unwrap();
    let out = Command::new(node)
        .current_dir(&tool)
        .arg("axe.mjs")
        .arg(&html)
        .env("ORTHOCHECK_CHROMIUM", &browser)
        .output()
        .expect("node runs");
    assert!(
        out.status.success(),
        "axe-core on report.html ({}):\n{}{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Headless Chromium with its own profile.
struct Browser {
    path: PathBuf,
    profile: PathBuf,
}

impl Browser {
    /// The browser's output on the local file `page`, with the `extra` arguments.
    fn run(&self, extra: &[&str], page: &Path) -> std::process::Output {
        headless(
            &self.path,
            &self.profile,
            extra,
            &format!("file://{}", page.display()),
        )
    }
}

/// The page loaded, its script ran, every claim is on it, and every in-page link lands on an
/// element.
fn check_links(dom: &str, claims: usize) {
    assert!(
        dom.contains("id=\"contents\""),
        "the page did not load: {dom:.300}"
    );
    assert!(
        dom.contains("id=\"search\""),
        "the page's script did not run"
    );
    assert_eq!(
        dom.matches("<article ").count(),
        claims,
        "every claim is on the page"
    );
    let ids: BTreeSet<&str> = dom
        .split(" id=\"")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .collect();
    let links: Vec<&str> = dom
        .split("href=\"#")
        .skip(1)
        .filter_map(|s| s.split('"').next())
        .collect();
    assert!(links.len() > 2 * claims, "{} in-page links", links.len());
    let dangling: Vec<&&str> = links.iter().filter(|l| !ids.contains(**l)).collect();
    assert!(dangling.is_empty(), "links to nowhere: {dangling:?}");
}

/// In a window `width` px wide the page does not scroll sideways.
fn check_width(chrome: &Browser, probe: &Path, width: u32) {
    let size = format!("--window-size={width},900");
    let out = chrome.run(&["--dump-dom", &size], probe);
    let dom = String::from_utf8_lossy(&out.stdout);
    // headless Chromium lays a narrow window out at its minimum width (500 px): the page
    // must fit whatever width it gets, without scrolling sideways
    let (content, view): (u32, u32) = dom
        .split("data-width=\"")
        .nth(1)
        .and_then(|s| s.split('"').next())
        .and_then(|s| s.split_once(' '))
        .and_then(|(a, b)| Some((a.parse().ok()?, b.parse().ok()?)))
        .expect("the probe reports the page width");
    assert!(
        view <= width.max(500),
        "a {width} px window is {view} px wide"
    );
    assert!(
        content <= view,
        "at {view} px the page is {content} px wide"
    );
}

/// A screenshot `width` px wide into `png` is as wide, tall enough, and not blank.
fn check_screenshot(chrome: &Browser, html: &Path, png: &Path, width: u32) {
    let shot = format!("--screenshot={}", png.display());
    let size = format!("--window-size={width},1600");
    let out = chrome.run(&[&shot, &size], html);
    let bytes = std::fs::read(png).unwrap_or_else(|e| {
        panic!(
            "no screenshot at {width} px ({e}): {}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    let image = png::decode(&bytes).expect("a PNG chromium wrote");
    assert_eq!(image.width, width);
    assert!(image.height >= 900, "{} px tall", image.height);
    let (colours, ink) = image.colours_and_ink();
    assert!(
        colours > 8,
        "at {width} px the screenshot has {colours} colours"
    );
    assert!(
        ink > 0.01,
        "at {width} px only {ink} of the screenshot is not background"
    );
    if let Some(keep) = std::env::var_os("ORTHOCHECK_KEEP_SCREENSHOTS") {
        let _ = std::fs::copy(png, Path::new(&keep).join(format!("shot-{width}.png")));
    }
}

/// Just enough PNG (8-bit RGB or RGBA, zlib, the five row filters) to look at a screenshot.
mod png {
    /// A decoded image.
    pub struct Image {
        pub width: u32,
        pub height: u32,
        channels: usize,
        pixels: Vec<u8>,
    }

    impl Image {
        /// How many distinct colours, and the share of pixels that differ from the top-left
        /// (background) one.
        pub fn colours_and_ink(&self) -> (usize, f64) {
            let px: Vec<&[u8]> = self.pixels.chunks(self.channels).collect();
            let bg = px.first().copied().unwrap_or(&[]);
            let distinct: std::collections::BTreeSet<&[u8]> = px.iter().copied().collect();
            let ink = px.iter().filter(|p| **p != bg).count();
            (distinct.len(), ink as f64 / px.len().max(1) as f64)
        }
    }

    pub fn decode(b: &[u8]) -> Option<Image> {
        if b.get(..8)? != b"\x89PNG\r\n\x1a\n" {
            return None;
        }
        let (mut pos, mut idat, mut head) = (8, Vec::new(), None);
        while pos + 8 <= b.len() {
            let len = u32::from_be_bytes(b[pos..pos + 4].try_into().ok()?) as usize;
            let kind = &b[pos + 4..pos + 8];
            let data = b.get(pos + 8..pos + 8 + len)?;
            match kind {
                b"IHDR" => head = Some(data.to_vec()),
                b"IDAT" => idat.extend_from_slice(data),
                b"IEND" => break,
                _ => {}
            }
            pos += 12 + len;
        }
        let head = head?;
        let width = u32::from_be_bytes(head[0..4].try_into().ok()?);
        let height = u32::from_be_bytes(head[4..8].try_into().ok()?);
        let channels = match (head[8], head[9], head[12]) {
            (8, 2, 0) => 3,
            (8, 6, 0) => 4,
            _ => return None,
        };
        let raw = inflate(idat.get(2..)?)?;
        let stride = width as usize * channels;
        let mut pixels = vec![0u8; stride * height as usize];
        for y in 0..height as usize {
            let row = raw.get(y * (stride + 1)..(y + 1) * (stride + 1))?;
            let (filter, src) = (row[0], &row[1..]);
            for x in 0..stride {
                let a = if x >= channels {
                    pixels[y * stride + x - channels]
                } else {
                    0
                };
                let up = if y > 0 {
                    pixels[(y - 1) * stride + x]
                } else {
                    0
                };
                let c = if y > 0 && x >= channels {
                    pixels[(y - 1) * stride + x - channels]
                } else {
                    0
                };
                let pred = match filter {
                    0 => 0,
                    1 => a,
                    2 => up,
                    3 => ((u16::from(a) + u16::from(up)) / 2) as u8,
                    4 => paeth(a, up, c),
                    _ => return None,
                };
                pixels[y * stride + x] = src[x].wrapping_add(pred);
            }
        }
        Some(Image {
            width,
            height,
            channels,
            pixels,
        })
    }

    fn paeth(a: u8, b: u8, c: u8) -> u8 {
        let p = i16::from(a) + i16::from(b) - i16::from(c);
        let (pa, pb, pc) = (
            (p - i16::from(a)).abs(),
            (p - i16::from(b)).abs(),
            (p - i16::from(c)).abs(),
        );
        if pa <= pb && pa <= pc {
            a
        } else if pb <= pc {
            b
        } else {
            c
        }
    }

    struct Bits<'a> {
        data: &'a [u8],
        pos: usize,
        bit: u32,
    }

    impl Bits<'_> {
        fn get(&mut self, n: u32) -> Option<u32> {
            let mut v = 0;
            for i in 0..n {
                let byte = *self.data.get(self.pos)?;
                v |= u32::from((byte >> self.bit) & 1) << i;
                self.bit += 1;
                if self.bit == 8 {
                    self.bit = 0;
                    self.pos += 1;
                }
            }
            Some(v)
        }
    }

    /// A canonical Huffman code as counts per length and symbols in code order (zlib's puff).
    struct Huffman {
        count: [u16; 16],
        symbol: Vec<u16>,
    }

    impl Huffman {
        fn new(lengths: &[u8]) -> Huffman {
            let mut count = [0u16; 16];
            for &l in lengths {
                count[l as usize] += 1;
            }
            count[0] = 0;
            let mut offs = [0u16; 16];
            for l in 1..15 {
                offs[l + 1] = offs[l] + count[l];
            }
            let mut symbol = vec![0u16; lengths.len()];
            for (s, &l) in lengths.iter().enumerate() {
                if l != 0 {
                    symbol[offs[l as usize] as usize] = s as u16;
                    offs[l as usize] += 1;
                }
            }
            Huffman { count, symbol }
        }

        fn decode(&self, b: &mut Bits) -> Option<u16> {
            let (mut code, mut first, mut index) = (0i32, 0i32, 0i32);
            for len in 1..16 {
                code |= b.get(1)? as i32;
                let count = i32::from(self.count[len]);
                if code - count < first {
                    return self.symbol.get((index + code - first) as usize).copied();
                }
                index += count;
                first = (first + count) << 1;
                code <<= 1;
            }
            None
        }
    }

    const LBASE: [u16; 29] = [
        3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115,
        131, 163, 195, 227, 258,
    ];
    const LEXT: [u8; 29] = [
        0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
    ];
    const DBASE: [u16; 30] = [
        1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
        2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
    ];
    const DEXT: [u8; 30] = [
        0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12,
        13, 13,
    ];

    /// Raw DEFLATE (RFC 1951).
    fn inflate(data: &[u8]) -> Option<Vec<u8>> {
        let mut b = Bits {
            data,
            pos: 0,
            bit: 0,
        };
        let mut out = Vec::new();
        loop {
            let last = b.get(1)?;
            match b.get(2)? {
                0 => {
                    if b.bit != 0 {
                        b.bit = 0;
                        b.pos += 1;
                    }
                    let len = usize::from(u16::from_le_bytes([
                        *data.get(b.pos)?,
                        *data.get(b.pos + 1)?,
                    ]));
                    b.pos += 4;
                    out.extend_from_slice(data.get(b.pos..b.pos + len)?);
                    b.pos += len;
                }
                1 => {
                    let mut l = [8u8; 288];
                    l[144..256].fill(9);
                    l[256..280].fill(7);
                    block(&mut b, &mut out, &Huffman::new(&l), &Huffman::new(&[5; 30]))?;
                }
                2 => {
                    let (lit, dist) = dynamic(&mut b)?;
                    block(&mut b, &mut out, &lit, &dist)?;
                }
                _ => return None,
            }
            if last == 1 {
                return Some(out);
            }
        }
    }

    fn dynamic(b: &mut Bits) -> Option<(Huffman, Huffman)> {
        const ORDER: [usize; 19] = [
            16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
        ];
        let nlen = b.get(5)? as usize + 257;
        let ndist = b.get(5)? as usize + 1;
        let ncode = b.get(4)? as usize + 4;
        let mut cl = [0u8; 19];
        for &o in ORDER.iter().take(ncode) {
            cl[o] = b.get(3)? as u8;
        }
        let code = Huffman::new(&cl);
        let mut lengths = Vec::with_capacity(nlen + ndist);
        while lengths.len() < nlen + ndist {
            match code.decode(b)? {
                s @ 0..=15 => lengths.push(s as u8),
                16 => {
                    let prev = *lengths.last()?;
                    let n = 3 + b.get(2)?;
                    lengths.extend(std::iter::repeat_n(prev, n as usize));
                }
                17 => {
                    let n = 3 + b.get(3)?;
                    lengths.extend(std::iter::repeat_n(0, n as usize));
                }
                _ => {
                    let n = 11 + b.get(7)?;
                    lengths.extend(std::iter::repeat_n(0, n as usize));
                }
            }
        }
        Some((
            Huffman::new(&lengths[..nlen]),
            Huffman::new(&lengths[nlen..nlen + ndist]),
        ))
    }

    fn block(b: &mut Bits, out: &mut Vec<u8>, lit: &Huffman, dist: &Huffman) -> Option<()> {
        loop {
            let s = lit.decode(b)? as usize;
            if s < 256 {
                out.push(s as u8);
            } else if s == 256 {
                return Some(());
            } else {
                let i = s - 257;
                let len = usize::from(*LBASE.get(i)?) + b.get(u32::from(LEXT[i]))? as usize;
                let d = dist.decode(b)? as usize;
                let back = usize::from(*DBASE.get(d)?) + b.get(u32::from(DEXT[d]))? as usize;
                let start = out.len().checked_sub(back)?;
                for k in 0..len {
                    out.push(out[start + k]);
                }
            }
        }
    }
}

//! The paper's LaTeX source, an optional input: given (`--paper FILE` or the environment
//! variable [`PAPER_ENV`]), it verifies the transcription of `paper_cases/` against the source
//! whose SHA-256 `paper.yml` records. Without it everything runs, and the report says that the
//! transcription was not verified.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

use super::quote::SourceText;
use crate::error::{Error, InputLocation, Result};

/// The environment variable naming the paper's LaTeX source when `--paper` does not.
pub const PAPER_ENV: &str = "ORTHOCHECK_PAPER";

/// The source a transcription was made from, as `paper.yml` records it.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct SourceRecord {
    /// The file's name as distributed.
    pub file: String,
    /// Its SHA-256, lower-case hex.
    pub sha256: String,
}

/// A LaTeX source whose hash is the recorded one.
#[derive(Clone, Debug, PartialEq)]
pub struct LatexSource {
    /// Where it was read from.
    pub path: PathBuf,
    /// Its SHA-256, lower-case hex.
    pub sha256: String,
    /// Its lines.
    pub text: SourceText,
}

/// The SHA-256 of `bytes`, lower-case hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The source to verify against: `arg` when given, else the file [`PAPER_ENV`] names (an
/// empty value names none).
pub fn source_path(arg: Option<&Path>) -> Option<PathBuf> {
    arg.map(Path::to_path_buf).or_else(|| {
        std::env::var_os(PAPER_ENV)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    })
}

impl LatexSource {
    /// Read `path` and refuse it unless its SHA-256 is `record`'s: a transcription is
    /// verified only against the source it was made from.
    pub fn read(path: &Path, record: &SourceRecord) -> Result<LatexSource> {
        let limit = crate::limits::INPUT_BYTES;
        let bytes = read_limited(path, limit)?;
        let sha256 = sha256_hex(&bytes);
        if sha256 != record.sha256 {
            return Err(Error::Input {
                location: InputLocation::file(path),
                message: format!(
                    "not the paper's source the transcription was made from: its SHA-256 is {sha256}, \
                     paper.yml records {} ({})",
                    record.sha256, record.file
                ),
            });
        }
        let raw = String::from_utf8(bytes).map_err(|_| Error::Input {
            location: InputLocation::file(path),
            message: "the file is not UTF-8 text".into(),
        })?;
        Ok(LatexSource {
            path: path.to_path_buf(),
            sha256,
            text: SourceText {
                lines: raw.split('\n').map(str::to_string).collect(),
            },
        })
    }
}

/// The bytes of `path`, refused beyond `limit` bytes (read no further than that).
pub(crate) fn read_limited(path: &Path, limit: u64) -> Result<Vec<u8>> {
    use std::io::Read as _;
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .map_err(io)?
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(Error::Input {
            location: InputLocation::file(path),
            message: format!("larger than the limit of {limit} bytes (see docs/limits.md)"),
        });
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hash_is_sha256() {
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn a_source_with_another_hash_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("paper.tex");
        std::fs::write(&path, "abc").unwrap();
        let mut record = SourceRecord {
            file: "paper.tex".into(),
            sha256: sha256_hex(b"abd"),
        };
        let e = LatexSource::read(&path, &record).unwrap_err().to_string();
        assert!(e.contains("not the paper's source"), "{e}");
        record.sha256 = sha256_hex(b"abc");
        let ok = LatexSource::read(&path, &record).unwrap();
        assert_eq!(ok.text.lines, ["abc"]);
    }
}

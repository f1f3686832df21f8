//! Where an audit item sits in the paper: what `orthocheck audit` shows of every audited kind.

use std::fmt;

use serde::Deserialize;

/// Where an audit item sits in the paper.
#[derive(Clone, Debug, Deserialize, PartialEq, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Place {
    /// Section as numbered ("2.2", "A").
    pub section: String,
    /// Equation label, if any.
    #[serde(default)]
    pub label: Option<String>,
    /// The LaTeX macros involved.
    #[serde(default)]
    pub macros: Vec<String>,
}

impl fmt::Display for Place {
    /// `§5.2, label p4f2, macros \faca \facb`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "§{}", self.section)?;
        if let Some(l) = &self.label {
            write!(f, ", label {l}")?;
        }
        if !self.macros.is_empty() {
            write!(f, ", macros {}", self.macros.join(" "))?;
        }
        Ok(())
    }
}

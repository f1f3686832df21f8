//! The census schema the three census kinds share: claims decided over seeded scenes.

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::check::{ClaimBuilder, ResultBuilder};
use crate::error::Result;
use crate::limits;

/// A claim decided over seeded random scenes.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CensusDesign {
    /// The claims decided.
    pub claims: Vec<ClaimRef>,
    /// Frames per scene.
    pub frames: usize,
    /// Scenes.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// Result suffixes per claim id, for a claim whose result sits beside others of the same
    /// claim (`abstract-linear: four-frames` gives the id `abstract-linear/four-frames`).
    #[serde(default)]
    pub suffixes: std::collections::BTreeMap<String, String>,
    /// A degenerate configuration the census finds and the paper never names: which claim it
    /// qualifies, and the suffix of the result that states it.
    #[serde(default)]
    pub exception: Option<CensusException>,
}

/// A degenerate configuration qualifying one claim of a census.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CensusException {
    /// The claim id it qualifies (one of the case's claims).
    pub qualifies: String,
    /// The suffix of the result that states it.
    pub suffix: String,
}

/// Suffixes and the exception must name claims of the census.
pub(crate) fn census_names(c: &CensusDesign, v: &Validator) -> Result<()> {
    let known = |id: &String| c.claims.iter().any(|k| &k.claim == id);
    if let Some(id) = c.suffixes.keys().find(|id| !known(id)) {
        return v.err("suffixes", format!("{id} is not one of the claims"));
    }
    match &c.exception {
        Some(e) if !known(&e.qualifies) => v.err(
            "exception.qualifies",
            format!("{} is not one of the claims", e.qualifies),
        ),
        _ => Ok(()),
    }
}

pub(crate) fn p4f3_checks(c: &CensusDesign, v: &Validator) -> Result<()> {
    if c.trials == 0 || c.claims.is_empty() || c.frames != 3 {
        return v.err("", "needs a claim, a trial and 3 frames".into());
    }
    census_names(c, v)
}

/// The p3f3 census (`needed` 3: exactly 3 frames) and the p3f4 census (`needed` 4: at least 4).
pub(crate) fn p3_census(c: &CensusDesign, needed: usize, v: &Validator) -> Result<()> {
    if c.trials == 0 || c.claims.is_empty() {
        return v.err("", "needs at least one claim and one trial".into());
    }
    census_names(c, v)?;
    if c.frames < needed || (needed == 3 && c.frames != 3) {
        return v.err(
            "check",
            format!(
                "frames must be {}",
                if needed == 3 { "3" } else { "at least 4" }
            ),
        );
    }
    Ok(())
}

/// The census's sizes within their limits.
pub(crate) fn sizes(c: &CensusDesign, v: &Validator) -> Result<()> {
    v.limit("trials", "trials", c.trials, limits::CASE_TRIALS)?;
    v.limit("frames", "frames", c.frames, limits::DOF_FRAMES)?;
    v.limit(
        "trials",
        "trials × frames",
        c.trials.saturating_mul(c.frames),
        limits::CASE_CENSUS_WORK,
    )
}

/// The result id of `claim` in a census case: its suffix from the case, when it has one.
pub(crate) fn census_claim<'b>(
    b: &'b ResultBuilder,
    case: &'b CensusDesign,
    claim: &'b ClaimRef,
) -> ClaimBuilder<'b> {
    match case.suffixes.get(&claim.claim) {
        Some(s) => b.claim(claim).suffix(s),
        None => b.claim(claim),
    }
}

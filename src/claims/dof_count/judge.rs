//! The judge of §2.1's worked counts: the printed unknowns and measurements against the count,
//! with the Jacobian rank at a generic scene as the real answer.

use num_bigint::BigInt;

use super::DofCountCase;
use crate::check::{ClaimResult, Evidence, Power, ResultBuilder, Tolerance, Verdict};
use crate::claims::shared::rank::rank_evidence;
use crate::derivations::dof::{count, identifiability};
use crate::error::Result;

/// The printed worked counts.
pub(super) fn results(b: &ResultBuilder, case: &DofCountCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();
    for ex in &case.examples {
        let c = count(ex.points, ex.frames);
        let printed_u = ex.unknowns.to_integer();
        let printed_m = ex.measurements.to_integer();
        let agree = printed_u == Some(BigInt::from(c.unknowns))
            && printed_m == Some(BigInt::from(c.measurements));
        let r = identifiability(ex.points, ex.frames, case.seed)?;
        let result = b
            .claim(&ex.claim)
            .printed("unknowns", &ex.unknowns)
            .printed("measurements", &ex.measurements)
            .computed("unknowns", c.unknowns)
            .computed("measurements", c.measurements)
            .computed("jacobian rank", r.exact_rank)
            .computed("parameters", r.parameters)
            .computed("deficiency", r.deficiency)
            .tolerance(Tolerance::exact("integer counts"))
            .power(Power::exact_value(&format!(
                "only unknowns {} and measurements {} pass; any other printed integer is contradicted",
                c.unknowns, c.measurements
            )))
            .evidence(rank_evidence(
                Evidence::new("the paper's count evaluated exactly; Jacobian rank at a generic rational scene as the real answer")
                    .with("points", ex.points)
                    .with("frames", ex.frames)
                    .with("balance (measurements − unknowns)", c.balance),
                &r,
            ))
            .verdict(Verdict::holds(agree));
        out.push(result);
    }
    Ok(out)
}

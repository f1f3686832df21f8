//! Evidence of a rank decision (§2.1): the Jacobian's size, its ranks, numeric and exact.

use crate::check::{Evidence, Value};
use crate::derivations::dof::Identifiability;

pub(crate) fn rank_evidence(e: Evidence, r: &Identifiability) -> Evidence {
    let e = e
        .with(
            "jacobian rows",
            usize::try_from(r.count.measurements).unwrap_or_default(),
        )
        .with("jacobian columns", r.parameters)
        .with("svd rank", r.jacobian_rank)
        .with("exact rank", r.exact_rank)
        .with("exact rank method", Value::label(r.exact_method.describe()))
        .with("deficiency (dimension of the ambiguity)", r.deficiency);
    let e = match r.condition {
        Some(c) => e.with("condition number", Value::real(c)),
        None => e.with("condition number", Value::label("none (rank-deficient)")),
    };
    e.with("scene seed", r.seed)
}

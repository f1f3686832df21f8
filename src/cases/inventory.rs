//! The claim inventory of a cases folder (`claims.md`, and `additional-claims.md` beside it):
//! the ids a case may name, so that a typo is refused as the file is read instead of
//! deciding a claim the paper does not make.

use std::collections::BTreeSet;

/// The inventory's file names, in the cases folder.
pub const INVENTORY_FILES: [&str; 2] = ["claims.md", "additional-claims.md"];

/// The first cell of each row of the table headed `| id | …`, without the header and the
/// `|---|` rule.
pub fn inventory_ids(text: &str) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    let mut in_table = false;
    for line in text.lines().map(str::trim) {
        let Some(row) = line.strip_prefix('|') else {
            in_table = false;
            continue;
        };
        let first = row.split('|').next().unwrap_or("").trim().trim_matches('`');
        if first == "id" {
            in_table = true;
        } else if in_table && !first.starts_with("---") && !first.is_empty() {
            ids.insert(first.to_string());
        }
    }
    ids
}

/// `id` or `id/suffix` with `id` an inventory id.
pub fn refers_to_inventory(reference: &str, ids: &BTreeSet<String>) -> bool {
    ids.contains(reference)
        || reference
            .split_once('/')
            .is_some_and(|(id, _)| ids.contains(id))
}

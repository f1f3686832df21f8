//! Permutations of assignments: the one enumeration every correspondence search uses.

/// All permutations of 0‥n, in lexicographic order (n! of them).
///
/// # Example
/// ```
/// use orthocheck_core::algebra::permutations;
/// assert_eq!(permutations(3).len(), 6);
/// assert_eq!(permutations(3)[1], vec![0, 2, 1]);
/// ```
pub fn permutations(n: usize) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut p: Vec<usize> = (0..n).collect();
    loop {
        out.push(p.clone());
        // next lexicographic permutation
        let Some(i) = (1..n).rev().find(|&i| p[i - 1] < p[i]) else {
            return out;
        };
        let j = (i..n).rev().find(|&j| p[j] > p[i - 1]).unwrap_or(i);
        p.swap(i - 1, j);
        p[i..].reverse();
    }
}

/// The 24 permutations of 0‥4 as arrays, in lexicographic order.
pub fn permutations4() -> Vec<[usize; 4]> {
    permutations(4)
        .into_iter()
        .map(|p| [p[0], p[1], p[2], p[3]])
        .collect()
}

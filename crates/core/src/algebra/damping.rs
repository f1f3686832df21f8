//! Levenberg–Marquardt's damping, updated by Nielsen's rule: after an accepted step of gain
//! ratio ρ (actual over predicted reduction), λ ← λ · max(1/3, 1 − (2ρ − 1)³) and ν ← 2; after a
//! rejected one, λ ← λ · ν and ν ← 2ν (Madsen, Nielsen & Tingleff, "Methods for non-linear
//! least squares problems", §3.2). One rule for every Levenberg–Marquardt loop.

/// The damping λ and its growth factor ν.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Damping {
    /// λ, added to the normal matrix's diagonal.
    pub lambda: f64,
    nu: f64,
}

impl Damping {
    /// Marquardt's start: 10⁻³ of the normal matrix's largest diagonal entry (at least the
    /// smallest positive number, so that λ > 0).
    pub fn from_diagonal_max(max: f64) -> Damping {
        Damping {
            lambda: 1e-3 * max.max(f64::MIN_POSITIVE),
            nu: 2.0,
        }
    }

    /// Damping λ with the growth factor's start, ν = 2 (for a scaled damping, where λ is
    /// relative to each parameter's own curvature).
    pub fn with_lambda(lambda: f64) -> Damping {
        Damping { lambda, nu: 2.0 }
    }

    /// After a step accepted with gain ratio `rho`.
    pub fn accepted(&mut self, rho: f64) {
        self.lambda *= (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
        self.nu = 2.0;
    }

    /// After a rejected step.
    pub fn rejected(&mut self) {
        self.lambda *= self.nu;
        self.nu *= 2.0;
    }
}

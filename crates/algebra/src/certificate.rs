//! Certificates: a construction's defining property decided as an exact identity.
//!
//! A [`Certificate`] names the property (`"x²+y²+z²−w² ≡ 0 (unit sphere)"`), says
//! whether it holds, and on failure carries a residual that shows how it fails
//! (for an exact scalar: the non-zero residual polynomial or value; for `f64`: the
//! largest absolute residual found).

use core::fmt;

/// The verdict of an exact (or, for `f64`, tolerance-based) check of a defining property.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Certificate {
    /// The property, as a formula a user can read.
    pub property: String,
    /// `true` if the property holds (exactly, for exact scalars).
    pub holds: bool,
    /// On failure, a description of the residual (`None` when the property holds).
    pub residual: Option<String>,
    /// `true` if the verdict is an exact proof (exact scalar), `false` for `f64`.
    pub exact: bool,
}

impl Certificate {
    /// A certificate that holds.
    pub fn holds(property: impl Into<String>, exact: bool) -> Self {
        Certificate {
            property: property.into(),
            holds: true,
            residual: None,
            exact,
        }
    }

    /// A certificate that fails with the given residual.
    pub fn fails(property: impl Into<String>, residual: impl Into<String>, exact: bool) -> Self {
        Certificate {
            property: property.into(),
            holds: false,
            residual: Some(residual.into()),
            exact,
        }
    }

    /// Holds iff `residual_is_zero`; `residual` is only formatted on failure.
    pub fn decide(
        property: impl Into<String>,
        residual_is_zero: bool,
        exact: bool,
        residual: impl FnOnce() -> String,
    ) -> Self {
        if residual_is_zero {
            Self::holds(property, exact)
        } else {
            Self::fails(property, residual(), exact)
        }
    }

    /// All certificates hold.
    pub fn all_hold(certs: &[Certificate]) -> bool {
        certs.iter().all(|c| c.holds)
    }
}

impl fmt::Display for Certificate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = if self.exact { "exact" } else { "f64" };
        match (&self.residual, self.holds) {
            (_, true) => write!(f, "[holds, {kind}] {}", self.property),
            (Some(r), false) => write!(f, "[FAILS, {kind}] {} — residual {r}", self.property),
            (None, false) => write!(f, "[FAILS, {kind}] {}", self.property),
        }
    }
}

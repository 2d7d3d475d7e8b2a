//! Envelopes of two-parameter sphere families (D. Gruber, "Rationale Parametrisierungen von
//! Kugelhüllflächen", 2008, chapter 3).
//!
//! * [`sphere_family`]: the construction of §3.2 from a line net ([`crate::lines::LineNet`])
//!   and two support functions: the cyclographic preimage `Φ` solves the linear system
//!   (3.7), the net's fibration reparametrizes it over the absolute quadric Ω (3.16), and the
//!   isotropic projection gives the rational envelope `Ψ(s, t)` (both sheets); the direct
//!   envelope `S ∩ S_u ∩ S_v` of §3.1.1 as an independent check; the subcases 3.3.1–3.5.3.
//! * [`recognition`]: a given rational family `Φ(u, v)` (centre, radius) → its line net
//!   (the normal lines span a linear congruence), support functions and envelope, or a
//!   named reason why not (not two-parametric, no real envelope, not a fibration, axes over
//!   `Q(√d)`, non-polynomial support functions).
//!
//! Derivations and corrections of the printed formulas: `docs/math/sphere-families.md`.

pub mod contacts;
pub mod quadratic_class;
pub mod recognition;
pub mod sphere_family;

pub use quadratic_class::peters_reif_class;
pub use recognition::{FamilyContacts, Recognition, RecognitionError, SphereFamily};
pub use sphere_family::{
    CyclographicEnvelope, DirectEnvelope, EnvelopedSphere, Reductions, SphereFamilyEnvelope,
    SphereFamilyError, Subcase, Support,
};

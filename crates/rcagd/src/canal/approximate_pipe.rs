//! Pipes around any rational spine: exact where the spine allows it, else exact around a
//! certified PH approximation of the spine (docs/math/pipes.md, "Pipes around any spine").
//!
//! A pipe of radius `r` around `m(t)` is rational over `Q` exactly when `|m′|²` is a sum of
//! two squares in `Q[t]` (Peternell–Pottmann 1997, "Computing rational parametrizations of
//! canal surfaces"); for most imported B-spline spines it is not. Such a spine is replaced by
//! a `G¹` spline of spatial PH quintics within a certified distance `ε` of it
//! ([`crate::ph::approximation`]), and the pipe around each quintic is built exactly
//! ([`super::pipe_around_ph_exportable`]; the whole spline checked for self-intersection,
//! [`super::check_ph_chain_embedded`]). The result is the exact pipe of a spine within `ε` of
//! the given one: every point of it lies within `ε` of the ideal pipe's point set and
//! conversely (the tubes are the sets of points at distance `|r|` from their spines, and the
//! spines are within Hausdorff distance `ε`).

use super::envelope::Method;
use super::envelope::Orientation;
use super::exportable::{
    check_ph_chain_embedded, pipe_along_chain, pipe_around_ph_checked, ExportableCanal, PipeChain,
};
use super::CanalError;
use crate::ph::approximation::{
    approximate_by_ph_quintics, PhApproximationOptions, PhSplineApproximation,
};
use crate::Certified;
use rayon::prelude::*;
use rcagd_algebra::{format_scalar, Certificate, Rational};
use rcagd_geom::{BezierCurve, BezierPatch};

/// When [`pipe_along_spine`] approximates the spine.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ApproximationPolicy {
    /// Exact around the given spine, or an error (as [`pipe_along_chain`]).
    Never,
    /// Exact around the given spine where it is rational over `Q`, else around a PH spline
    /// approximation of the whole spine.
    #[default]
    Auto,
    /// Always around a PH spline approximation.
    Always,
}

/// The exact pipe around a certified PH spline approximation of a spine.
#[derive(Debug, Clone, PartialEq)]
pub struct ApproximatePipe {
    spline: PhSplineApproximation,
    pipe: PipeChain,
    radius: Rational,
}

impl ApproximatePipe {
    /// The PH spline the pipe is exact around.
    pub fn spline(&self) -> &PhSplineApproximation {
        &self.spline
    }

    /// The pipe around each PH piece.
    pub fn pieces(&self) -> &[ExportableCanal] {
        self.pipe.pieces()
    }

    /// The certified bound on the distance between the PH spline and the given spine.
    pub fn deviation(&self) -> Rational {
        self.spline.deviation()
    }

    /// All patches (every Bernstein weight `> 0`), piece after piece.
    pub fn patches(&self) -> Vec<BezierPatch<Rational>> {
        self.pipe.patches()
    }

    /// The total number of control points.
    pub fn control_points(&self) -> usize {
        self.pipe.control_points()
    }
}

impl Certified for ApproximatePipe {
    /// The spline's certificates (PH pieces, distance to the spine, `G¹` joints) and every
    /// piece's pipe certificates (canal identities, positive weights, `r·κ < 1`), with a
    /// statement of the spine deviation.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = self.spline.certify();
        out.extend(self.pipe.certify());
        let eps = self.deviation();
        out.push(Certificate::decide(
            format!(
                "the pipe of radius {} is exact around a PH spline within ε = {} of the given spine (spine deviation; the pipe lies within ε of the ideal pipe)",
                format_scalar(&self.radius),
                format_scalar(&eps)
            ),
            eps <= *self.spline.tolerance(),
            true,
            || "the deviation exceeds the tolerance".into(),
        ));
        out
    }
}

/// A pipe around a spine: exact around the spine itself, or exact around a certified PH
/// approximation of it.
#[derive(Debug, Clone, PartialEq)]
pub enum SpinePipe {
    /// Exact around the given spine.
    Exact(PipeChain),
    /// Exact around a PH spline within a certified distance of the spine.
    Approximate(ApproximatePipe),
}

impl SpinePipe {
    /// All patches.
    pub fn patches(&self) -> Vec<BezierPatch<Rational>> {
        match self {
            SpinePipe::Exact(c) => c.patches(),
            SpinePipe::Approximate(a) => a.patches(),
        }
    }

    /// The total number of control points.
    pub fn control_points(&self) -> usize {
        match self {
            SpinePipe::Exact(c) => c.control_points(),
            SpinePipe::Approximate(a) => a.control_points(),
        }
    }

    /// The certified spine deviation (`0` for an exact pipe).
    pub fn deviation(&self) -> Rational {
        match self {
            SpinePipe::Exact(_) => Rational::ZERO,
            SpinePipe::Approximate(a) => a.deviation(),
        }
    }
}

impl Certified for SpinePipe {
    fn certify(&self) -> Vec<Certificate> {
        match self {
            SpinePipe::Exact(c) => c.certify(),
            SpinePipe::Approximate(a) => a.certify(),
        }
    }
}

/// `true` for the errors that approximating the spine can cure: the spine's `|m′|²` needs a
/// quadratic field (possibly inside one piece of a chain).
fn needs_field(e: &CanalError) -> bool {
    match e {
        CanalError::IrrationalSplit { .. }
        | CanalError::NeedsLargerExtension(_)
        | CanalError::NotExportable { .. } => true,
        CanalError::SpinePiece { source, .. } => needs_field(source),
        _ => false,
    }
}

/// The pipe of radius `r` around a chain of rational spine curves in 3-space (each on
/// `t ∈ [0, 1]`, as [`pipe_along_chain`]).
///
/// With [`ApproximationPolicy::Auto`] the pipe is exact around the given spine where that is
/// rational over `Q`; otherwise the whole spine is replaced by a `G¹` spline of spatial PH
/// quintics within `tolerance` of it (default: `10⁻⁶` of the diagonal of the spine's
/// control-point box, [`PhApproximationOptions::relative`]) and the pipe is exact around
/// each quintic; the certificates report the certified spine deviation.
///
/// # Errors
/// As [`pipe_along_chain`] (with [`ApproximationPolicy::Never`], or for errors other than a
/// needed quadratic field); [`CanalError::SpineApproximation`] when the tolerance cannot be
/// met (or is `≤ 0`), the spine has a zero tangent or a weight `≤ 0`;
/// [`CanalError::SpinePiece`] wrapping the error of the pipe around one PH piece (for
/// example [`CanalError::RadiusNotBelowCurvatureRadius`]).
pub fn pipe_along_spine(
    spine: &[BezierCurve<Rational>],
    radius: &Rational,
    orientation: Orientation,
    policy: ApproximationPolicy,
    tolerance: Option<&Rational>,
) -> Result<SpinePipe, CanalError> {
    if policy != ApproximationPolicy::Always {
        match pipe_along_chain(spine, radius, orientation) {
            Ok(c) => return Ok(SpinePipe::Exact(c)),
            Err(e) if policy == ApproximationPolicy::Auto && needs_field(&e) => {}
            Err(e) => return Err(e),
        }
    }
    if radius == &Rational::ZERO {
        return Err(CanalError::InvalidArgument(
            "the pipe radius must be non-zero".into(),
        ));
    }
    let options = match tolerance {
        Some(t) => PhApproximationOptions::new(t.clone()),
        None => PhApproximationOptions::relative(spine),
    };
    let spline = approximate_by_ph_quintics(spine, &options)?;
    let (zero, one) = (Rational::ZERO, Rational::ONE);
    // the pipes around the pieces are independent: built in parallel, kept in order (the
    // first failing piece's error is reported)
    let pieces = spline
        .pieces()
        .par_iter()
        .enumerate()
        .map(rcagd_algebra::budget::inherit(
            |(k, p): (usize, &crate::ph::approximation::ApproximationPiece)| {
                pipe_around_ph_checked(
                    &p.curve,
                    radius,
                    (&zero, &one),
                    orientation,
                    Method::Lowest,
                    false,
                )
                .map_err(|e| CanalError::SpinePiece {
                    index: k,
                    source: Box::new(e),
                })
            },
        ))
        .collect::<Vec<_>>()
        .into_iter()
        .collect::<Result<Vec<_>, _>>()?;
    // the global check of the whole PH spline (after the pieces' local regularity)
    let curves: Vec<_> = spline.pieces().iter().map(|p| &p.curve).collect();
    let global = check_ph_chain_embedded(&curves, radius)?;
    let mut pieces = pieces;
    let mut seam = Vec::new();
    if spline.is_closed() {
        // a closed spline (the spine is G¹-closed): the rings are matched around the seam,
        // as for an exact closed spine (`pipe_along_chain`); a seam that cannot be tiled
        // with positive weights within the limits stays open, exact and certified
        let mut closing = pieces.clone();
        match super::seam::close_rings(&mut closing) {
            Ok(certs) => {
                pieces = closing;
                seam = certs;
            }
            Err(CanalError::InvalidArgument(_)) => {}
            Err(e) => return Err(e),
        }
    }
    let mut pipe = PipeChain::from_pieces(pieces, "pipe around PH piece", global);
    pipe.add_joins(seam);
    Ok(SpinePipe::Approximate(ApproximatePipe {
        spline,
        pipe,
        radius: radius.clone(),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Scalar;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn pipe_around_a_twisted_cubic() {
        let pts = vec![
            vec![q(0), q(0), q(0)],
            vec![Rational::from_ratio(1, 3), q(0), q(0)],
            vec![Rational::from_ratio(2, 3), Rational::from_ratio(1, 3), q(0)],
            vec![q(1), q(1), q(1)],
        ];
        let spine = vec![BezierCurve::from_points(&pts).expect("cubic")];
        let r = Rational::from_ratio(1, 10);
        // exact is impossible: |m′|² = 1 + 4t² + 9t⁴ needs a quadratic field
        let never = pipe_along_spine(
            &spine,
            &r,
            Orientation::Positive,
            ApproximationPolicy::Never,
            None,
        );
        assert!(matches!(&never, Err(e) if needs_field(e)), "{never:?}");
        let t = std::time::Instant::now();
        let p = pipe_along_spine(
            &spine,
            &r,
            Orientation::Positive,
            ApproximationPolicy::Auto,
            None,
        )
        .expect("approximate pipe");
        let SpinePipe::Approximate(a) = &p else {
            panic!("expected an approximation");
        };
        eprintln!(
            "{} PH pieces, {} patches, {} control points, ε = {}, {:?}",
            a.spline().pieces().len(),
            a.patches().len(),
            a.control_points(),
            format_scalar(&a.deviation()),
            t.elapsed()
        );
        let certs = p.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        assert!(a.deviation() > Rational::ZERO);
    }
}

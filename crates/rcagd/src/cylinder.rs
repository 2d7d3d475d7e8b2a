//! Rational biquadratic patches on a circular cylinder.
//!
//! The cylinder `(x − c_x)² + (y − c_y)² = r²` (axis parallel to `z` through
//! `(c_x, c_y)`) contains the translates of its cross-section circle. A patch is the
//! product of an exact rational circle arc `a(u)` ([`CircleArc`], degree 2 in `u`, module
//! [`crate::conic`]) and the segment `z(v) = (1 − v)z₀ + v z₁` (degree 1, elevated to
//! degree 2: `z₀, (z₀ + z₁)/2, z₁`):
//!
//! ```text
//! Pᵢⱼ = (wᵢ, wᵢxᵢ, wᵢyᵢ, wᵢ zⱼ),   (wᵢ, wᵢxᵢ, wᵢyᵢ) the arc's control points,
//! ```
//!
//! a rational biquadratic patch with `(X − c_x W)² + (Y − c_y W)² − r²W² ≡ 0`
//! (the 4×4 matrix [`cylinder_matrix`] in `(W, X, Y, Z)`), the main certificate.

use crate::certs;
use crate::conic::{CircleArc, CircleArcs, Point2};
use crate::error::{check_finite, format_point, format_scalar, ConstructionError};
use crate::Certified;
use rcagd_algebra::{Certificate, Scalar};
use rcagd_geom::BezierPatch;

/// The symmetric 4×4 matrix of the cylinder `(x − c_x)² + (y − c_y)² = r²` in
/// homogeneous coordinates `(W, X, Y, Z)`: the circle matrix bordered by zeros.
pub fn cylinder_matrix<F: Scalar>(center: &Point2<F>, radius: &F) -> Vec<Vec<F>> {
    let circle = crate::conic::circle_matrix(center, radius);
    let mut m: Vec<Vec<F>> = circle
        .into_iter()
        .map(|mut row| {
            row.push(F::zero());
            row
        })
        .collect();
    m.push(vec![F::zero(); 4]);
    m
}

/// A rational biquadratic patch on the cylinder over one circle arc (< 180°) between
/// the heights `z₀ < z₁`; `u` runs along the arc, `v` from `z₀` to `z₁`.
#[derive(Debug, Clone, PartialEq)]
pub struct CylinderPatch<F> {
    arc: CircleArc<F>,
    z0: F,
    z1: F,
    patch: BezierPatch<F>,
}

impl<F: Scalar> CylinderPatch<F> {
    /// The patch on the cylinder `x² + y² = r²` (axis `z`) over the counter-clockwise arc
    /// from `from` to `to` (less than 180°) between the heights `z0 < z1`.
    ///
    /// # Errors
    /// As [`CircleArc::new`] (radius, points on the circle, coincident points, arc too
    /// large), and [`ConstructionError::EmptyInterval`] unless `z0 < z1`.
    pub fn new(
        radius: F,
        from: Point2<F>,
        to: Point2<F>,
        z0: F,
        z1: F,
    ) -> Result<Self, ConstructionError> {
        let arc = CircleArc::new([F::zero(), F::zero()], radius, from, to, false)?;
        Self::from_arc(arc, z0, z1)
    }

    /// The patch over a given arc (the cylinder's axis passes through the arc's centre).
    ///
    /// # Errors
    /// [`ConstructionError::EmptyInterval`] unless `z0 < z1`,
    /// [`ConstructionError::NotFinite`] for NaN/infinite `f64` heights.
    pub fn from_arc(arc: CircleArc<F>, z0: F, z1: F) -> Result<Self, ConstructionError> {
        check_finite("z0", &[&z0])?;
        check_finite("z1", &[&z1])?;
        if z0 >= z1 {
            return Err(ConstructionError::EmptyInterval {
                name: "heights z0 < z1".into(),
                lower: format_scalar(&z0),
                upper: format_scalar(&z1),
            });
        }
        let zmid = (z0.clone() + z1.clone()) / F::from_i64(2);
        let heights = [z0.clone(), zmid, z1.clone()];
        let net: Vec<Vec<Vec<F>>> = arc
            .curve()
            .control_points()
            .map(|p| {
                heights
                    .iter()
                    .map(|z| {
                        let mut h = p.to_vec();
                        let w = h.first().cloned().unwrap_or_else(F::one);
                        h.push(w * z.clone());
                        h
                    })
                    .collect()
            })
            .collect();
        let patch = BezierPatch::from_homogeneous(net)?;
        Ok(CylinderPatch { arc, z0, z1, patch })
    }

    /// The rational biquadratic patch (homogeneous `(w, wx, wy, wz)`).
    pub fn patch(&self) -> &BezierPatch<F> {
        &self.patch
    }

    /// Consumes the construction, returning its patch.
    pub fn into_patch(self) -> BezierPatch<F> {
        self.patch
    }

    /// The base arc (the boundary `v = 0` projected to the `xy`-plane).
    pub fn arc(&self) -> &CircleArc<F> {
        &self.arc
    }

    /// The lower height.
    pub fn z0(&self) -> &F {
        &self.z0
    }

    /// The upper height.
    pub fn z1(&self) -> &F {
        &self.z1
    }

    fn corner(&self, p: &Point2<F>, z: &F) -> Vec<F> {
        vec![p[0].clone(), p[1].clone(), z.clone()]
    }

    /// Every `v`-row of the net has the same `(w, wx, wy)`: the `v`-isoparametric lines
    /// are vertical segments (rulings of the cylinder).
    fn rulings_certificate(&self) -> Certificate {
        let property =
            "v-isoparameter lines are vertical rulings: (w, wx, wy) of Pᵢⱼ independent of j";
        let (m, n) = self.patch.degree();
        for i in 0..=m {
            let base = self.patch.control_point(i, 0);
            for j in 1..=n {
                let p = self.patch.control_point(i, j);
                let same =
                    base.iter().zip(p).take(3).all(|(a, b)| {
                        certs::is_negligible(&(a.clone() - b.clone()), a.to_f64().abs())
                    });
                if !same {
                    return Certificate::fails(
                        property,
                        format!(
                            "P[{i}][0] = {} vs P[{i}][{j}] = {}",
                            format_point(base),
                            format_point(p)
                        ),
                        F::EXACT,
                    );
                }
            }
        }
        Certificate::holds(property, F::EXACT)
    }
}

impl<F: Scalar> Certified for CylinderPatch<F> {
    /// On the cylinder (exact identity), the four corners, vertical rulings, and the
    /// base arc's own certificates.
    fn certify(&self) -> Vec<Certificate> {
        let c = self.arc.center();
        let r = self.arc.radius();
        let q = cylinder_matrix(c, r);
        let property = format!(
            "on the cylinder: (x − cx)² + (y − cy)² − r² ≡ 0, axis through {} parallel to z, r = {}",
            format_point(c),
            format_scalar(r)
        );
        let mut out = vec![certs::patch_on_quadric(&self.patch, &q, &property)
            .unwrap_or_else(|e| Certificate::fails(property.clone(), e.to_string(), F::EXACT))];
        let (zero, one) = (F::zero(), F::one());
        let corners = [
            (&zero, &zero, self.arc.from(), &self.z0, "P(0, 0)"),
            (&one, &zero, self.arc.to(), &self.z0, "P(1, 0)"),
            (&zero, &one, self.arc.from(), &self.z1, "P(0, 1)"),
            (&one, &one, self.arc.to(), &self.z1, "P(1, 1)"),
        ];
        for (u, v, p, z, name) in corners {
            let point = self.corner(p, z);
            out.push(certs::patch_interpolates(
                &self.patch,
                u,
                v,
                &point,
                &format!("corner {name} = {}", format_point(&point)),
            ));
        }
        out.push(self.rulings_certificate());
        out.extend(self.arc.certify().into_iter().map(|mut cert| {
            cert.property = format!("base arc: {}", cert.property);
            cert
        }));
        out
    }
}

/// Patches on the cylinder `x² + y² = r²` over the counter-clockwise arc from `from` to
/// `to` of any extent below 360° (split as in [`CircleArcs`]), between `z0 < z1`.
///
/// # Errors
/// As [`CircleArcs::new`] and [`CylinderPatch::from_arc`].
pub fn cylinder_patches<F: Scalar>(
    radius: F,
    from: Point2<F>,
    to: Point2<F>,
    z0: F,
    z1: F,
) -> Result<Vec<CylinderPatch<F>>, ConstructionError> {
    let arcs = CircleArcs::new([F::zero(), F::zero()], radius, from, to, false)?;
    arcs.pieces()
        .iter()
        .map(|arc| CylinderPatch::from_arc(arc.clone(), z0.clone(), z1.clone()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    #[test]
    fn quarter_cylinder() {
        let c = CylinderPatch::new(
            q(2, 1),
            [q(2, 1), q(0, 1)],
            [q(0, 1), q(2, 1)],
            q(0, 1),
            q(3, 1),
        )
        .expect("valid");
        assert_eq!(c.patch().degree(), (2, 2));
        assert_eq!(
            c.patch().control_point(2, 1),
            &[q(2, 1), q(0, 1), q(4, 1), q(3, 1)]
        );
        let certs = c.certify();
        assert!(Certificate::all_hold(&certs), "{certs:#?}");
        assert!(certs.iter().all(|c| c.exact));
    }

    #[test]
    fn heights_must_increase() {
        let e = CylinderPatch::new(
            q(1, 1),
            [q(1, 1), q(0, 1)],
            [q(0, 1), q(1, 1)],
            q(1, 1),
            q(1, 1),
        );
        assert!(matches!(e, Err(ConstructionError::EmptyInterval { .. })));
    }

    #[test]
    fn long_cylinder_arcs_split() {
        let ps = cylinder_patches(
            q(1, 1),
            [q(1, 1), q(0, 1)],
            [q(0, 1), q(-1, 1)],
            q(0, 1),
            q(1, 1),
        )
        .expect("valid");
        assert_eq!(ps.len(), 3);
        assert!(ps.iter().all(|p| p.all_hold()));
    }
}

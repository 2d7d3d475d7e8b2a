//! The exchange model: a named, certified object with exact rational geometry.
//!
//! Every exporter (JSON, OBJ, SVG, the report) takes an [`Object`]: the result of one
//! recipe entry, i.e. its `name`, the `op` that built it, the op's `params` (as JSON),
//! its exact [`Geometry`] and its [`Certificate`]s.

use crate::quantity::NamedQuantity;
use crate::IoError;
use rcagd_algebra::{Certificate, Rational};
use rcagd_geom::weight_sign::{
    curve_has_one_sign, patch_has_one_sign, split_curve_uniform, split_patches_adaptive,
    zero_weight_edge, SignRule,
};
use rcagd_geom::{BezierCurve, BezierPatch, GeomError};

/// The deepest uniform split ([`split_curve_uniform`]) of a curve for drawing.
const DRAW_CURVE_LEVEL: u32 = 6;
/// The most bisections in `v` and in `u` ([`split_patches_adaptive`]) of a patch for
/// drawing.
const DRAW_PATCH_SPLITS: (usize, usize) = (4, 4);

/// Exact rational geometry: one or several homogeneous rational Bézier curves or
/// tensor-product patches.
#[derive(Debug, Clone, PartialEq)]
pub enum Geometry {
    /// One curve.
    Curve(BezierCurve<Rational>),
    /// A chain or collection of curves (e.g. the pieces of a circle).
    Curves(Vec<BezierCurve<Rational>>),
    /// One patch.
    Patch(BezierPatch<Rational>),
    /// A collection of patches.
    Patches(Vec<BezierPatch<Rational>>),
}

impl Geometry {
    /// `"curve"`, `"curves"`, `"patch"` or `"patches"`.
    pub fn kind(&self) -> &'static str {
        match self {
            Geometry::Curve(_) => "curve",
            Geometry::Curves(_) => "curves",
            Geometry::Patch(_) => "patch",
            Geometry::Patches(_) => "patches",
        }
    }

    /// The curves (empty for patch geometry).
    pub fn curves(&self) -> Vec<&BezierCurve<Rational>> {
        match self {
            Geometry::Curve(c) => vec![c],
            Geometry::Curves(cs) => cs.iter().collect(),
            _ => Vec::new(),
        }
    }

    /// The patches (empty for curve geometry).
    pub fn patches(&self) -> Vec<&BezierPatch<Rational>> {
        match self {
            Geometry::Patch(p) => vec![p],
            Geometry::Patches(ps) => ps.iter().collect(),
            _ => Vec::new(),
        }
    }

    /// Number of curves or patches.
    pub fn piece_count(&self) -> usize {
        match self {
            Geometry::Curve(_) | Geometry::Patch(_) => 1,
            Geometry::Curves(cs) => cs.len(),
            Geometry::Patches(ps) => ps.len(),
        }
    }

    /// The Euclidean dimension (the largest over the pieces; 0 when empty).
    pub fn dim(&self) -> usize {
        let c = self.curves().iter().map(|c| c.dim()).max();
        let p = self.patches().iter().map(|p| p.dim()).max();
        c.or(p).unwrap_or(0)
    }

    /// Total number of homogeneous control points.
    pub fn control_point_count(&self) -> usize {
        let c: usize = self.curves().iter().map(|c| c.degree() + 1).sum();
        let p: usize = self
            .patches()
            .iter()
            .map(|p| {
                let (m, n) = p.degree();
                (m + 1) * (n + 1)
            })
            .sum();
        c + p
    }

    /// A short human-readable degree: `"degree 2"`, `"4 pieces of degree 2"`,
    /// `"3 pieces of degree 2, 3, 3"`, `"bidegree (2, 2)"`, `"2 patches of bidegree (2, 2)"`.
    pub fn degree_summary(&self) -> String {
        match self {
            Geometry::Curve(c) => format!("degree {}", c.degree()),
            Geometry::Patch(p) => {
                let (m, n) = p.degree();
                format!("bidegree ({m}, {n})")
            }
            Geometry::Curves(cs) => {
                let degs: Vec<usize> = cs.iter().map(|c| c.degree()).collect();
                summarize(
                    cs.len(),
                    "piece",
                    "pieces",
                    "degree",
                    degs.iter().map(|d| d.to_string()),
                )
            }
            Geometry::Patches(ps) => {
                let degs = ps.iter().map(|p| {
                    let (m, n) = p.degree();
                    format!("({m}, {n})")
                });
                summarize(ps.len(), "patch", "patches", "bidegree", degs)
            }
        }
    }

    /// The curves as pieces whose weights have one sign (module
    /// [`rcagd_geom::weight_sign`]), for pictures and meshes: a piece whose weight
    /// function vanishes inside would be drawn as a spike to infinity. Curves that
    /// already have weights of one sign are returned as they are.
    ///
    /// # Errors
    /// [`IoError::Invalid`] for a curve whose weight function has a zero on `[0, 1]`
    /// (a point at infinity: no split into `2⁶` pieces has weights of one sign).
    pub fn drawable_curves(&self) -> Result<Vec<BezierCurve<Rational>>, IoError> {
        let mut out = Vec::new();
        for (k, c) in self.curves().into_iter().enumerate() {
            if curve_has_one_sign(c) {
                out.push(c.clone());
                continue;
            }
            match split_curve_uniform(c, DRAW_CURVE_LEVEL)? {
                Some(pieces) => out.extend(pieces),
                None => {
                    return Err(IoError::Invalid(format!(
                        "curve {k} cannot be drawn: its weight function has a zero on [0, 1] \
                         (a point at infinity); no split into {} pieces has weights of one sign",
                        1u32 << DRAW_CURVE_LEVEL
                    )))
                }
            }
        }
        Ok(out)
    }

    /// The patches as pieces whose weights have one sign (as [`Self::drawable_curves`]),
    /// each with the index of the patch it comes from. Patches that already have
    /// weights of one sign are returned as they are.
    ///
    /// # Errors
    /// [`IoError::Invalid`] for a patch whose weight vanishes on a whole boundary edge
    /// (the edge lies at infinity) or whose weight function has a zero on `[0, 1]²`
    /// (no split by [`split_patches_adaptive`] with up to 4 bisections in each
    /// direction gives weights of one sign).
    pub fn drawable_patches(&self) -> Result<Vec<(usize, BezierPatch<Rational>)>, IoError> {
        let patches = self.patches();
        if patches.iter().all(|p| patch_has_one_sign(p)) {
            return Ok(patches.into_iter().cloned().enumerate().collect());
        }
        const EDGES: [&str; 4] = ["v = 0", "u = 1", "v = 1", "u = 0"];
        for (k, p) in patches.iter().enumerate() {
            if let Some(e) = zero_weight_edge(p) {
                return Err(IoError::Invalid(format!(
                    "patch {k} cannot be drawn: its weight vanishes on the whole edge {} \
                     (the edge lies at infinity)",
                    EDGES[e]
                )));
            }
        }
        let split = split_patches_adaptive(
            patches.into_iter().cloned().collect(),
            SignRule::OneSign,
            DRAW_PATCH_SPLITS,
        )?;
        if split.failed > 0 {
            let k = split
                .pieces
                .iter()
                .zip(&split.source)
                .find(|(p, _)| !patch_has_one_sign(p))
                .map_or(0, |(_, &k)| k);
            return Err(IoError::Invalid(format!(
                "patch {k} cannot be drawn: its weight function has a zero on [0, 1]² (a pole \
                 or point at infinity); {} bisections in v and {} in u leave pieces whose \
                 weights change sign",
                DRAW_PATCH_SPLITS.0, DRAW_PATCH_SPLITS.1
            )));
        }
        Ok(split.source.into_iter().zip(split.pieces).collect())
    }

    /// The `f64` images of the curves (correctly rounded coordinates).
    pub fn curves_f64(&self) -> Result<Vec<BezierCurve<f64>>, GeomError> {
        self.curves().into_iter().map(curve_to_f64).collect()
    }

    /// The `f64` images of the patches (correctly rounded coordinates).
    pub fn patches_f64(&self) -> Result<Vec<BezierPatch<f64>>, GeomError> {
        self.patches().into_iter().map(patch_to_f64).collect()
    }
}

fn summarize(
    count: usize,
    one: &str,
    many: &str,
    what: &str,
    degrees: impl Iterator<Item = String>,
) -> String {
    // distinct degrees with their counts, in order of first appearance
    let mut groups: Vec<(String, usize)> = Vec::new();
    for d in degrees {
        match groups.iter_mut().find(|(g, _)| *g == d) {
            Some((_, n)) => *n += 1,
            None => groups.push((d, 1)),
        }
    }
    let noun = if count == 1 { one } else { many };
    match groups.as_slice() {
        [] => format!("0 {many}"),
        [(d, _)] => format!("{count} {noun} of {what} {d}"),
        gs if gs.len() <= 3 => {
            let parts: Vec<String> = gs
                .iter()
                .map(|(d, n)| format!("{n} of {what} {d}"))
                .collect();
            format!("{count} {noun}: {}", parts.join(", "))
        }
        gs => format!("{count} {noun} of {} different {what}s", gs.len()),
    }
}

/// The `f64` image of an exact curve.
pub fn curve_to_f64(c: &BezierCurve<Rational>) -> Result<BezierCurve<f64>, GeomError> {
    Ok(c.to_f64())
}

/// The `f64` image of an exact patch.
pub fn patch_to_f64(p: &BezierPatch<Rational>) -> Result<BezierPatch<f64>, GeomError> {
    Ok(p.to_f64())
}

/// One certified object: the unit of every export and of the report.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    /// The user's name for the object (from the recipe).
    pub name: String,
    /// The op that built it (`"circle_arc"`, `"cylinder_patch"`, …).
    pub op: String,
    /// The op's parameters, as given (numbers as exact strings where possible).
    pub params: serde_json::Value,
    /// The exact geometry.
    pub geometry: Geometry,
    /// The certificates of the construction.
    pub certificates: Vec<Certificate>,
    /// Named exact values the op computed besides the geometry (module
    /// [`crate::quantity`]); empty for most constructions.
    pub values: Vec<NamedQuantity>,
}

impl Object {
    /// Assembles an object.
    pub fn new(
        name: impl Into<String>,
        op: impl Into<String>,
        params: serde_json::Value,
        geometry: Geometry,
        certificates: Vec<Certificate>,
    ) -> Self {
        Object {
            name: name.into(),
            op: op.into(),
            params,
            geometry,
            certificates,
            values: Vec::new(),
        }
    }

    /// The object with these named values (see [`Object::values`]).
    #[must_use]
    pub fn with_values(mut self, values: Vec<NamedQuantity>) -> Self {
        self.values = values;
        self
    }

    /// `"curve"`, `"curves"`, `"patch"` or `"patches"`.
    pub fn kind(&self) -> &'static str {
        self.geometry.kind()
    }

    /// See [`Geometry::degree_summary`].
    pub fn degree_summary(&self) -> String {
        self.geometry.degree_summary()
    }

    /// Total number of homogeneous control points.
    pub fn control_point_count(&self) -> usize {
        self.geometry.control_point_count()
    }

    /// `true` if every certificate holds (vacuously for none).
    pub fn all_certificates_hold(&self) -> bool {
        Certificate::all_hold(&self.certificates)
    }

    /// The number of certificates that fail.
    pub fn failed_certificate_count(&self) -> usize {
        self.certificates.iter().filter(|c| !c.holds).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Scalar;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    fn quarter() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(1, 1), q(0, 1)],
            vec![q(1, 1), q(1, 1), q(1, 1)],
            vec![q(2, 1), q(0, 1), q(2, 1)],
        ])
        .expect("valid")
    }

    #[test]
    fn summaries() {
        let one = Geometry::Curve(quarter());
        assert_eq!(one.degree_summary(), "degree 2");
        assert_eq!(one.control_point_count(), 3);
        let four = Geometry::Curves(vec![quarter(); 4]);
        assert_eq!(four.degree_summary(), "4 pieces of degree 2");
        assert_eq!(four.control_point_count(), 12);
        assert_eq!(four.dim(), 2);
        let line = BezierCurve::from_points(&[vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(1, 1)]])
            .expect("valid");
        let mixed = Geometry::Curves(vec![quarter(), line]);
        assert_eq!(
            mixed.degree_summary(),
            "2 pieces: 1 of degree 2, 1 of degree 1"
        );
        // many pieces of a few degrees: grouped, not listed one by one
        let mut many = vec![quarter(); 40];
        many.push(
            BezierCurve::from_points(&[vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(1, 1)]])
                .expect("valid"),
        );
        let many = Geometry::Curves(many);
        assert_eq!(
            many.degree_summary(),
            "41 pieces: 40 of degree 2, 1 of degree 1"
        );

        assert_eq!(Geometry::Curves(vec![]).degree_summary(), "0 pieces");
        let patch = BezierPatch::from_flat(3, 2, 1, vec![q(1, 1); 24]).expect("valid");
        assert_eq!(
            Geometry::Patch(patch.clone()).degree_summary(),
            "bidegree (2, 1)"
        );
        assert_eq!(
            Geometry::Patches(vec![patch; 2]).degree_summary(),
            "2 patches of bidegree (2, 1)"
        );
    }

    #[test]
    fn certificates_verdict() {
        let mut o = Object::new(
            "q",
            "circle_arc",
            serde_json::json!({}),
            Geometry::Curve(quarter()),
            vec![],
        );
        assert!(o.all_certificates_hold());
        o.certificates.push(Certificate::holds("a", true));
        o.certificates.push(Certificate::fails("b", "1/2", true));
        assert!(!o.all_certificates_hold());
        assert_eq!(o.failed_certificate_count(), 1);
        assert_eq!(o.kind(), "curve");
    }

    /// The arc `(1 − t², 2t)/(1 + t²)`, `t ∈ [−1, 3]`: weight `1 + t² > 0` with a
    /// negative middle Bernstein coefficient.
    fn long_arc() -> BezierCurve<Rational> {
        BezierCurve::from_homogeneous(vec![
            vec![q(2, 1), q(0, 1), q(-2, 1)],
            vec![q(-2, 1), q(4, 1), q(2, 1)],
            vec![q(10, 1), q(-8, 1), q(6, 1)],
        ])
        .expect("valid")
    }

    #[test]
    fn drawing_splits_mixed_weights_and_refuses_zeros() {
        use crate::svg::{geometry_svg, SvgOptions};
        // a zero-free weight with mixed Bernstein signs: split, drawn
        let g = Geometry::Curve(long_arc());
        let pieces = g.drawable_curves().expect("splits");
        assert!(pieces.len() > 1);
        assert!(geometry_svg(&g, &SvgOptions::default()).is_ok());
        // the cylinder over that arc: patches split in the arc direction
        let lift = |z: i64| {
            BezierCurve::from_homogeneous(
                long_arc()
                    .control_points()
                    .map(|h| {
                        vec![
                            h[0].clone(),
                            h[1].clone(),
                            h[2].clone(),
                            h[0].clone() * q(z, 1),
                        ]
                    })
                    .collect(),
            )
            .expect("valid")
        };
        let cyl = BezierPatch::from_curves_ruled(&lift(0), &lift(1)).expect("ruled");
        let g = Geometry::Patch(cyl);
        let pieces = g.drawable_patches().expect("splits");
        assert!(pieces.len() > 1 && pieces.iter().all(|(k, _)| *k == 0));
        assert!(geometry_svg(&g, &SvgOptions::default()).is_ok());
        // a pole inside (weight 1 − 2t): a clear error, no picture
        let pole = BezierCurve::from_homogeneous(vec![
            vec![q(1, 1), q(0, 1), q(0, 1)],
            vec![q(-1, 1), q(1, 1), q(1, 1)],
        ])
        .expect("valid");
        let e = geometry_svg(&Geometry::Curve(pole), &SvgOptions::default()).expect_err("pole");
        assert!(e.to_string().contains("weight function has a zero"), "{e}");
        // a weight vanishing on the whole edge u = 0: a clear error from every writer
        let net = vec![
            vec![
                vec![q(0, 1), q(1, 1), q(0, 1), q(0, 1)],
                vec![q(0, 1), q(1, 1), q(1, 1), q(0, 1)],
            ],
            vec![
                vec![q(1, 1), q(1, 1), q(0, 1), q(0, 1)],
                vec![q(1, 1), q(1, 1), q(1, 1), q(0, 1)],
            ],
        ];
        let p = BezierPatch::from_homogeneous(net).expect("valid");
        let o = Object::new("z", "t", serde_json::json!({}), Geometry::Patch(p), vec![]);
        let e = geometry_svg(&o.geometry, &SvgOptions::default()).expect_err("edge at infinity");
        assert!(
            e.to_string().contains("vanishes on the whole edge u = 0"),
            "{e}"
        );
        assert!(crate::stl::object_mesh(&o, &Default::default()).is_err());
        assert!(crate::raster::render(&o, &Default::default()).is_err());
        assert!(crate::obj::geometry_to_obj("z", &o.geometry, 1e-3).is_err());
    }
}

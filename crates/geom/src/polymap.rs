//! Homogeneous polynomial maps `Pᵈ → Pᵈ'` and their action on Bézier curves and
//! patches.
//!
//! A [`PolyMap`] is a named vector `F = (F₀, …, F_{d'})` of homogeneous polynomials of
//! one degree `k` in the `d + 1` homogeneous coordinates `(w, x₁, …, x_d)` (weight
//! first). Stereographic projections, the cyclographic map and the Hopf map δ of
//! Jüttler are such maps. It maps a rational Bézier curve of degree `n` to one of
//! degree `k·n` and a patch of bidegree `(m, n)` to one of bidegree `(k·m, k·n)`,
//! exactly: the image's Bernstein coefficients are sums of Bernstein products of the
//! coordinate vectors (Jüttler, docs/math/quadrics.md, "Curves and patches under δ", which state the
//! quadratic case by the polar form `F̂(a,b) = (F(a+b) − F(a−b))/4`; a product of
//! Bernstein coefficient vectors is the same computation for any degree).

use crate::curve::BezierCurve;
use crate::error::GeomError;
use crate::patch::BezierPatch;
use rcagd_algebra::bernstein;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Scalar;
use std::collections::HashMap;

/// A homogeneous polynomial map with a name, `x ↦ (F₀(x), …, F_{d'}(x))`.
#[derive(Debug, Clone)]
pub struct PolyMap<F> {
    name: String,
    nvars: usize,
    degree: usize,
    components: Vec<MPoly<F>>,
}

impl<F: Scalar> PartialEq for PolyMap<F> {
    /// Equal names, input dimensions and components (as polynomials).
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && self.nvars == other.nvars && self.components == other.components
    }
}

impl<F: Scalar> PolyMap<F> {
    /// From its components, homogeneous of one degree in the homogeneous input
    /// coordinates `x₀ = w, x₁, …` (weight first). The number of input coordinates is
    /// the largest `nvars` of the components; a component in fewer variables does not
    /// depend on the last ones (the padding convention of [`MPoly`]).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] for fewer than two components or fewer than two
    /// variables; [`GeomError::Degree`] if a
    /// component is not homogeneous, the degrees differ, or every component is zero.
    pub fn new(name: impl Into<String>, components: Vec<MPoly<F>>) -> Result<Self, GeomError> {
        let nvars = components.iter().map(MPoly::nvars).max().unwrap_or(0);
        if nvars < 2 {
            return Err(GeomError::Dimension(format!(
                "a polynomial map acts on homogeneous coordinates (w, x₁, …): needs at least \
                 two variables, got {nvars}"
            )));
        }
        let degree = homogeneous_degree(&components, nvars)?;
        Ok(PolyMap {
            name: name.into(),
            nvars,
            degree,
            components,
        })
    }

    /// The identity of `Pᵈ`, `(w, x₁, …, x_d) ↦ (w, x₁, …, x_d)` (degree 1).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `dim = 0`.
    pub fn identity(dim: usize) -> Result<Self, GeomError> {
        if dim == 0 {
            return Err(GeomError::Dimension("dimension must be at least 1".into()));
        }
        let comps = (0..=dim).map(|i| MPoly::var(dim + 1, i)).collect();
        Self::new("identity", comps)
    }

    /// The linear (projective) map `X ↦ M X`; `M` has `d' + 1` rows of length `d + 1`.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] for fewer than two rows or rows of different or too
    /// small length, [`GeomError::Degree`] for the zero matrix.
    pub fn linear(name: impl Into<String>, matrix: &[Vec<F>]) -> Result<Self, GeomError> {
        let cols = matrix.first().map_or(0, Vec::len);
        crate::curve::check_matrix(matrix, cols, false)?;
        let comps = matrix
            .iter()
            .map(|row| {
                let terms = row
                    .iter()
                    .enumerate()
                    .map(|(i, c)| (unit_exponent(cols, i, 1), c.clone()))
                    .collect();
                MPoly::from_terms(cols, terms)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Self::new(name, comps)
    }

    /// The quadratic map `X ↦ (Xᵀ A₀ X, …, Xᵀ A_{d'} X)`, one symmetric (or not: only the
    /// symmetric part counts) `(d+1)×(d+1)` matrix per output coordinate.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the matrices are not square of one size ≥ 2 or there
    /// are fewer than two; [`GeomError::Degree`] if all forms are zero.
    pub fn from_quadratic_forms(
        name: impl Into<String>,
        forms: &[Vec<Vec<F>>],
    ) -> Result<Self, GeomError> {
        let n = forms.first().map_or(0, Vec::len);
        let comps = forms
            .iter()
            .map(|a| {
                crate::curve::check_matrix(a, n, true)?;
                let mut terms = Vec::new();
                for (i, row) in a.iter().enumerate() {
                    for (j, c) in row.iter().enumerate() {
                        let mut e = vec![0u32; n];
                        e[i] += 1;
                        e[j] += 1;
                        terms.push((e, c.clone()));
                    }
                }
                Ok(MPoly::from_terms(n, terms)?)
            })
            .collect::<Result<Vec<_>, GeomError>>()?;
        Self::new(name, comps)
    }

    /// The name (shown in reports and certificates).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Euclidean input dimension `d` (the components have `d + 1` variables).
    pub fn input_dim(&self) -> usize {
        self.nvars - 1
    }

    /// Euclidean output dimension `d'` (there are `d' + 1` components).
    pub fn output_dim(&self) -> usize {
        self.components.len() - 1
    }

    /// The common degree `k` of the components.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The components `F₀, …, F_{d'}`.
    pub fn components(&self) -> &[MPoly<F>] {
        &self.components
    }

    /// The image `F(x)` of a homogeneous point.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `x` has not `d + 1` coordinates.
    pub fn eval(&self, x: &[F]) -> Result<Vec<F>, GeomError> {
        if x.len() != self.nvars {
            return Err(GeomError::Dimension(format!(
                "map {:?} takes {} homogeneous coordinates, got {}",
                self.name,
                self.nvars,
                x.len()
            )));
        }
        Ok(self
            .components
            .iter()
            .map(|c| c.eval(x.get(..c.nvars()).unwrap_or(x)))
            .collect::<Result<Vec<_>, _>>()?)
    }

    /// The image curve, degree `k·n` ([`BezierCurve::apply_polymap`]).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the curve's dimension is not the map's input dimension.
    pub fn apply_curve(&self, curve: &BezierCurve<F>) -> Result<BezierCurve<F>, GeomError> {
        self.check_input(curve.dim())?;
        curve.apply_polymap(&self.components)
    }

    /// The image patch, bidegree `(k·m, k·n)` ([`BezierPatch::apply_polymap`]).
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if the patch's dimension is not the map's input dimension.
    pub fn apply_patch(&self, patch: &BezierPatch<F>) -> Result<BezierPatch<F>, GeomError> {
        self.check_input(patch.dim())?;
        patch.apply_polymap(&self.components)
    }

    fn check_input(&self, dim: usize) -> Result<(), GeomError> {
        if dim == self.input_dim() {
            Ok(())
        } else {
            Err(GeomError::Dimension(format!(
                "map {:?} acts on dimension {}, got an object of dimension {dim}",
                self.name,
                self.input_dim()
            )))
        }
    }

    /// The composition `self ∘ inner`, `x ↦ self(inner(x))`, of degree
    /// `deg self · deg inner`, named `"self∘inner"`.
    ///
    /// # Errors
    /// [`GeomError::Dimension`] if `inner`'s output dimension is not `self`'s input
    /// dimension; [`GeomError::Degree`] if the composite vanishes identically.
    pub fn compose(&self, inner: &PolyMap<F>) -> Result<PolyMap<F>, GeomError> {
        if inner.components.len() != self.nvars {
            return Err(GeomError::Dimension(format!(
                "cannot compose {:?} (input dimension {}) after {:?} (output dimension {})",
                self.name,
                self.input_dim(),
                inner.name,
                inner.output_dim()
            )));
        }
        let mut powers = PowerCache::new(inner.components.clone());
        let comps = self
            .components
            .iter()
            .map(|f| {
                let mut acc = MPoly::zero(inner.nvars);
                for (e, c) in f.terms() {
                    let mut mono = MPoly::constant(inner.nvars, c.clone());
                    for (a, &ea) in e.iter().enumerate() {
                        if ea > 0 {
                            mono = &mono * powers.get(a, ea, |x| Ok(x.pow(ea)))?;
                        }
                    }
                    acc = &acc + &mono;
                }
                Ok(acc)
            })
            .collect::<Result<Vec<_>, GeomError>>()?;
        Self::new(format!("{}∘{}", self.name, inner.name), comps)
    }
}

/// The exponent vector of `x_i^k` in `n` variables.
fn unit_exponent(n: usize, i: usize, k: u32) -> Vec<u32> {
    let mut e = vec![0u32; n];
    if let Some(x) = e.get_mut(i) {
        *x = k;
    }
    e
}

/// Caches powers `Xₐᵉ` of the inputs.
struct PowerCache<T> {
    inputs: Vec<T>,
    cache: HashMap<(usize, u32), T>,
}

impl<T: Clone> PowerCache<T> {
    fn new(inputs: Vec<T>) -> Self {
        PowerCache {
            inputs,
            cache: HashMap::new(),
        }
    }

    /// `Xₐᵉ`, computed by `pow` on first use.
    fn get(
        &mut self,
        a: usize,
        e: u32,
        pow: impl FnOnce(&T) -> Result<T, GeomError>,
    ) -> Result<&T, GeomError> {
        if !self.cache.contains_key(&(a, e)) {
            let x = self
                .inputs
                .get(a)
                .ok_or_else(|| GeomError::Dimension(format!("variable {a} out of range")))?;
            let p = pow(x)?;
            self.cache.insert((a, e), p);
        }
        self.cache
            .get(&(a, e))
            .ok_or_else(|| GeomError::Dimension("power cache".into()))
    }
}

/// The common degree `k` of homogeneous components in (at most) `nvars` variables.
/// A component in fewer variables is a polynomial in the first ones (the padding
/// convention of [`MPoly`]).
///
/// # Errors
/// As [`PolyMap::new`].
pub(crate) fn homogeneous_degree<F: Scalar>(
    map: &[MPoly<F>],
    nvars: usize,
) -> Result<usize, GeomError> {
    if map.len() < 2 {
        return Err(GeomError::Dimension(format!(
            "a map into homogeneous coordinates needs at least two components, got {}",
            map.len()
        )));
    }
    let mut degree: Option<usize> = None;
    for (j, f) in map.iter().enumerate() {
        if f.nvars() > nvars {
            return Err(GeomError::Dimension(format!(
                "component {j} is a polynomial in {} variables, the points have only {nvars} \
                 homogeneous coordinates",
                f.nvars()
            )));
        }
        if !f.is_homogeneous() {
            return Err(GeomError::Degree(format!(
                "component {j} is not homogeneous"
            )));
        }
        if let Some(dj) = f.total_degree() {
            match degree {
                Some(k) if k != dj => {
                    return Err(GeomError::Degree(format!(
                        "component {j} has degree {dj}, an earlier one has degree {k}"
                    )))
                }
                _ => degree = Some(dj),
            }
        }
    }
    degree.ok_or_else(|| GeomError::Degree("the polynomial map is identically zero".into()))
}

/// A polynomial in tensor-product Bernstein form: coefficients (row-major) and
/// bidegree. A univariate polynomial of degree `n` has bidegree `(n, 0)`.
#[derive(Debug, Clone)]
pub(crate) struct Bernstein2<F> {
    pub(crate) coeffs: Vec<F>,
    pub(crate) degree: (usize, usize),
}

impl<F: Scalar> Bernstein2<F> {
    fn one() -> Self {
        Bernstein2 {
            coeffs: vec![F::one()],
            degree: (0, 0),
        }
    }

    fn mul(&self, other: &Self) -> Result<Self, GeomError> {
        let coeffs = bernstein::product_tensor_scalar(
            &self.coeffs,
            self.degree,
            &other.coeffs,
            other.degree,
        )?;
        Ok(Bernstein2 {
            coeffs,
            degree: (
                self.degree.0 + other.degree.0,
                self.degree.1 + other.degree.1,
            ),
        })
    }

    fn pow(&self, e: u32) -> Result<Self, GeomError> {
        let mut acc = Self::one();
        for _ in 0..e {
            acc = acc.mul(self)?;
        }
        Ok(acc)
    }

    /// `acc += c·self`, coefficientwise.
    fn add_scaled_to(&self, c: &F, acc: &mut [F]) -> Result<(), GeomError> {
        if acc.len() != self.coeffs.len() {
            return Err(GeomError::Degree(format!(
                "a term of bidegree {:?} does not fit the image degree",
                self.degree
            )));
        }
        for (a, x) in acc.iter_mut().zip(&self.coeffs) {
            *a += c.clone() * x.clone();
        }
        Ok(())
    }
}

/// The Bernstein coefficients of `F₀(X), …, F_{d'}(X)` for homogeneous components of
/// degree `k` (already checked by [`homogeneous_degree`]) and inputs `X₀, …, X_d` of
/// one bidegree `(m, n)`: `Σ_terms c · Π X_a^{e_a}`, each monomial a Bernstein product
/// of bidegree `(km, kn)`. Powers and monomials shared between components are computed
/// once.
pub(crate) fn apply_to_bernstein<F: Scalar>(
    map: &[MPoly<F>],
    k: usize,
    inputs: Vec<Bernstein2<F>>,
) -> Result<Vec<Vec<F>>, GeomError> {
    let (m, n) = inputs.first().map_or((0, 0), |x| x.degree);
    let out_len = (k * m + 1) * (k * n + 1);
    let mut powers = PowerCache::new(inputs);
    let mut monomials: HashMap<Vec<u32>, Bernstein2<F>> = HashMap::new();
    map.iter()
        .map(|f| {
            let mut acc = vec![F::zero(); out_len];
            for (e, c) in f.terms() {
                if !monomials.contains_key(e) {
                    let mut mono = Bernstein2::one();
                    for (a, &ea) in e.iter().enumerate() {
                        if ea > 0 {
                            mono = mono.mul(powers.get(a, ea, |x| x.pow(ea))?)?;
                        }
                    }
                    monomials.insert(e.to_vec(), mono);
                }
                if let Some(mono) = monomials.get(e) {
                    mono.add_scaled_to(c, &mut acc)?;
                }
            }
            Ok(acc)
        })
        .collect()
}

/// The Bernstein coefficients of `Σ_{a,b} Q_ab X_a X_b` (only the symmetric part of
/// `Q` counts: `Q_aa X_a² + Σ_{a<b} (Q_ab + Q_ba) X_a X_b`) for inputs of one bidegree
/// `(m, n)`; bidegree `(2m, 2n)`. `Q` must be square of the number of inputs.
pub(crate) fn quadratic_form_bernstein<F: Scalar>(
    q: &[Vec<F>],
    inputs: &[Bernstein2<F>],
) -> Result<Vec<F>, GeomError> {
    let (m, n) = inputs.first().map_or((0, 0), |x| x.degree);
    let mut acc = vec![F::zero(); (2 * m + 1) * (2 * n + 1)];
    for (a, xa) in inputs.iter().enumerate() {
        for (b, xb) in inputs.iter().enumerate().skip(a) {
            let entry = |i: usize, j: usize| q.get(i).and_then(|r| r.get(j)).cloned();
            let coef = match (entry(a, b), entry(b, a)) {
                (Some(x), _) if a == b => x,
                (Some(x), Some(y)) => x + y,
                _ => {
                    return Err(GeomError::Dimension(format!(
                        "the quadratic form must be {0}×{0}",
                        inputs.len()
                    )))
                }
            };
            if !coef.is_zero() {
                xa.mul(xb)?.add_scaled_to(&coef, &mut acc)?;
            }
        }
    }
    Ok(acc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Rational;

    fn pt(v: &[i64]) -> Vec<Rational> {
        v.iter().map(|&x| Rational::from(x)).collect()
    }

    /// σ(p₀,p₁,p₂) = (p₀²+p₁²+p₂², 2p₀p₁, 2p₀p₂, p₁²+p₂²−p₀²): the inverse
    /// stereographic projection of the plane onto the unit sphere (Jüttler, docs/math/quadrics.md, "The map δ onto the sphere").
    fn sigma() -> PolyMap<Rational> {
        let forms = vec![
            vec![pt(&[1, 0, 0]), pt(&[0, 1, 0]), pt(&[0, 0, 1])],
            vec![pt(&[0, 1, 0]), pt(&[1, 0, 0]), pt(&[0, 0, 0])],
            vec![pt(&[0, 0, 1]), pt(&[0, 0, 0]), pt(&[1, 0, 0])],
            vec![pt(&[-1, 0, 0]), pt(&[0, 1, 0]), pt(&[0, 0, 1])],
        ];
        PolyMap::from_quadratic_forms("σ", &forms).expect("valid forms")
    }

    #[test]
    fn quadratic_map_on_a_line_gives_a_circle_on_the_sphere() {
        let s = sigma();
        assert_eq!((s.input_dim(), s.output_dim(), s.degree()), (2, 3, 2));
        let line = BezierCurve::from_points(&[pt(&[0, 1]), pt(&[2, 3])]).expect("valid");
        let image = s.apply_curve(&line).expect("dimensions fit");
        assert_eq!(image.degree(), 2);
        for k in 0..5 {
            let t = Rational::from_ratio(k, 4);
            let x = line.eval_homogeneous(&t);
            assert_eq!(
                image.eval_homogeneous(&t),
                s.eval(&x).expect("3 coordinates")
            );
        }
        // On the unit sphere: x² + y² + z² − w² ≡ 0.
        let q = vec![
            pt(&[-1, 0, 0, 0]),
            pt(&[0, 1, 0, 0]),
            pt(&[0, 0, 1, 0]),
            pt(&[0, 0, 0, 1]),
        ];
        let f = image.quadratic_form(&q).expect("4×4");
        assert!(f.iter().all(|x| *x == Rational::from(0)));
    }

    #[test]
    fn identity_linear_and_composition() {
        let id = PolyMap::<Rational>::identity(2).expect("dim 2");
        let c = BezierCurve::from_homogeneous(vec![pt(&[1, 2, 3]), pt(&[2, 0, 1]), pt(&[1, 1, 1])])
            .expect("valid");
        assert_eq!(id.apply_curve(&c).expect("fits"), c);
        let m = vec![pt(&[1, 0, 0]), pt(&[1, 2, 0]), pt(&[0, 0, 3])];
        let lin = PolyMap::linear("M", &m).expect("3×3");
        assert_eq!(
            lin.apply_curve(&c).expect("fits"),
            c.apply_projective(&m).expect("fits")
        );
        let s = sigma();
        let comp = s.compose(&lin).expect("dimensions fit");
        assert_eq!(comp.degree(), 2);
        assert_eq!(comp.name(), "σ∘M");
        assert_eq!(
            comp.apply_curve(&c).expect("fits"),
            s.apply_curve(&lin.apply_curve(&c).expect("fits"))
                .expect("fits")
        );
        assert!(lin.compose(&s).is_err());
    }

    #[test]
    fn rejects_bad_maps() {
        let x = MPoly::<Rational>::var(3, 0);
        let y2 = &MPoly::<Rational>::var(3, 1) * &MPoly::var(3, 1);
        assert!(matches!(
            PolyMap::new("mixed", vec![x.clone(), y2.clone()]),
            Err(GeomError::Degree(_))
        ));
        let inhom = &x + &y2;
        assert!(PolyMap::new("inhomogeneous", vec![inhom, x.clone()]).is_err());
        assert!(PolyMap::new("short", vec![x.clone()]).is_err());
        assert!(PolyMap::new("zero", vec![MPoly::<Rational>::zero(3), MPoly::zero(3)]).is_err());
        // A component in fewer variables is padded; one in more does not fit a curve.
        assert!(PolyMap::new("padded", vec![x.clone(), MPoly::var(2, 0)]).is_ok());
        let c2 = BezierCurve::from_points(&[pt(&[1])]).expect("valid");
        assert!(matches!(
            c2.apply_polymap(&[x, MPoly::var(2, 0)]),
            Err(GeomError::Dimension(_))
        ));
        assert!(PolyMap::<Rational>::identity(0).is_err());
        let c = BezierCurve::from_points(&[pt(&[0, 1, 2])]).expect("valid");
        assert!(sigma().apply_curve(&c).is_err());
        assert!(sigma().eval(&pt(&[1, 2])).is_err());
    }
}

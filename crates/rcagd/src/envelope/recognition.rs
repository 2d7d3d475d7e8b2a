//! Recognition of a given two-parameter sphere family: which line net of D. Gruber,
//! "Rationale Parametrisierungen von Kugelhüllflächen" (2008), chapter 3 it belongs to, its
//! support functions, and its rational envelope — or a named reason why there is none.
//!
//! Derivation: `docs/math/sphere-families.md#recognition`. In the cyclographic model the
//! family is a surface `Φ(u, v) = (m, r) ∈ R^{3,1}`. Its tangent plane has the ideal line
//! `g = Φ_u ∧ Φ_v` (Plücker coordinates of two ideal points), and the envelope points come
//! from the points of the polar line `h = E g` on Ω (Gruber §3.1.2). Gruber's construction
//! (§3.2) applies exactly when the lines `h(u, v)` lie in a regular linear congruence
//! (a line net, a fibration of the ideal space):
//!
//! 1. The coefficient vectors of `h(u, v)` span a linear space of Plücker space; a
//!    congruence needs dimension 4. Its two complexes `C₁, C₂` (the kernel of the reciprocal
//!    product) span a pencil whose singular members — the roots of the quadratic form
//!    `q(λ, μ) = Ω(λC₁ + μC₂, λC₁ + μC₂)` — are the axes: two real roots (hyperbolic net), two
//!    conjugate ones (elliptic), a double root (parabolic). The roots are rational exactly
//!    when the discriminant `Δ = K₁₂² − K₁₁K₂₂` (`Kᵢⱼ = Ω(Cᵢ, Cⱼ)`) is a square in the
//!    scalar field (`−Δ` for elliptic nets, whose axes then lie in `Q(i)`).
//! 2. The net parameters of the line `h(u, v)` are rational functions
//!    ([`LineNet::parameters_of_point`] on a point of `h`), and the support function is
//!    the value of the tangent hyperplane through `Φ` with ideal plane `e = D c(u)`:
//!    `a(u) = e(u)ᵀ Φ` (constant along the family's curves with the same `u`, because `e`
//!    contains `g`). It is found as a univariate rational function by linear algebra;
//!    a single pole `ρ` is moved to `u = ∞` by choosing the axis point `c(ρ)` as the row's
//!    direction (a Möbius change of the axis parameter), after which the support function
//!    of Gruber (3.6) is polynomial; a denominator with several roots is kept as a
//!    rational support function ([`Support::over`]; hyperbolic and elliptic nets — on a
//!    parabolic net `a_u = b_v` ties `b` to `a′` and only a polynomial `a` is recovered).
//! 3. The envelope is built from the recovered net and support functions
//!    ([`SphereFamilyEnvelope`]), and the certificate `Φ_net(u(u, v), v(u, v)) ≡ Φ(u, v)`
//!    proves that it is the envelope of the given family.
//!
//! The decisions (the rank of the span, `Δ` zero or a square, the kernel of the support
//! system) are exact for exact scalars; recognize exact data and convert the result
//! ([`SphereFamilyEnvelope::map_scalar`]) for `f64` work.

use super::sphere_family::{SphereFamilyEnvelope, SphereFamilyError, Subcase, Support};
use crate::error::format_scalar;
use crate::lines::net::{CPoly, NetParameters};
use crate::lines::plucker::{
    coordinate_plane_points, klein_form, reciprocal_product, swap, wedge, POINT_PAIRS,
};
use crate::lines::{ComplexPointRow, LineNet, PointRow, SqrtScalar};
use crate::pn::poly::{
    abs_mpoly, cancel_gcd, div_exact, gcd2, identity_cert, identity_cert_within, mag,
    normalize_content,
};
use crate::Certified;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::plane_positivity::{plane_positivity, PlanePositivity};
use rcagd_algebra::Rational;
use rcagd_algebra::{sqrt_in_field, Certificate, Matrix, Scalar};
use std::collections::BTreeMap;
use thiserror::Error;

/// Why a sphere family is not recognized. Every variant names the violated condition.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum RecognitionError {
    /// The input is not a family in two parameters (wrong number of variables, zero
    /// denominator).
    #[error("invalid sphere family: {0}")]
    InvalidInput(String),
    /// `Φ_u ∧ Φ_v ≡ 0`: the centres and radii depend on fewer than two parameters.
    #[error("the family is not two-parametric: Φ_u ∧ Φ_v ≡ 0 (centre and radius depend on at most one parameter)")]
    NotTwoParametric,
    /// Every tangent plane of `Φ` is timelike: the normal lines `h` miss Ω, no sphere
    /// touches a real envelope (neighbouring spheres are nested).
    #[error("no real envelope: {0}")]
    NoRealEnvelope(String),
    /// The normal lines `h(u, v)` do not lie in a regular linear congruence, so they are no
    /// line net (Gruber §3.2 needs a fibration of the ideal space).
    #[error("not a fibration: {0}")]
    NotAFibration(String),
    /// The congruence is a line net over the scalar field, but its axes are defined only
    /// over the quadratic extension `Q(√d)`.
    #[error("the axes of the line net need the extension field Q(√{d}): {detail}")]
    NeedsExtension {
        /// The radicand `d` (the discriminant of the pencil of complexes).
        d: String,
        /// What was found.
        detail: String,
    },
    /// A support function could not be recovered: no rational function of bounded degree
    /// fits, or a parabolic net's support function has several poles.
    #[error("the support function {which} is not supported: {detail}")]
    UnsupportedSupport {
        /// `"a"` or `"b"`.
        which: &'static str,
        /// The rational function found.
        detail: String,
    },
    /// The linear system (3.7) of the recovered data does not reproduce the family.
    #[error("inconsistent system: {0}")]
    Inconsistent(String),
    /// The envelope construction of the recovered net failed.
    #[error(transparent)]
    Envelope(#[from] SphereFamilyError),
}

/// A rational two-parameter sphere family `Φ(u, v) = (centre, radius) = N(u, v)/D(u, v)`.
#[derive(Debug, Clone)]
pub struct SphereFamily<F> {
    num: [MPoly<F>; 4],
    den: MPoly<F>,
}

impl<F: Scalar> SphereFamily<F> {
    /// The family with centre `(X, Y, Z)/W` and signed radius `R/W` (polynomials in the
    /// two variables `u`, `v`).
    ///
    /// # Errors
    /// [`RecognitionError::InvalidInput`] for a polynomial not in two variables or `W ≡ 0`.
    pub fn new(
        centre: [MPoly<F>; 3],
        radius: MPoly<F>,
        den: MPoly<F>,
    ) -> Result<Self, RecognitionError> {
        let [x, y, z] = centre;
        let num = [x, y, z, radius];
        if num.iter().chain([&den]).any(|p| p.nvars() != 2) {
            return Err(RecognitionError::InvalidInput(
                "centre, radius and denominator are polynomials in the two parameters u, v".into(),
            ));
        }
        if den.is_zero() {
            return Err(RecognitionError::InvalidInput(
                "the denominator W is the zero polynomial".into(),
            ));
        }
        let mut all: Vec<MPoly<F>> = num.to_vec();
        all.push(den);
        cancel_gcd(&mut all);
        normalize_content(&mut all);
        Ok(SphereFamily {
            num: core::array::from_fn(|k| all[k].clone()),
            den: all[4].clone(),
        })
    }

    /// The family from four rational functions `(numerator, denominator)`: the centre
    /// coordinates and the radius (brought to a common denominator).
    ///
    /// # Errors
    /// As [`Self::new`], also for a zero denominator.
    pub fn from_rational(coords: [(MPoly<F>, MPoly<F>); 4]) -> Result<Self, RecognitionError> {
        let mut l = MPoly::constant(2, F::one());
        for (_, d) in &coords {
            if d.is_zero() || d.nvars() != 2 {
                return Err(RecognitionError::InvalidInput(
                    "every denominator is a non-zero polynomial in u, v".into(),
                ));
            }
            let g = gcd2(&l, d);
            let q = div_exact(d, &g).unwrap_or_else(|| d.clone());
            l = &l * &q;
        }
        let num: Vec<MPoly<F>> = coords
            .iter()
            .map(|(n, d)| {
                let f = div_exact(&l, d).unwrap_or_else(|| l.clone());
                n * &f
            })
            .collect();
        Self::new(
            [num[0].clone(), num[1].clone(), num[2].clone()],
            num[3].clone(),
            l,
        )
    }

    /// `(N, D)`: `Φ = N/D`, `N = (X, Y, Z, R)`.
    pub fn numerators(&self) -> (&[MPoly<F>; 4], &MPoly<F>) {
        (&self.num, &self.den)
    }

    /// Recognizes the family (module docs).
    ///
    /// # Errors
    /// [`RecognitionError::NotTwoParametric`], [`RecognitionError::NoRealEnvelope`],
    /// [`RecognitionError::NotAFibration`], [`RecognitionError::NeedsExtension`],
    /// [`RecognitionError::UnsupportedSupport`], [`RecognitionError::Inconsistent`] and the
    /// errors of [`SphereFamilyEnvelope::new`].
    pub fn recognize(&self) -> Result<Recognition<F>, RecognitionError> {
        recognize(self)
    }
}

/// A recognized sphere family: the line net of its normal lines, the support functions,
/// the envelope, and the map from the family's parameters to the net parameters.
#[derive(Debug, Clone)]
pub struct Recognition<F> {
    family: SphereFamily<F>,
    complexes: [[F; 6]; 2],
    normals: [MPoly<F>; 6],
    params: NetParameters<F>,
    envelope: SphereFamilyEnvelope<F>,
    discriminant: F,
}

impl<F: Scalar> Recognition<F> {
    /// The subcase of Gruber chapter 3.
    pub fn subcase(&self) -> Subcase {
        self.envelope.subcase()
    }

    /// The recovered line net.
    pub fn net(&self) -> &LineNet<F> {
        self.envelope.net()
    }

    /// The envelope built from the recovered net and support functions.
    pub fn envelope(&self) -> &SphereFamilyEnvelope<F> {
        &self.envelope
    }

    /// The recovered support functions `(a, b)` in the net parameters.
    pub fn supports(&self) -> (&Support<F>, &Support<F>) {
        self.envelope.supports()
    }

    /// The two linear complexes whose common lines form the congruence of the normals.
    pub fn complexes(&self) -> &[[F; 6]; 2] {
        &self.complexes
    }

    /// The discriminant `Δ = K₁₂² − K₁₁K₂₂` of the pencil of complexes (`> 0` hyperbolic,
    /// `< 0` elliptic, `0` parabolic).
    pub fn discriminant(&self) -> &F {
        &self.discriminant
    }

    /// The net parameters as rational functions of the family's parameters `(u, v)`.
    pub fn net_parameters(&self) -> &NetParameters<F> {
        &self.params
    }
}

/// The cyclographic construction (Gruber 2008 §3.1.2) at one sphere `Φ(u, v)` of a directly
/// given family ([`SphereFamily::cyclographic_at`]): the family parameters, the net
/// parameters of the recognized net, the sphere and its two contact points with the
/// envelope (over the square-root extension: rational exactly when the normal line meets
/// Ω in rational points).
#[derive(Debug, Clone, PartialEq)]
pub struct FamilyContacts<F: SqrtScalar> {
    /// The family parameters `(u, v)`.
    pub parameters: [F; 2],
    /// The net parameters of the sphere (the recognized net's `(u, v)`).
    pub net_parameters: [F; 2],
    /// The sphere `(centre, signed radius)` of the given family.
    pub sphere: ([F; 3], F),
    /// The two contact points `S ∩ S_u ∩ S_v`.
    pub points: [[F::Ext; 3]; 2],
    /// The family's centre and radius derivatives `(m_u, r_u)`, `(m_v, r_v)` at `(u, v)`.
    derivatives: [([F; 3], F); 2],
}

impl<F: SqrtScalar> FamilyContacts<F> {
    /// The contact points as rationals of the base field, `None` if irrational.
    pub fn rational_points(&self) -> Option<[[F; 3]; 2]> {
        let back = |x: &F::Ext| x.to_rational().map(|r| F::from_rational(&r));
        let pt = |p: &[F::Ext; 3]| -> Option<[F; 3]> {
            Some([back(&p[0])?, back(&p[1])?, back(&p[2])?])
        };
        Some([pt(&self.points[0])?, pt(&self.points[1])?])
    }
}

impl<F: SqrtScalar> Certified for FamilyContacts<F> {
    /// For both points `x`, with the given family's own centre `m`, radius `r` and their
    /// derivatives at `(u, v)` (independent of the recovered net): `|x − m|² = r²` (on the
    /// sphere `S`), `⟨x − m, m_u⟩ + r r_u = 0` and `⟨x − m, m_v⟩ + r r_v = 0` (on `S_u` and
    /// `S_v`: the characteristic points of the family, Gruber §3.1.1) — exact over the
    /// extension field.
    fn certify(&self) -> Vec<Certificate> {
        let (m, r) = &self.sphere;
        let e = |x: &F| x.embed();
        let mut out = Vec::new();
        let [u, v] = &self.parameters;
        for (k, x) in self.points.iter().enumerate() {
            let d: [F::Ext; 3] = core::array::from_fn(|i| x[i].clone() - e(&m[i]));
            let dot = |a: &[F::Ext; 3], b: &[F::Ext; 3]| {
                a.iter()
                    .zip(b)
                    .fold(<F::Ext as num_traits::Zero>::zero(), |acc, (p, q)| {
                        acc + p.clone() * q.clone()
                    })
            };
            let on = dot(&d, &d) - e(r) * e(r);
            let mut checks = vec![("on the sphere S: |x − m|² − r² = 0", on)];
            for ((mu, ru), name) in self.derivatives.iter().zip(["S_u", "S_v"]) {
                let mu_e: [F::Ext; 3] = core::array::from_fn(|i| e(&mu[i]));
                let val = dot(&d, &mu_e) + e(r) * e(ru);
                checks.push((
                    if name == "S_u" {
                        "on S_u: ⟨x − m, m_u⟩ + r r_u = 0"
                    } else {
                        "on S_v: ⟨x − m, m_v⟩ + r r_v = 0"
                    },
                    val,
                ));
            }
            for (what, val) in checks {
                out.push(Certificate::decide(
                    format!(
                        "contact point {} of the sphere Φ({}, {}) (cyclographic construction, Gruber §3.1.2) {what}",
                        k + 1,
                        format_scalar(u),
                        format_scalar(v)
                    ),
                    crate::lines::is_small(&val, 1.0),
                    F::EXACT,
                    || format_scalar(&val),
                ));
            }
        }
        out
    }
}

impl<F: SqrtScalar> SphereFamily<F> {
    /// The sphere `Φ(u, v)`, its centre and radius derivatives at `(u, v)` (quotient rule).
    #[allow(clippy::type_complexity)]
    fn jet(&self, u: &F, v: &F) -> Result<(([F; 3], F), [([F; 3], F); 2]), RecognitionError> {
        let x = [u.clone(), v.clone()];
        let ev = |p: &MPoly<F>| {
            p.eval(&x)
                .map_err(|e| RecognitionError::InvalidInput(e.to_string()))
        };
        let w = ev(&self.den)?;
        if w.is_zero() {
            return Err(RecognitionError::InvalidInput(format!(
                "the family has a pole at ({}, {}): W = 0",
                format_scalar(u),
                format_scalar(v)
            )));
        }
        let n: Vec<F> = self.num.iter().map(ev).collect::<Result<_, _>>()?;
        let val: Vec<F> = n.iter().map(|c| c.clone() / w.clone()).collect();
        let mut ders = Vec::with_capacity(2);
        for i in 0..2 {
            let wi = ev(&self.den.partial(i))?;
            let d: Vec<F> = self
                .num
                .iter()
                .zip(&n)
                .map(|(p, nk)| {
                    ev(&p.partial(i)).map(|ni| {
                        (ni * w.clone() - nk.clone() * wi.clone()) / (w.clone() * w.clone())
                    })
                })
                .collect::<Result<_, _>>()?;
            ders.push(([d[0].clone(), d[1].clone(), d[2].clone()], d[3].clone()));
        }
        let [du, dv] = <[([F; 3], F); 2]>::try_from(ders)
            .map_err(|_| RecognitionError::InvalidInput("two derivatives".into()))?;
        Ok((
            (
                [val[0].clone(), val[1].clone(), val[2].clone()],
                val[3].clone(),
            ),
            [du, dv],
        ))
    }

    /// Recognition and the cyclographic construction in one call: the family is
    /// recognized ([`Self::recognize`]), `(u, v)` mapped to the net parameters of the
    /// recovered net, and the construction of Gruber §3.1.2
    /// ([`SphereFamilyEnvelope::cyclographic_envelope`]) run at the sphere `Φ(u, v)`; the
    /// result is certified against the family's own derivatives ([`FamilyContacts`]).
    ///
    /// # Errors
    /// The recognition's errors; [`RecognitionError::InvalidInput`] for a pole of the family
    /// or of the net parameters at `(u, v)`; [`RecognitionError::Envelope`] if the
    /// construction fails there (a singular point of Φ, a timelike tangent plane: no real
    /// contact point).
    pub fn cyclographic_at(&self, u: &F, v: &F) -> Result<FamilyContacts<F>, RecognitionError> {
        let rec = self.recognize()?;
        rec.cyclographic_at(u, v)
    }
}

impl<F: SqrtScalar> Recognition<F> {
    /// The cyclographic construction at the sphere `Φ(u, v)` of the recognized family
    /// ([`SphereFamily::cyclographic_at`]).
    ///
    /// # Errors
    /// As [`SphereFamily::cyclographic_at`] without the recognition.
    pub fn cyclographic_at(&self, u: &F, v: &F) -> Result<FamilyContacts<F>, RecognitionError> {
        let (p, q) = self.params.at(u, v).ok_or_else(|| {
            RecognitionError::InvalidInput(format!(
                "the net parameters have a pole at ({}, {})",
                format_scalar(u),
                format_scalar(v)
            ))
        })?;
        let (sphere, derivatives) = self.family.jet(u, v)?;
        let ce = self.envelope.cyclographic_envelope(&p, &q)?;
        Ok(FamilyContacts {
            parameters: [u.clone(), v.clone()],
            net_parameters: [p, q],
            sphere,
            points: ce.points,
            derivatives,
        })
    }
}

impl Recognition<Rational> {
    /// This exact recognition with its envelope built in the scalar `G` (`f64`): the
    /// recognition's decisions — the rank of the normal lines' span, the pencil of
    /// complexes and its discriminant (zero, a square in Q), the recovered net and support
    /// functions — are those of this exact recognition of the input; the envelope is
    /// constructed in `G` from the net and support functions ([`SphereFamilyEnvelope::new_along`])
    /// replaying the common factors the exact construction divided out
    /// ([`SphereFamilyEnvelope::reductions`]; with `other_sheet` also the other sheet's),
    /// and the normal lines `h = E(Φ_u ∧ Φ_v)` are formed in `G` from the family's
    /// coefficients in `G`, so that [`Certified::certify`] of the result checks, in `G`,
    /// that they lie in both (exact) complexes and that the `G` envelope's family is the
    /// given one.
    ///
    /// # Errors
    /// [`RecognitionError::Envelope`] if a replayed factor does not divide in `G` up to
    /// rounding.
    pub fn in_scalar<G: Scalar>(
        &self,
        other_sheet: bool,
    ) -> Result<Recognition<G>, RecognitionError> {
        let f = |x: &Rational| G::from_rational(x);
        let exact = if other_sheet {
            self.envelope.clone().with_other_sheet_divisor()
        } else {
            self.envelope.clone()
        };
        let replay = exact.reductions().map(f);
        let (a, b) = self.envelope.supports();
        let envelope = SphereFamilyEnvelope::new_along(
            &self.envelope.net().map_scalar(f),
            a.map(f),
            b.map(f),
            Some(&replay),
        )?;
        let family = SphereFamily {
            num: core::array::from_fn(|k| self.family.num[k].map(f)),
            den: self.family.den.map(f),
        };
        let (pu, pv) = tangents(&family);
        let normals = polar_omega(&wedge(&pu, &pv));
        let p = &self.params;
        Ok(Recognition {
            family,
            complexes: core::array::from_fn(|i| core::array::from_fn(|k| f(&self.complexes[i][k]))),
            normals,
            params: NetParameters {
                first: p.first.map(f),
                first_den: p.first_den.map(f),
                second: p.second.map(f),
                second_den: p.second_den.map(f),
            },
            envelope,
            discriminant: f(&self.discriminant),
        })
    }
}

/// The tangent directions `Φ_u`, `Φ_v` of the family as ideal points (numerators of the
/// quotient rule: `N_i D − N D_i`).
fn tangents<F: Scalar>(fam: &SphereFamily<F>) -> ([MPoly<F>; 4], [MPoly<F>; 4]) {
    let (n, d) = (&fam.num, &fam.den);
    let tangent = |i: usize| -> [MPoly<F>; 4] {
        core::array::from_fn(|k| &(&n[k].partial(i) * d) - &(&n[k] * &d.partial(i)))
    };
    (tangent(0), tangent(1))
}

impl<F: Scalar> Certified for Recognition<F> {
    /// Every normal line `h(u, v)` lies in both complexes; the recovered family equals the
    /// given one, `Φ_net(u(u, v), v(u, v)) ≡ Φ(u, v)`; and every certificate of the envelope.
    /// For `f64` the residual of `Ω(C, h) ≡ 0` is compared with the size of its terms
    /// (`Σ |Cᵢ||h_j|` per monomial), not with its own cancelled coefficients.
    fn certify(&self) -> Vec<Certificate> {
        let mut out = Vec::new();
        let abs_normals: [MPoly<f64>; 6] = core::array::from_fn(|i| abs_mpoly(&self.normals[i]));
        for (k, c) in self.complexes.iter().enumerate() {
            let cp: [MPoly<F>; 6] = core::array::from_fn(|i| MPoly::constant(2, c[i].clone()));
            let v = reciprocal_product(&cp, &self.normals);
            let abs_c: [MPoly<f64>; 6] = core::array::from_fn(|i| abs_mpoly(&cp[i]));
            out.push(identity_cert_within(
                &format!(
                    "the normal lines h = E(Φ_u ∧ Φ_v) lie in the complex C{}: Ω(C{}, h(u, v)) ≡ 0 (a line net, Gruber §1.1.4)",
                    k + 1,
                    k + 1
                ),
                &v,
                &MPoly::zero(2),
                &reciprocal_product(&abs_c, &abs_normals),
            ));
        }
        out.extend(same_family_certificates(
            &self.family,
            &self.envelope,
            &self.params,
        ));
        out.extend(self.envelope.certify());
        out
    }
}

fn same_family_certificates<F: Scalar>(
    family: &SphereFamily<F>,
    env: &SphereFamilyEnvelope<F>,
    params: &NetParameters<F>,
) -> Vec<Certificate> {
    let (phi, den) = env.phi();
    let d = NetParameters::degree_bounds(phi.iter().chain([den]));
    let sub = |p: &MPoly<F>| params.substitute(p, d);
    let rd = sub(den);
    let names = ["x", "y", "z", "r"];
    (0..4)
        .map(|k| {
            let lhs = &sub(&phi[k]) * &family.den;
            let rhs = &family.num[k] * &rd;
            identity_cert(
                &format!(
                    "the recognized family is the given one: Φ_net,{}(net parameters(u, v)) ≡ Φ_{}(u, v)",
                    names[k], names[k]
                ),
                &lhs,
                &rhs,
            )
        })
        .collect()
}

// ---------------------------------------------------------------------------------------
// small complex numbers over the scalar

#[derive(Debug, Clone, PartialEq)]
struct Cx<F> {
    re: F,
    im: F,
}

impl<F: Scalar> Cx<F> {
    fn real(re: F) -> Self {
        Cx { re, im: F::zero() }
    }
    fn zero() -> Self {
        Cx::real(F::zero())
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }
    fn add(&self, o: &Self) -> Self {
        Cx {
            re: self.re.clone() + o.re.clone(),
            im: self.im.clone() + o.im.clone(),
        }
    }
    fn mul(&self, o: &Self) -> Self {
        Cx {
            re: self.re.clone() * o.re.clone() - self.im.clone() * o.im.clone(),
            im: self.re.clone() * o.im.clone() + self.im.clone() * o.re.clone(),
        }
    }
    fn neg(&self) -> Self {
        Cx {
            re: -self.re.clone(),
            im: -self.im.clone(),
        }
    }
    fn div(&self, o: &Self) -> Option<Self> {
        let n = o.re.clone() * o.re.clone() + o.im.clone() * o.im.clone();
        let inv = n.inv().filter(|_| !n.is_zero())?;
        let c = Cx {
            re: o.re.clone() * inv.clone(),
            im: -(o.im.clone() * inv),
        };
        Some(self.mul(&c))
    }
    fn text(&self) -> String {
        if self.im.is_zero() {
            format_scalar(&self.re)
        } else {
            format!(
                "({} + {}·i)",
                format_scalar(&self.re),
                format_scalar(&self.im)
            )
        }
    }
}

fn negligible<F: Scalar>(p: &MPoly<F>) -> bool {
    if F::EXACT {
        return p.is_zero();
    }
    let s = mag(p);
    p.terms()
        .all(|(_, c)| c.to_f64().abs() <= 1e-9 * s.max(1.0))
        || p.is_zero()
}

fn scalar_zero<F: Scalar>(x: &F, scale: f64) -> bool {
    if F::EXACT {
        x.is_zero()
    } else {
        x.to_f64().abs() <= 1e-9 * scale.max(1.0)
    }
}

fn cst<F: Scalar>(c: &F) -> MPoly<F> {
    MPoly::constant(2, c.clone())
}

/// The Lorentz product `a₁b₁ + a₂b₂ + a₃b₃ − a₄b₄` of polynomial 4-vectors.
fn lorentz<F: Scalar>(a: &[MPoly<F>; 4], b: &[MPoly<F>; 4]) -> MPoly<F> {
    &(&(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])) - &(&a[3] * &b[3])
}

/// `Some(proof)` if the Lorentz Gram determinant `gram` of the family's tangent planes is
/// negative at every real `(u, v)` off the poles `den = 0`: first the sufficient test of
/// [`certainly_positive`] on `−gram`, then the exact decision
/// [`rcagd_algebra::plane_positivity::plane_positivity`] on `−gram / den^{2k}` (the largest
/// even power of the denominator that divides it; the sign is kept). `None` when `gram ≥ 0`
/// somewhere (a real envelope point, possibly a double one) or the decision stays open.
fn timelike_everywhere<F: Scalar>(gram: &MPoly<F>, den: &MPoly<F>) -> Option<String> {
    let neg = -gram;
    if certainly_positive(&neg) {
        return Some("every term of −Gram is an even monomial with a positive coefficient".into());
    }
    let to_q = |p: &MPoly<F>| -> Option<MPoly<Rational>> {
        let terms = p
            .terms()
            .map(|(e, c)| Some((e.to_vec(), c.to_rational()?)))
            .collect::<Option<Vec<_>>>()?;
        MPoly::from_terms(p.nvars().max(2), terms).ok()
    };
    let mut g = to_q(&neg)?;
    if let Some(dq) = to_q(den) {
        if dq.total_degree().unwrap_or(0) > 0 {
            let d2 = &dq * &dq;
            while let Some(q) = div_exact(&g, &d2) {
                g = q;
            }
        }
    }
    match plane_positivity(&g) {
        Ok(PlanePositivity::Positive(proof)) => Some(format!("proved: {}", proof.summary)),
        _ => None,
    }
}

/// `p > 0` on all of R², decided by a sufficient condition: a positive constant term and
/// every other term an even monomial `u^{2i} v^{2j}` with a positive coefficient.
fn certainly_positive<F: Scalar>(p: &MPoly<F>) -> bool {
    let c0 = p.coeff(&[0, 0]);
    c0 > F::zero()
        && p.terms()
            .all(|(e, c)| e.iter().all(|k| k % 2 == 0) && *c > F::zero())
}

/// The polar line `h = E g` with respect to Ω (Gruber (1.19)).
fn polar_omega<F: Scalar>(g: &[MPoly<F>; 6]) -> [MPoly<F>; 6] {
    [
        -&g[3],
        -&g[4],
        g[5].clone(),
        g[0].clone(),
        g[1].clone(),
        -&g[2],
    ]
}

/// Two points spanning the real line `l`.
fn real_points<F: Scalar>(l: &[F; 6]) -> Option<([F; 4], [F; 4])> {
    let s = coordinate_plane_points(l);
    let best = POINT_PAIRS
        .iter()
        .max_by(|a, b| {
            l[a.2]
                .abs()
                .partial_cmp(&l[b.2].abs())
                .unwrap_or(core::cmp::Ordering::Equal)
        })
        .copied()?;
    if l[best.2].is_zero() {
        return None;
    }
    Some((s[best.0].clone(), s[best.1].clone()))
}

/// Two complex points `(c₀, c₁)` of a complex point row.
type ComplexRow<F> = ([Cx<F>; 4], [Cx<F>; 4]);

/// Two points spanning the complex line `re + i·im`.
fn complex_points<F: Scalar>(re: &[F; 6], im: &[F; 6]) -> Option<ComplexRow<F>> {
    let sr = coordinate_plane_points(re);
    let si = coordinate_plane_points(im);
    let (i, j, _) = POINT_PAIRS
        .iter()
        .copied()
        .find(|p| !re[p.2].is_zero() || !im[p.2].is_zero())?;
    let pt = |k: usize| -> [Cx<F>; 4] {
        core::array::from_fn(|n| Cx {
            re: sr[k][n].clone(),
            im: si[k][n].clone(),
        })
    };
    Some((pt(i), pt(j)))
}

/// The null plane of the point `x` in the linear complex `n`: `y ↦ Ω(n, x ∧ y)`.
fn null_plane<F: Scalar>(n: &[F; 6], x: &[F; 4]) -> [F; 4] {
    core::array::from_fn(|j| {
        let mut e: [F; 4] = core::array::from_fn(|_| F::zero());
        e[j] = F::one();
        reciprocal_product(n, &wedge(x, &e))
    })
}

/// The point where the line `p ∧ q` meets the plane `π`: `(π·q) p − (π·p) q`.
fn meet<F: Scalar>(p: &[F; 4], q: &[F; 4], pi: &[F; 4]) -> [F; 4] {
    let d = |a: &[F; 4]| {
        a.iter()
            .zip(pi)
            .fold(F::zero(), |s, (x, y)| s + x.clone() * y.clone())
    };
    let (pq, pp) = (d(q), d(p));
    core::array::from_fn(|k| pq.clone() * p[k].clone() - pp.clone() * q[k].clone())
}

/// The vectors scaled jointly to integers without a common factor (exact scalars).
fn primitive<F: Scalar, const N: usize>(v: [[F; 4]; N]) -> [[F; 4]; N] {
    let mut polys: Vec<MPoly<F>> = v.iter().flatten().map(cst).collect();
    normalize_content(&mut polys);
    core::array::from_fn(|i| {
        core::array::from_fn(|k| {
            polys
                .get(4 * i + k)
                .map(|p| p.coeff(&[0, 0]))
                .unwrap_or_else(F::zero)
        })
    })
}

fn primitive_row<F: Scalar>(r: ([F; 4], [F; 4])) -> ([F; 4], [F; 4]) {
    let [a] = primitive([r.0]);
    let [b] = primitive([r.1]);
    (a, b)
}

fn primitive_complex<F: Scalar>(c: ComplexRow<F>) -> ComplexRow<F> {
    let split = |p: &[Cx<F>; 4]| -> [[F; 4]; 2] {
        [
            core::array::from_fn(|k| p[k].re.clone()),
            core::array::from_fn(|k| p[k].im.clone()),
        ]
    };
    let join = |x: [[F; 4]; 2]| -> [Cx<F>; 4] {
        core::array::from_fn(|k| Cx {
            re: x[0][k].clone(),
            im: x[1][k].clone(),
        })
    };
    (join(primitive(split(&c.0))), join(primitive(split(&c.1))))
}

/// The axes of the recovered net, before the choice of the parametrization is final.
#[derive(Debug, Clone)]
enum Axes<F> {
    Hyperbolic {
        c: ([F; 4], [F; 4]),
        d: ([F; 4], [F; 4]),
    },
    Elliptic {
        c: ComplexRow<F>,
    },
    Parabolic {
        c: ([F; 4], [F; 4]),
        /// A regular complex of the pencil (its null planes are the pencil planes).
        n: [F; 6],
    },
}

fn parabolic_rows<F: Scalar>(
    c: &([F; 4], [F; 4]),
    n: &[F; 6],
) -> Result<(PointRow<F>, PointRow<F>), RecognitionError> {
    let axis = wedge(&c.0, &c.1);
    // a coordinate line skew to the axis
    let mut lines = Vec::new();
    for i in 0..4 {
        for j in i + 1..4 {
            let mut p: [F; 4] = core::array::from_fn(|_| F::zero());
            let mut q = p.clone();
            p[i] = F::one();
            q[j] = F::one();
            lines.push((p, q));
        }
    }
    let (p, q) = lines
        .into_iter()
        .find(|(p, q)| !reciprocal_product(&axis, &wedge(p, q)).is_zero())
        .ok_or_else(|| {
            RecognitionError::NotAFibration("the parabolic axis meets every coordinate line".into())
        })?;
    let d0 = meet(&p, &q, &null_plane(n, &c.0));
    let d1 = meet(&p, &q, &null_plane(n, &c.1));
    let cr = PointRow::new(c.0.clone(), c.1.clone()).map_err(SphereFamilyError::from)?;
    let dr = PointRow::new(d0, d1).map_err(SphereFamilyError::from)?;
    Ok((cr, dr))
}

impl<F: Scalar> Axes<F> {
    fn normalized(self) -> Self {
        match self {
            Axes::Hyperbolic { c, d } => Axes::Hyperbolic {
                c: primitive_row(c),
                d: primitive_row(d),
            },
            Axes::Elliptic { c } => Axes::Elliptic {
                c: primitive_complex(c),
            },
            Axes::Parabolic { c, n } => Axes::Parabolic {
                c: primitive_row(c),
                n,
            },
        }
    }

    fn net(&self) -> Result<LineNet<F>, RecognitionError> {
        let row = |r: &([F; 4], [F; 4])| {
            PointRow::new(r.0.clone(), r.1.clone()).map_err(SphereFamilyError::from)
        };
        Ok(match self {
            Axes::Hyperbolic { c, d } => {
                LineNet::hyperbolic(row(c)?, row(d)?).map_err(SphereFamilyError::from)?
            }
            Axes::Elliptic { c } => LineNet::elliptic(ComplexPointRow {
                origin_re: core::array::from_fn(|k| c.0[k].re.clone()),
                origin_im: core::array::from_fn(|k| c.0[k].im.clone()),
                direction_re: core::array::from_fn(|k| c.1[k].re.clone()),
                direction_im: core::array::from_fn(|k| c.1[k].im.clone()),
            })
            .map_err(SphereFamilyError::from)?,
            Axes::Parabolic { c, n } => {
                let (cr, dr) = parabolic_rows(c, n)?;
                LineNet::parabolic(cr, dr).map_err(SphereFamilyError::from)?
            }
        })
    }

    /// Moves the pole `ρ` of the support function on the first (`first = true`) or second
    /// axis to the parameter ∞: the row `(p₀, p₁)` becomes `(p₁, p₀ + ρ p₁)`.
    fn move_pole(&mut self, first: bool, rho: &Cx<F>) {
        let mv = |r: &mut ([F; 4], [F; 4])| {
            let o: [F; 4] =
                core::array::from_fn(|k| r.0[k].clone() + rho.re.clone() * r.1[k].clone());
            *r = (r.1.clone(), o);
        };
        match self {
            Axes::Hyperbolic { c, d } => {
                if first {
                    mv(c)
                } else {
                    mv(d)
                }
            }
            Axes::Parabolic { c, .. } => mv(c),
            Axes::Elliptic { c } => {
                let o: [Cx<F>; 4] = core::array::from_fn(|k| c.0[k].add(&rho.mul(&c.1[k])));
                *c = (c.1.clone(), o);
            }
        }
        *self = self.clone().normalized();
    }
}

fn recognize<F: Scalar>(fam: &SphereFamily<F>) -> Result<Recognition<F>, RecognitionError> {
    let d = &fam.den;
    // tangent directions (ideal points) by the quotient rule
    let (pu, pv) = tangents(fam);
    let g = wedge(&pu, &pv);
    if g.iter().all(negligible) {
        return Err(RecognitionError::NotTwoParametric);
    }
    // the tangent plane's Lorentz Gram determinant
    let gram =
        &(&lorentz(&pu, &pu) * &lorentz(&pv, &pv)) - &(&lorentz(&pu, &pv) * &lorentz(&pu, &pv));
    if let Some(proof) = timelike_everywhere(&gram, d) {
        return Err(RecognitionError::NoRealEnvelope(format!(
            "the Lorentz Gram determinant of the tangent plane, ⟨Φ_u,Φ_u⟩⟨Φ_v,Φ_v⟩ − ⟨Φ_u,Φ_v⟩², is negative for all real (u, v) ({proof}): every tangent plane is timelike, its normal line misses Ω (Gruber §3.1.2), neighbouring spheres are nested"
        )));
    }
    let h = polar_omega(&g);
    // coefficient vectors of h
    let mut rows: BTreeMap<Vec<u32>, [F; 6]> = BTreeMap::new();
    for (k, p) in h.iter().enumerate() {
        for (e, c) in p.terms() {
            let r = rows
                .entry(e.to_vec())
                .or_insert_with(|| core::array::from_fn(|_| F::zero()));
            r[k] = c.clone();
        }
    }
    let m = Matrix::from_rows(rows.values().map(|r| r.to_vec()).collect())
        .map_err(|e| RecognitionError::InvalidInput(e.to_string()))?;
    let rank = m.rank();
    if rank != 4 {
        let what = match rank {
            5 | 6 => "they lie in no linear congruence (a line net spans 4)",
            3 => "they form a bundle, a ruled field or a regulus, not a regular line net (which spans 4)",
            _ => "they form at most a pencil, not a regular line net (which spans 4)",
        };
        return Err(RecognitionError::NotAFibration(format!(
            "the normal lines h(u, v) = E(Φ_u ∧ Φ_v) span a {rank}-dimensional space of Plücker coordinates: {what}"
        )));
    }
    let ker = m.null_space();
    if ker.len() != 2 {
        return Err(RecognitionError::NotAFibration(format!(
            "the normal lines lie in {} independent complexes, a line net in 2",
            ker.len()
        )));
    }
    let cx: [[F; 6]; 2] = core::array::from_fn(|i| {
        let v: [F; 6] = core::array::from_fn(|k| ker[i].get(k).cloned().unwrap_or_else(F::zero));
        swap(&v)
    });
    let [c1, c2] = cx.clone();
    let k11 = klein_form(&c1);
    let k22 = klein_form(&c2);
    let k12 = reciprocal_product(&c1, &c2) * F::from_ratio(1, 2);
    let delta = k12.clone() * k12.clone() - k11.clone() * k22.clone();
    let sc = [&k11, &k12, &k22]
        .iter()
        .map(|x| x.to_f64().abs())
        .fold(1.0, f64::max);
    let comb = |l: &F, m: &F| -> [F; 6] {
        core::array::from_fn(|k| l.clone() * c1[k].clone() + m.clone() * c2[k].clone())
    };
    let radicand = |d: &F| -> String { format_scalar(d) };
    let axes = if scalar_zero(&k11, sc) && scalar_zero(&k12, sc) && scalar_zero(&k22, sc) {
        return Err(RecognitionError::NotAFibration(
            "every complex of the pencil is singular: the normal lines meet two intersecting lines (a singular congruence: a bundle and a ruled field), not a fibration".into(),
        ));
    } else if scalar_zero(&delta, sc * sc) {
        // parabolic: the double root is the axis
        let (axis, regular) = if !scalar_zero(&k11, sc) {
            (comb(&-k12.clone(), &k11), c1.clone())
        } else {
            (c1.clone(), c2.clone())
        };
        let c = real_points(&axis).ok_or_else(|| {
            RecognitionError::NotAFibration("the parabolic axis is degenerate".into())
        })?;
        Axes::Parabolic { c, n: regular }
    } else if delta > F::zero() {
        let Some(r) = sqrt_in_field(&delta) else {
            return Err(RecognitionError::NeedsExtension {
                d: radicand(&delta),
                detail: "the normal lines form a hyperbolic net whose two real axes (the singular complexes of the pencil, Gruber §1.1.6) are irrational".into(),
            });
        };
        let (a1, a2) = if !scalar_zero(&k11, sc) {
            (
                comb(&(r.clone() - k12.clone()), &k11),
                comb(&(-r - k12.clone()), &k11),
            )
        } else {
            (c1.clone(), comb(&k22, &(-(k12.clone() * F::from_i64(2)))))
        };
        let c = real_points(&a1)
            .ok_or_else(|| RecognitionError::NotAFibration("an axis is degenerate".into()))?;
        let d = real_points(&a2)
            .ok_or_else(|| RecognitionError::NotAFibration("an axis is degenerate".into()))?;
        Axes::Hyperbolic { c, d }
    } else {
        let Some(r) = sqrt_in_field(&-delta.clone()) else {
            return Err(RecognitionError::NeedsExtension {
                d: radicand(&delta),
                detail: "the normal lines form an elliptic net whose conjugate axes are defined over Q(√Δ), not over Q(i) (−Δ is no square)".into(),
            });
        };
        // axis (−K₁₂ + i r) C₁ + K₁₁ C₂ (K₁₁ ≠ 0 because Δ < 0)
        let re = comb(&-k12.clone(), &k11);
        let im: [F; 6] = core::array::from_fn(|k| r.clone() * c1[k].clone());
        let c = complex_points(&re, &im).ok_or_else(|| {
            RecognitionError::NotAFibration("the elliptic axis is degenerate".into())
        })?;
        Axes::Elliptic { c }
    };
    build(fam, axes, cx, h, delta)
}

/// The net parameters of the line `h(u, v)`: those of one of its points.
fn parameters_of_line<F: Scalar>(
    net: &LineNet<F>,
    h: &[MPoly<F>; 6],
) -> Result<NetParameters<F>, RecognitionError> {
    let s = coordinate_plane_points(h);
    // the points of h in the coordinate planes and a few combinations (the former may all
    // lie on the axes, e.g. for axes in coordinate planes)
    let mut pts: Vec<[MPoly<F>; 4]> = s.to_vec();
    let two = F::from_i64(2);
    for i in 0..4 {
        for j in i + 1..4 {
            pts.push(core::array::from_fn(|k| &s[i][k] + &s[j][k]));
            pts.push(core::array::from_fn(|k| &s[i][k] - &s[j][k]));
            pts.push(core::array::from_fn(|k| &s[i][k] + &s[j][k].scale(&two)));
        }
    }
    for p in pts.iter() {
        if p.iter().all(negligible) {
            continue;
        }
        let Ok(mut par) = net.parameters_of_point(p) else {
            continue;
        };
        if negligible(&par.first_den) || negligible(&par.second_den) {
            continue;
        }
        let mut a = vec![par.first.clone(), par.first_den.clone()];
        cancel_gcd(&mut a);
        normalize_content(&mut a);
        let mut b = vec![par.second.clone(), par.second_den.clone()];
        cancel_gcd(&mut b);
        normalize_content(&mut b);
        par.first = a[0].clone();
        par.first_den = a[1].clone();
        par.second = b[0].clone();
        par.second_den = b[1].clone();
        return Ok(par);
    }
    Err(RecognitionError::NotAFibration(
        "no point of the normal line h(u, v) has a unique net line".into(),
    ))
}

/// A support function found as a univariate rational function of its net parameter.
enum Recovered<F> {
    /// Polynomial coefficients, lowest first.
    Polynomial(Vec<Cx<F>>),
    /// A single pole `ρ` (of some order).
    Pole(Cx<F>),
    /// A rational function `num/den` (coefficients lowest first) whose denominator has
    /// more than one root.
    Rational(Vec<Cx<F>>, Vec<Cx<F>>),
}

fn cpoly_scale_real<F: Scalar>(p: &CPoly<F>, q: &MPoly<F>) -> CPoly<F> {
    CPoly {
        re: &p.re * q,
        im: &p.im * q,
    }
}

/// The univariate `A = N/D` (degrees ≤ K, K minimal) with `A(X/Y) ≡ Tn/Td` (`X`, `Tn`
/// complex, `Y`, `Td` real polynomials in `u, v`), by the kernel of the linear system
/// `Σ nⱼ Xʲ Y^{K−j} Td − Σ dⱼ Xʲ Y^{K−j} Tn ≡ 0`.
fn recover_univariate<F: Scalar>(
    which: &'static str,
    x: &CPoly<F>,
    y: &MPoly<F>,
    tn: &CPoly<F>,
    td: &MPoly<F>,
    complex: bool,
) -> Result<Recovered<F>, RecognitionError> {
    const KMAX: usize = 10;
    for kdeg in 0..=KMAX {
        // Xʲ Y^{K−j}
        let mut xp = vec![CPoly::real(cst(&F::one()))];
        for j in 1..=kdeg {
            let next = xp[j - 1].mul(x);
            xp.push(next);
        }
        let basis: Vec<CPoly<F>> = (0..=kdeg)
            .map(|j| cpoly_scale_real(&xp[j], &y.pow((kdeg - j) as u32)))
            .collect();
        let mut cols: Vec<CPoly<F>> = Vec::new();
        let tdc = CPoly::real(td.clone());
        for (src, sign) in [(&tdc, false), (tn, true)] {
            for b in &basis {
                let mut c = b.mul(src);
                if sign {
                    c = c.neg();
                }
                if complex {
                    let ic = CPoly {
                        re: -&c.im,
                        im: c.re.clone(),
                    };
                    cols.push(c);
                    cols.push(ic);
                } else {
                    cols.push(c);
                }
            }
        }
        // rows: (monomial, real/imaginary part)
        let mut index: BTreeMap<(Vec<u32>, bool), usize> = BTreeMap::new();
        for c in &cols {
            for (part, p) in [(false, &c.re), (true, &c.im)] {
                for (e, _) in p.terms() {
                    let len = index.len();
                    index.entry((e.to_vec(), part)).or_insert(len);
                }
            }
        }
        let nrows = index.len().max(1);
        let ncols = cols.len();
        let mut data = vec![F::zero(); nrows * ncols];
        for (j, c) in cols.iter().enumerate() {
            for (part, p) in [(false, &c.re), (true, &c.im)] {
                for (e, v) in p.terms() {
                    if let Some(&i) = index.get(&(e.to_vec(), part)) {
                        if let Some(slot) = data.get_mut(i * ncols + j) {
                            *slot = v.clone();
                        }
                    }
                }
            }
        }
        let m = Matrix::from_vec(nrows, ncols, data)
            .map_err(|e| RecognitionError::InvalidInput(e.to_string()))?;
        let ker = m.null_space();
        let Some(sol) = ker.first() else {
            continue;
        };
        let get = |k: usize| sol.get(k).cloned().unwrap_or_else(F::zero);
        let coef = |which_half: usize, j: usize| -> Cx<F> {
            if complex {
                let base = which_half * 2 * (kdeg + 1) + 2 * j;
                Cx {
                    re: get(base),
                    im: get(base + 1),
                }
            } else {
                Cx::real(get(which_half * (kdeg + 1) + j))
            }
        };
        let num: Vec<Cx<F>> = (0..=kdeg).map(|j| coef(0, j)).collect();
        let mut den: Vec<Cx<F>> = (0..=kdeg).map(|j| coef(1, j)).collect();
        while den.len() > 1 && den.last().is_some_and(Cx::is_zero) {
            den.pop();
        }
        let k = den.len() - 1;
        let lead = den[k].clone();
        if lead.is_zero() {
            return Err(RecognitionError::Inconsistent(format!(
                "the support function {which} has the zero denominator"
            )));
        }
        if k == 0 {
            let mut out: Vec<Cx<F>> = num
                .iter()
                .map(|c| c.div(&lead).unwrap_or_else(Cx::zero))
                .collect();
            while out.len() > 1 && out.last().is_some_and(Cx::is_zero) {
                out.pop();
            }
            return Ok(Recovered::Polynomial(out));
        }
        // D = lead (x − ρ)^k ?
        let kk = Cx::real(F::from_i64(k as i64));
        let rho = den[k - 1]
            .neg()
            .div(&kk.mul(&lead))
            .ok_or_else(|| RecognitionError::Inconsistent("zero leading coefficient".into()))?;
        // expand lead (x − ρ)^k
        let mut pw = vec![lead.clone()];
        for _ in 0..k {
            let mut next = vec![Cx::zero(); pw.len() + 1];
            for (i, c) in pw.iter().enumerate() {
                next[i + 1] = next[i + 1].add(c);
                next[i] = next[i].add(&c.mul(&rho.neg()));
            }
            pw = next;
        }
        if pw.iter().zip(&den).all(|(a, b)| {
            let d = a.add(&b.neg());
            d.is_zero() || (!F::EXACT && d.re.to_f64().abs() + d.im.to_f64().abs() < 1e-9)
        }) {
            return Ok(Recovered::Pole(rho));
        }
        // several poles: no Möbius change makes it a polynomial; a rational support
        // function (Support::over) takes it as it is
        return Ok(Recovered::Rational(num, den));
    }
    Err(RecognitionError::UnsupportedSupport {
        which,
        detail: format!("no rational function of degree ≤ {KMAX} in the net parameter fits e(u)ᵀΦ"),
    })
}

/// `Σ sᵢ rᵢ Nᵢ` with the polarity signs `D = diag(1, 1, 1, −1)` (rows complex).
fn polar_dot<F: Scalar>(row: &[CPoly<F>; 4], n: &[MPoly<F>; 4]) -> CPoly<F> {
    let mut acc = CPoly::real(MPoly::zero(2));
    for k in 0..4 {
        let t = cpoly_scale_real(&row[k], &n[k]);
        acc = if k == 3 { acc.sub(&t) } else { acc.add(&t) };
    }
    acc
}

fn real_row<F: Scalar>(p0: &[F; 4], p1: &[F; 4], x: &MPoly<F>, y: &MPoly<F>) -> [CPoly<F>; 4] {
    core::array::from_fn(|k| CPoly::real(&y.scale(&p0[k]) + &x.scale(&p1[k])))
}

/// The support function `num/den` in variable `var` with a real denominator: for complex
/// coefficients `num·d̄en / (den·d̄en)` (`den·d̄en = |den|²` on the real line has real
/// coefficients).
fn support_rational<F: Scalar>(num: &[Cx<F>], den: &[Cx<F>], var: usize) -> Support<F> {
    let conj: Vec<Cx<F>> = den
        .iter()
        .map(|c| Cx {
            re: c.re.clone(),
            im: -c.im.clone(),
        })
        .collect();
    let mul = |a: &[Cx<F>], b: &[Cx<F>]| -> Vec<Cx<F>> {
        let mut out = vec![Cx::zero(); (a.len() + b.len()).saturating_sub(1)];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].add(&x.mul(y));
            }
        }
        out
    };
    let n = support_poly(&mul(num, &conj), var);
    let d = support_poly(&mul(den, &conj), var);
    n.over(d.re)
}

fn support_of<F: Scalar>(r: Recovered<F>, var: usize) -> Option<Support<F>> {
    match r {
        Recovered::Polynomial(c) => Some(support_poly(&c, var)),
        Recovered::Rational(n, d) => Some(support_rational(&n, &d, var)),
        Recovered::Pole(_) => None,
    }
}

fn support_poly<F: Scalar>(coeffs: &[Cx<F>], var: usize) -> Support<F> {
    let re: Vec<F> = coeffs.iter().map(|c| c.re.clone()).collect();
    let im: Vec<F> = coeffs.iter().map(|c| c.im.clone()).collect();
    let r = Support::univariate(&re, var);
    let i = Support::univariate(&im, var);
    Support::complex(r.re, i.re)
}

fn build<F: Scalar>(
    fam: &SphereFamily<F>,
    mut axes: Axes<F>,
    complexes: [[F; 6]; 2],
    h: [MPoly<F>; 6],
    delta: F,
) -> Result<Recognition<F>, RecognitionError> {
    let (n, dphi) = (&fam.num, &fam.den);
    axes = axes.normalized();
    for _attempt in 0..4 {
        let net = axes.net()?;
        let par = parameters_of_line(&net, &h)?;
        let (p, q) = (&par.first, &par.first_den);
        let (r, s) = (&par.second, &par.second_den);
        let (a, b) = match &axes {
            Axes::Hyperbolic { c, d } => {
                let ta = polar_dot(&real_row(&c.0, &c.1, p, q), n);
                let ra =
                    recover_univariate("a", &CPoly::real(p.clone()), q, &ta, &(q * dphi), false)?;
                let tb = polar_dot(&real_row(&d.0, &d.1, r, s), n);
                let rb =
                    recover_univariate("b", &CPoly::real(r.clone()), s, &tb, &(s * dphi), false)?;
                match (ra, rb) {
                    (Recovered::Pole(rho), _) => {
                        axes.move_pole(true, &rho);
                        continue;
                    }
                    (_, Recovered::Pole(rho)) => {
                        axes.move_pole(false, &rho);
                        continue;
                    }
                    (ra, rb) => match (support_of(ra, 0), support_of(rb, 1)) {
                        (Some(a), Some(b)) => (a, b),
                        _ => continue,
                    },
                }
            }
            Axes::Elliptic { c } => {
                // u = m − i n = (Pm Qn − i Pn Qm)/(Qm Qn)
                let x = CPoly {
                    re: p * s,
                    im: -&(r * q),
                };
                let y = q * s;
                let row: [CPoly<F>; 4] = core::array::from_fn(|k| {
                    let c0 = CPoly {
                        re: cst(&c.0[k].re),
                        im: cst(&c.0[k].im),
                    };
                    let c1 = CPoly {
                        re: cst(&c.1[k].re),
                        im: cst(&c.1[k].im),
                    };
                    cpoly_scale_real(&c0, &y).add(&c1.mul(&x))
                });
                let ta = polar_dot(&row, n);
                match recover_univariate("a", &x, &y, &ta, &(&y * dphi), true)? {
                    Recovered::Pole(rho) => {
                        axes.move_pole(true, &rho);
                        continue;
                    }
                    other => {
                        let Some(a) = support_of(other, 0) else {
                            continue;
                        };
                        let b = a.conjugate_in_v();
                        (a, b)
                    }
                }
            }
            Axes::Parabolic { c, n: cplx } => {
                let ta = polar_dot(&real_row(&c.0, &c.1, p, q), n);
                let av = match recover_univariate(
                    "a",
                    &CPoly::real(p.clone()),
                    q,
                    &ta,
                    &(q * dphi),
                    false,
                )? {
                    Recovered::Pole(rho) => {
                        axes.move_pole(true, &rho);
                        continue;
                    }
                    Recovered::Polynomial(a) => a,
                    Recovered::Rational(..) => {
                        return Err(RecognitionError::UnsupportedSupport {
                            which: "a",
                            detail: "a rational support function with several poles on a parabolic net (a_u = b_v ties b to a'; only polynomial a, or a single pole moved to ∞, is recovered)".into(),
                        })
                    }
                };
                let (cr, dr) = parabolic_rows(c, cplx)?;
                // b = fᵀΦ, f = D(d₀ + u d₁ + v c₁); Q S f = D(Q S d₀ + P S d₁ + Q R c₁)
                let qs = q * s;
                let row: [CPoly<F>; 4] = core::array::from_fn(|k| {
                    CPoly::real(
                        &(&qs.scale(&dr.origin[k]) + &(p * s).scale(&dr.direction[k]))
                            + &(q * r).scale(&cr.direction[k]),
                    )
                });
                let tb = polar_dot(&row, n).re;
                let tb_den = &qs * dphi;
                // a'(u) = A1/Q^{deg a − 1}
                let deg = av.len().saturating_sub(1);
                let mut a1 = MPoly::zero(2);
                for (j, cj) in av.iter().enumerate().skip(1) {
                    let t = &p.pow((j - 1) as u32) * &q.pow((deg - j) as u32);
                    a1 = &a1 + &t.scale(&(cj.re.clone() * F::from_i64(j as i64)));
                }
                let a1_den = q.pow(deg.saturating_sub(1) as u32);
                // b₀ = b − v a'(u) = tb/tb_den − R A1/(S a1_den)
                let num0 = &(&tb * &(s * &a1_den)) - &(&(r * &a1) * &tb_den);
                let den0 = &tb_den * &(s * &a1_den);
                let b0 = match recover_univariate(
                    "b",
                    &CPoly::real(p.clone()),
                    q,
                    &CPoly::real(num0),
                    &den0,
                    false,
                )? {
                    Recovered::Polynomial(b0) => b0,
                    Recovered::Pole(rho) => {
                        return Err(RecognitionError::UnsupportedSupport {
                            which: "b",
                            detail: format!(
                                "b − v·a'(u) has a pole at u = {} although a is polynomial",
                                rho.text()
                            ),
                        })
                    }
                    Recovered::Rational(..) => {
                        return Err(RecognitionError::UnsupportedSupport {
                            which: "b",
                            detail: "b − v·a'(u) has several poles although a is polynomial".into(),
                        })
                    }
                };
                let a_s = support_poly(&av, 0);
                // b = v a'(u) + b₀(u)
                let ap = a_s.re.partial(0);
                let b_re = &(&MPoly::var(2, 1) * &ap) + &support_poly(&b0, 0).re;
                (a_s, Support::real(b_re))
            }
        };
        let env = match SphereFamilyEnvelope::new(&net, a, b) {
            Ok(e) => e,
            Err(SphereFamilyError::InconsistentSupport(m)) => {
                return Err(RecognitionError::Inconsistent(m))
            }
            Err(e) => return Err(e.into()),
        };
        let same = same_family_certificates(fam, &env, &par);
        if let Some(bad) = same.iter().find(|c| !c.holds) {
            return Err(RecognitionError::Inconsistent(format!(
                "the solution of (3.7) for the recovered net and support functions is not the given family: {} fails ({})",
                bad.property,
                bad.residual.clone().unwrap_or_default()
            )));
        }
        return Ok(Recognition {
            family: fam.clone(),
            complexes,
            normals: h,
            params: par,
            envelope: env,
            discriminant: delta,
        });
    }
    Err(RecognitionError::UnsupportedSupport {
        which: "a",
        detail: "moving its pole to the parameter ∞ did not give a polynomial".into(),
    })
}

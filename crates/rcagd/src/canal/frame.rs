//! Base-point-free parametrizations on a parameter interval: the choice of the
//! stereographic frame (Gruber §2.1, "rotate coordinates if necessary";
//! docs/math/lines-and-canal.md, "Canal surfaces").
//!
//! The construction of [`super::envelope`] uses the stereographic projection from the pole
//! `e₃` of the sphere of unit normals. Where `c = P₄ + P₃` (in the construction frame)
//! vanishes, the circle of unit normals at `t` passes through the pole, its image is a line,
//! and the parametrization has a **base point**: all four homogeneous coordinates vanish at
//! some `(t₀, u₀)` (a weight-zero point of the Bézier patches; the identities still hold).
//! If `c(t) ≠ 0` on `[a, b]`, then `K₀ = c(u² + 1) ≠ 0` for every real `u` and the leading
//! `u`-coefficient `c ≠ 0`, so `X₀ = W·(K₀² + K₁² + K₂²)/(u² + 1) ≠ 0` on
//! `[a, b] × (R ∪ {∞})` wherever `W ≠ 0`: the patches are free of poles and base points.
//!
//! For a unit direction `e` the frame in which `e` is the pole axis gives
//! `c_e = P₄ + e·(P₁, P₂, P₃)`. [`pole_free_direction`] searches the rational unit vectors
//! of small height (the coordinate axes first) for one with `c_e` free of real roots on
//! `[a, b]` (exact root counting); the frame is the Householder reflection
//! `H = I − 2vvᵀ/(vᵀv)`, `v = e − e₃` ([`householder`]), rational for rational `e`,
//! orthogonal and involutive, with `He = e₃`. The surface built for the family `H·m` is
//! mapped back by `H` ([`super::CanalSurface::transformed`]); the canal identities and the
//! split `g₁² + g₂² = D` are invariant under orthogonal maps, and the certificates are
//! computed for the family as given.
//!
//! Such a direction exists iff the vectors `(Pₘ, P₄)(t)`, `t ∈ [a, b]`, avoid the hyperplane
//! `e·x + x₄ = 0` for one unit `e`; for a closed spine such as a circle (all `t ∈ R`) it does
//! not exist, so closed surfaces are built in pieces (the CLI's `torus` splits the circle
//! into four quarters). When no candidate works, the builders fall back to the plain
//! construction (certified, but possibly with a base point).

use super::envelope::{canal_surface, canal_surface_with_split, CanalBuild, CanalOptions};
use super::envelope::{AxisChoice, CanalSurface, Construction, Method, Orientation};
use super::pipe::pipe_around_ph_parts;
use super::{CanalError, CanalSpine};
use crate::ph::PhCurve;
use rcagd_algebra::roots::count_real_roots_in;
use rcagd_algebra::{Poly, QuadExt, Rational, Scalar};
use rcagd_geom::weight_sign::{split_patches_adaptive, SignRule};

/// The largest height `n` of the candidate directions `(a, b, c)/n`.
const MAX_HEIGHT: i64 = 17;

/// The rational unit vectors `(a, b, c)/n` with `a² + b² + c² = n²`, `n ≤ 17`, all signs and
/// permutations, ordered by `n` (the coordinate axes first).
pub fn candidate_directions() -> Vec<[Rational; 3]> {
    candidate_directions_cached()
        .iter()
        .map(|(e, _)| e.clone())
        .collect()
}

/// [`candidate_directions`] with their `f64` values, computed once per process (a constant
/// list).
fn candidate_directions_cached() -> &'static [([Rational; 3], [f64; 3])] {
    static LIST: std::sync::OnceLock<Vec<([Rational; 3], [f64; 3])>> = std::sync::OnceLock::new();
    LIST.get_or_init(|| {
        candidate_directions_uncached()
            .into_iter()
            .map(|e| {
                let ef = e.clone().map(|x| Scalar::to_f64(&x));
                (e, ef)
            })
            .collect()
    })
}

fn candidate_directions_uncached() -> Vec<[Rational; 3]> {
    let mut out: Vec<[i64; 4]> = Vec::new();
    for n in 1..=MAX_HEIGHT {
        for a in 0..=n {
            for b in a..=n {
                let rest = n * n - a * a - b * b;
                if rest < b * b {
                    continue;
                }
                let c = (rest as f64).sqrt().round() as i64;
                if c * c != rest {
                    continue;
                }
                for perm in [
                    [a, b, c],
                    [a, c, b],
                    [b, a, c],
                    [b, c, a],
                    [c, a, b],
                    [c, b, a],
                ] {
                    for signs in 0..8 {
                        let v: [i64; 4] = [
                            if signs & 1 == 0 { perm[0] } else { -perm[0] },
                            if signs & 2 == 0 { perm[1] } else { -perm[1] },
                            if signs & 4 == 0 { perm[2] } else { -perm[2] },
                            n,
                        ];
                        if !out.contains(&v) {
                            out.push(v);
                        }
                    }
                }
            }
        }
    }
    out.into_iter()
        .map(|v| core::array::from_fn(|k| Rational::from_ratio(v[k], v[3])))
        .collect()
}

/// The Householder reflection `H = I − 2vvᵀ/(vᵀv)`, `v = e − e₃`, with `He = e₃` for a unit
/// vector `e` (`H = I` for `e = e₃`). `H` is orthogonal and `H⁻¹ = H`.
pub fn householder(e: &[Rational; 3]) -> [[Rational; 3]; 3] {
    let v = [e[0].clone(), e[1].clone(), e[2].clone() - Rational::from(1)];
    let vv = v
        .iter()
        .fold(Rational::from(0), |a, x| a + x.clone() * x.clone());
    core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            let id = if i == j {
                Rational::from(1)
            } else {
                Rational::from(0)
            };
            if vv == Rational::from(0) {
                id
            } else {
                id - Rational::from(2) * v[i].clone() * v[j].clone() / vv.clone()
            }
        })
    })
}

/// `c_e = P₄ + e·Pₘ` of a family.
fn c_of(p: &[Poly<Rational>; 4], e: &[Rational; 3]) -> Poly<Rational> {
    (0..3).fold(p[3].clone(), |acc, i| &acc + &p[i].scale(&e[i]))
}

/// A rational unit direction `e` with `P₄ + e·Pₘ` free of real roots on `[a, b]` (module
/// docs); `None` if no candidate works. Among the candidates the best conditioned is
/// chosen: the largest `min |c_e| / |(Pₘ, P₄)|` over 65 sample parameters of `[a, b]` (the
/// pole of the projection as far as possible from the circles of unit normals, so the
/// weights stay away from zero); ties keep the order of [`candidate_directions`]. The
/// choice is verified exactly (no real root of `c_e` on `[a, b]`).
///
/// # Errors
/// As [`CanalSpine::derivative_numerators`]; [`CanalError::InvalidArgument`] for `a > b`.
pub fn pole_free_direction(
    spine: &CanalSpine<Rational>,
    a: &Rational,
    b: &Rational,
) -> Result<Option<[Rational; 3]>, CanalError> {
    Ok(pole_free_directions(spine, a, b, 1)?.into_iter().next())
}

/// Up to `limit` directions as [`pole_free_direction`], best conditioned first, each
/// verified exactly.
///
/// # Errors
/// As [`pole_free_direction`].
pub fn pole_free_directions(
    spine: &CanalSpine<Rational>,
    a: &Rational,
    b: &Rational,
    limit: usize,
) -> Result<Vec<[Rational; 3]>, CanalError> {
    if a > b {
        return Err(CanalError::InvalidArgument(format!(
            "empty parameter interval [{}, {}]",
            crate::error::format_scalar(a),
            crate::error::format_scalar(b)
        )));
    }
    let p = spine.derivative_numerators()?;
    let pf: Vec<Poly<f64>> = p.iter().map(|q| q.map(Scalar::to_f64)).collect();
    let (af, bf) = (Scalar::to_f64(a), Scalar::to_f64(b));
    let samples: Vec<[f64; 4]> = (0..=64)
        .map(|i| {
            let t = af + (bf - af) * f64::from(i) / 64.0;
            let v: [f64; 4] = core::array::from_fn(|k| pf[k].eval(&t));
            let n = v
                .iter()
                .map(|x| x * x)
                .sum::<f64>()
                .sqrt()
                .max(f64::MIN_POSITIVE);
            v.map(|x| x / n)
        })
        .collect();
    let mut scored: Vec<(f64, [Rational; 3])> = Vec::new();
    for (e, ef) in candidate_directions_cached() {
        let (e, ef) = (e.clone(), *ef);
        let mut lo = f64::INFINITY;
        let mut sign = 0.0f64;
        let mut ok = true;
        for v in &samples {
            let c = v[3] + ef[0] * v[0] + ef[1] * v[1] + ef[2] * v[2];
            if sign == 0.0 {
                sign = c.signum();
            }
            if c * sign <= 0.0 {
                ok = false;
                break;
            }
            lo = lo.min(c.abs());
        }
        if ok {
            scored.push((lo, e));
        }
    }
    scored.sort_by(|x, y| y.0.total_cmp(&x.0));
    let mut out = Vec::new();
    for (_, e) in scored {
        if out.len() >= limit {
            break;
        }
        let c = c_of(&p, &e);
        if !c.is_zero() && count_real_roots_in(&c, a, b)? == 0 {
            out.push(e);
        }
    }
    Ok(out)
}

pub(crate) fn transform_spine<F: Scalar>(spine: &CanalSpine<F>, q: &[[F; 3]; 3]) -> CanalSpine<F> {
    let m = spine.center_polys();
    let mq: [Poly<F>; 3] =
        core::array::from_fn(|i| (0..3).fold(Poly::zero(), |acc, j| &acc + &m[j].scale(&q[i][j])));
    // W ≢ 0 is preserved
    CanalSpine::new(spine.weight().clone(), mq, spine.radius_poly().clone())
        .unwrap_or_else(|_| spine.clone())
}

pub(crate) fn coordinate_axis(e: &[Rational; 3]) -> Option<AxisChoice> {
    let zero = Rational::from(0);
    let nz: Vec<usize> = (0..3).filter(|&i| e[i] != zero).collect();
    match nz.as_slice() {
        [j] => Some(AxisChoice {
            axis: *j,
            positive: e[*j] > zero,
        }),
        _ => None,
    }
}

pub(crate) fn oriented(spine: &CanalSpine<Rational>, o: Orientation) -> CanalSpine<Rational> {
    match o {
        Orientation::Positive => spine.clone(),
        Orientation::Negative => spine.reversed(),
    }
}

/// [`canal_surface`] on the domain of `options` (required) in a frame where the
/// parametrization has no base point on the domain (module docs); if the family needs the
/// reparametrization of the domain, `W` vanishes on it, the axis is fixed by `options`, or no
/// direction is found, this is [`canal_surface`] itself.
///
/// With [`Method::Lowest`] both constructions are built and the one that exports smaller
/// is kept: the domain patches ([`CanalSurface::domain_patches`]) are split into pieces with
/// positive Bernstein weights (`rcagd_geom::weight_sign`, at most [`EXPORT_SPLITS`]
/// bisections, as the recipe ops export them) and the build with fewer control points after splitting
/// wins (on a tie, the lower bidegree). A Krasauskas build (Gruber §2.4) often has the
/// lower bidegree but a weight `W·|a + u b|²` that varies more on the domain.
///
/// # Errors
/// As [`canal_surface`]; [`CanalError::InvalidArgument`] without a domain.
pub fn canal_surface_pole_free(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
) -> Result<CanalBuild, CanalError> {
    let built = pole_free_any(spine, options)?;
    let is_krasauskas = |b: &CanalBuild| {
        matches!(
            b,
            CanalBuild::Rational(s) if matches!(s.construction(), Construction::Krasauskas { .. })
        )
    };
    if options.method != Method::Lowest || !is_krasauskas(&built) {
        return Ok(built);
    }
    let opts = CanalOptions {
        method: Method::PeternellPottmann,
        ..options.clone()
    };
    let Ok(pp) = pole_free_any(spine, &opts) else {
        return Ok(built);
    };
    match (export_size(&built), export_size(&pp)) {
        (Some(k), Some(p)) if (k, built.degree()) <= (p, pp.degree()) => Ok(built),
        (Some(_), None) => Ok(built),
        _ => Ok(pp),
    }
}

/// The most bisections in `v` (the circle direction) and in `u` (the spine direction) when a
/// canal surface's domain patches are split into pieces with positive weights for export
/// (the recipe ops use the same limit).
pub const EXPORT_SPLITS: (usize, usize) = (4, 4);

/// The number of control points of the domain patches after splitting them into pieces
/// with positive weights (`None` if that fails within [`EXPORT_SPLITS`]).
fn export_size(b: &CanalBuild) -> Option<usize> {
    let CanalBuild::Rational(s) = b else {
        return None;
    };
    let patches = s.domain_patches().ok()?;
    let split = split_patches_adaptive(patches, SignRule::Positive, EXPORT_SPLITS).ok()?;
    if split.failed > 0 {
        return None;
    }
    Some(
        split
            .pieces
            .iter()
            .map(|p| (p.degree().0 + 1) * (p.degree().1 + 1))
            .sum(),
    )
}

fn pole_free_any(
    spine: &CanalSpine<Rational>,
    options: &CanalOptions,
) -> Result<CanalBuild, CanalError> {
    let (a, b) = options.domain.clone().ok_or_else(|| {
        CanalError::InvalidArgument("a base-point-free build needs a parameter domain".into())
    })?;
    let so = oriented(spine, options.orientation);
    so.check_real_envelope(Some((&a, &b)))?;
    let plain = options.axis.is_some()
        || so.check_real_envelope(None).is_err()
        || count_real_roots_in(so.weight(), &a, &b)? > 0;
    if plain {
        return canal_surface(spine, options);
    }
    let Some(e) = pole_free_direction(&so, &a, &b)? else {
        return canal_surface(spine, options);
    };
    if let Some(axis) = coordinate_axis(&e) {
        let opts = CanalOptions {
            axis: Some(axis),
            ..options.clone()
        };
        return canal_surface(spine, &opts);
    }
    let h = householder(&e);
    let opts = CanalOptions {
        axis: Some(AxisChoice {
            axis: 2,
            positive: true,
        }),
        ..options.clone()
    };
    let built = canal_surface(&transform_spine(spine, &h), &opts)?;
    Ok(match built {
        CanalBuild::Rational(s) => CanalBuild::Rational(s.transformed(&h, &so)?),
        CanalBuild::Extension { radicand, surface } => {
            let he = h.clone().map(|r| r.map(QuadExt::rational));
            let se = so.map_scalar(|x| QuadExt::rational(x.clone()));
            CanalBuild::Extension {
                radicand,
                surface: surface.transformed(&he, &se)?,
            }
        }
    })
}

/// The pipe of radius `r` around a PH curve (split `(σ, 0)`, no factorization, exact) on
/// `t ∈ [a, b]` in a frame without base points there (module docs); the plain
/// [`super::pipe_around_ph`] if no direction is found.
///
/// # Errors
/// As [`super::pipe_around_ph`]; [`CanalError::InvalidArgument`] for `a > b`.
pub fn pipe_around_ph_pole_free(
    curve: &PhCurve<Rational>,
    radius: &Rational,
    domain: (&Rational, &Rational),
    orientation: Orientation,
) -> Result<CanalSurface<Rational>, CanalError> {
    let position = curve.position();
    let sigma = curve.speed();
    let spine = CanalSpine::polynomial(position.clone(), Poly::constant(radius.clone()));
    let so = oriented(&spine, orientation);
    let options = CanalOptions {
        orientation,
        ..CanalOptions::default()
    };
    let e = if radius.is_zero() {
        None
    } else {
        pole_free_direction(&so, domain.0, domain.1)?
    };
    let Some(e) = e else {
        return pipe_around_ph_parts(&position, &sigma, radius, &options);
    };
    if let Some(axis) = coordinate_axis(&e) {
        let opts = CanalOptions {
            axis: Some(axis),
            ..options
        };
        return pipe_around_ph_parts(&position, &sigma, radius, &opts);
    }
    let h = householder(&e);
    let ph: [Poly<Rational>; 3] = core::array::from_fn(|i| {
        (0..3).fold(Poly::zero(), |acc, j| &acc + &position[j].scale(&h[i][j]))
    });
    let opts = CanalOptions {
        axis: Some(AxisChoice {
            axis: 2,
            positive: true,
        }),
        ..options
    };
    let s = pipe_around_ph_parts(&ph, &sigma, radius, &opts)?;
    s.transformed(&h, &so)
}

/// [`canal_surface_with_split`] in the frame of direction `e` (module docs): the split is
/// frame-invariant.
///
/// # Errors
/// As [`canal_surface_with_split`].
pub fn canal_surface_with_split_in_frame(
    spine: &CanalSpine<Rational>,
    g1: &Poly<Rational>,
    g2: &Poly<Rational>,
    e: &[Rational; 3],
    orientation: Orientation,
) -> Result<CanalSurface<Rational>, CanalError> {
    let h = householder(e);
    let opts = CanalOptions {
        orientation,
        axis: Some(AxisChoice {
            axis: 2,
            positive: true,
        }),
        ..CanalOptions::default()
    };
    let s = canal_surface_with_split(&transform_spine(spine, &h), g1, g2, &opts)?;
    s.transformed(&h, &oriented(spine, orientation))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Certified;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn householder_is_an_involution_mapping_e_to_e3() {
        for e in candidate_directions().into_iter().take(200) {
            let h = householder(&e);
            let he: Vec<Rational> = (0..3)
                .map(|i| (0..3).fold(q(0), |a, j| a + h[i][j].clone() * e[j].clone()))
                .collect();
            assert_eq!(he, vec![q(0), q(0), q(1)]);
            for i in 0..3 {
                for j in 0..3 {
                    let hh = (0..3).fold(q(0), |a, k| a + h[i][k].clone() * h[k][j].clone());
                    assert_eq!(hh, if i == j { q(1) } else { q(0) });
                }
            }
        }
    }

    #[test]
    fn quarter_circle_pipe_has_no_base_point() {
        // the circle (1 − t², 2t, 0)/(1 + t²) on [0, 1]: every coordinate axis has c = 0
        // somewhere on [0, 1] (c ∝ t, 1 − t² or ≡ 0), a tilted direction does not
        let w = Poly::from_ints(&[1, 0, 1]);
        let spine = CanalSpine::new(
            w.clone(),
            [
                Poly::from_ints(&[1, 0, -1]),
                Poly::from_ints(&[0, 2]),
                Poly::zero(),
            ],
            w.scale(&Rational::from_ratio(1, 4)),
        )
        .expect("family");
        let (a, b) = (q(0), q(1));
        let e = pole_free_direction(&spine, &a, &b)
            .expect("ok")
            .expect("direction");
        assert!(coordinate_axis(&e).is_none(), "{e:?}");
        let opts = CanalOptions {
            domain: Some((a.clone(), b.clone())),
            ..CanalOptions::default()
        };
        let build = canal_surface_pole_free(&spine, &opts).expect("build");
        let s = build.as_rational().expect("rational");
        assert!(s.all_hold(), "{:?}", s.certify());
        // X₀ > 0 on a grid of [0, 1] × R (incl. u = ∞)
        for i in 0..=8 {
            let t = Rational::from_ratio(i, 8);
            for j in -8..=8 {
                let u = Rational::from_ratio(j, 2);
                assert!(s.eval_homogeneous(&t, &u)[0] != q(0));
            }
            assert!(s.eval_at_u_infinity(&t)[0] != q(0));
        }
        // the plain construction has a base point on [0, 1] for this family
        let plain = canal_surface(&spine, &opts).expect("plain");
        let p = plain.as_rational().expect("rational");
        let pn = p.spine().derivative_numerators().expect("P");
        let ax = p.axis();
        let c = if ax.positive {
            &pn[3] + &pn[ax.axis]
        } else {
            &pn[3] - &pn[ax.axis]
        };
        assert!(count_real_roots_in(&c, &a, &b).expect("roots") > 0);
    }
}

//! The one op module that names polynomial types: reading coefficient lists into
//! polynomials (parsing) and writing library polynomials as report values (wrapping).
//!
//! Every other file under `ops/` reads its parameters, calls one library function and wraps
//! the result; it neither builds a polynomial nor computes with one (docs/ARCHITECTURE.md,
//! "Library first"; enforced by the CLI test `it::library_first`). The converters here
//! only place coefficients: no sums of products, no evaluation, no change of basis.

use super::OpError;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::rational::format_rational;
use rcagd_algebra::{Poly, QuadExt, Rational};
use rcagd_geom::BezierCurve;
use rcagd_io::ndim::NdimMap;
use rcagd_io::quantity::{NamedQuantity, Quantity};

type Q = Rational;

pub use rcagd_algebra::roots::RootInterval;

/// A polynomial in `t` over `Q` (for signatures of op helpers that pass one on).
pub type PolyT = Poly<Q>;

/// A multivariate polynomial over `Q`.
pub type MPolyQ = MPoly<Q>;

/// A polynomial in the scalar `T` of a generic op builder ([`super::arith::OpScalar`]).
pub type MPolyIn<T> = MPoly<T>;

/// An exact polynomial of the recipe in `T` (the identity's values for `Rational`, the
/// nearest `f64`s for the float path).
pub fn mpoly_in<T: rcagd_algebra::Scalar>(p: &MPolyQ) -> MPolyIn<T> {
    p.map(T::from_rational)
}

/// An exact univariate polynomial of the recipe in `T` (as [`mpoly_in`]).
pub fn poly_in<T: rcagd_algebra::Scalar>(p: &Poly<Q>) -> Poly<T> {
    p.map(T::from_rational)
}

/// A computed polynomial of `T` as an exact value (an `f64` one: the exact binary values of
/// its coefficients; a non-finite coefficient is an error, as for control points).
pub fn poly_exact<T: rcagd_algebra::Scalar>(p: &Poly<T>) -> Result<Poly<Q>, OpError> {
    let c: Option<Vec<Q>> = p
        .coeffs()
        .iter()
        .map(rcagd_algebra::Scalar::to_rational)
        .collect();
    c.map(Poly::new).ok_or_else(|| {
        OpError::new("the f64 construction produced a non-finite coefficient (overflow or an ill-conditioned input); build it without --float")
    })
}

/// A `4×4` matrix of polynomials in `t` over `Q`.
pub type PolyMatrix4 = [[Poly<Q>; 4]; 4];

// ---------------------------------------------------------------- reading (parsing)

/// `Σ c[k] tᵏ` from power coefficients.
pub fn poly(coeffs: Vec<Q>) -> Poly<Q> {
    Poly::new(coeffs)
}

/// The constant polynomial `1`.
pub fn poly_one() -> Poly<Q> {
    Poly::constant(Q::from(1))
}

/// Coordinate `k` of a list of power-coefficient points: `Σ points[j][k] tʲ`. The caller
/// has checked that every point has more than `k` entries.
pub fn coordinate_poly(points: &[Vec<Q>], k: usize) -> Poly<Q> {
    Poly::new(points.iter().map(|p| p[k].clone()).collect())
}

/// The `N` coordinate polynomials of a list of power-coefficient points (each point has
/// `N` entries, checked by the caller).
pub fn coordinate_polys<const N: usize>(points: &[Vec<Q>]) -> [Poly<Q>; N] {
    core::array::from_fn(|k| coordinate_poly(points, k))
}

/// One polynomial in `t` per row of power coefficients.
pub fn polys(rows: &[Vec<Q>]) -> Vec<Poly<Q>> {
    rows.iter().map(|r| Poly::new(r.clone())).collect()
}

/// `N` polynomials in `t` from `N` rows of power coefficients (the caller has checked that
/// there are `N` rows).
pub fn polys_array<const N: usize>(rows: &[Vec<Q>]) -> [Poly<Q>; N] {
    core::array::from_fn(|i| Poly::new(rows[i].clone()))
}

/// A matrix of polynomials in `t` from a net of power-coefficient lists (`net[i][j]` the
/// coefficients of entry `(i, j)`).
pub fn poly_rows(net: &[Vec<Vec<Q>>]) -> Vec<Vec<Poly<Q>>> {
    net.iter()
        .map(|r| r.iter().map(|c| Poly::new(c.clone())).collect())
        .collect()
}

/// A `4×4` matrix of polynomials from a net of coefficient lists.
///
/// # Errors
/// [`OpError::param`] at `param` unless the net has 4 rows of 4 entries.
pub fn poly_matrix4(
    net: &[Vec<Vec<Q>>],
    param: &'static str,
) -> Result<[[Poly<Q>; 4]; 4], OpError> {
    if net.len() != 4 || net.iter().any(|r| r.len() != 4) {
        return Err(OpError::param(param, "needs 4 rows of 4 entries"));
    }
    Ok(core::array::from_fn(|i| {
        core::array::from_fn(|j| Poly::new(net[i][j].clone()))
    }))
}

/// The space coordinates `[x, y, z]` (power basis) of the homogeneous coordinate
/// polynomials `[w, x, y, z]` of a polynomial Bézier curve, as given.
///
/// # Errors
/// [`OpError`] if the curve does not lie in space.
pub fn space_polys(bez: &BezierCurve<Q>) -> Result<[Poly<Q>; 3], OpError> {
    let [_, x, y, z] = <[Poly<Q>; 4]>::try_from(bez.coordinate_polys())
        .map_err(|_| OpError::new("the curve must lie in space (x, y, z)"))?;
    Ok([x, y, z])
}

fn exp(k: usize) -> Result<u32, OpError> {
    u32::try_from(k).map_err(|_| OpError::new("a polynomial degree is too large"))
}

/// `Σ g[i][j] uⁱ vʲ` (two variables).
///
/// # Errors
/// [`OpError`] if a degree does not fit a `u32`.
pub fn grid_mpoly(grid: &[Vec<Q>]) -> Result<MPoly<Q>, OpError> {
    let mut terms = Vec::new();
    for (i, row) in grid.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            terms.push((vec![exp(i)?, exp(j)?], c.clone()));
        }
    }
    MPoly::from_terms(2, terms).map_err(|e| OpError::new(e.to_string()))
}

/// `Σ c[k] tᵏ` as a polynomial in the first of `nvars` variables.
///
/// # Errors
/// [`OpError`] if a degree does not fit a `u32`.
pub fn list_mpoly(list: &[Q], nvars: usize) -> Result<MPoly<Q>, OpError> {
    let mut terms = Vec::new();
    for (k, c) in list.iter().enumerate() {
        let mut e = vec![0; nvars.max(1)];
        e[0] = exp(k)?;
        terms.push((e, c.clone()));
    }
    MPoly::from_terms(nvars.max(1), terms).map_err(|e| OpError::new(e.to_string()))
}

/// One polynomial in `t` (one variable) per row of power coefficients.
///
/// # Errors
/// As [`list_mpoly`].
pub fn list_mpolys(rows: &[Vec<Q>]) -> Result<Vec<MPoly<Q>>, OpError> {
    rows.iter().map(|r| list_mpoly(r, 1)).collect()
}

/// The constant `c` in `nvars` variables.
pub fn mpoly_constant(nvars: usize, c: Q) -> MPoly<Q> {
    MPoly::constant(nvars, c)
}

/// The variable `xᵢ` of `nvars` variables.
pub fn mpoly_var(nvars: usize, i: usize) -> MPoly<Q> {
    MPoly::var(nvars, i)
}

/// `Σ net[i][j] uⁱ vʲ` per homogeneous coordinate of a net of 4-vectors (checked by the
/// caller).
///
/// # Errors
/// As [`grid_mpoly`].
pub fn net_mpolys4(net: &[Vec<[Q; 4]>]) -> Result<[MPoly<Q>; 4], OpError> {
    let coord = |k: usize| -> Result<MPoly<Q>, OpError> {
        let grid: Vec<Vec<Q>> = net
            .iter()
            .map(|row| row.iter().map(|p| p[k].clone()).collect())
            .collect();
        grid_mpoly(&grid)
    };
    Ok([coord(0)?, coord(1)?, coord(2)?, coord(3)?])
}

/// `Σ c·u^e` from terms `[c, e₁, …, e_nvars]`.
///
/// # Errors
/// [`OpError::param`] at `param` if a term has the wrong length or an exponent is not a
/// non-negative integer.
pub fn terms_mpoly(
    rows: &[Vec<Q>],
    nvars: usize,
    param: &'static str,
) -> Result<MPoly<Q>, OpError> {
    let mut terms = Vec::with_capacity(rows.len());
    for r in rows {
        if r.len() != nvars + 1 {
            return Err(OpError::param(
                param,
                format!(
                    "each term is [c, e₁, …, e_{nvars}] ({} entries), got {}",
                    nvars + 1,
                    r.len()
                ),
            ));
        }
        let e: Vec<u32> = r[1..]
            .iter()
            .map(|x| x.to_string().parse::<u32>())
            .collect::<Result<_, _>>()
            .map_err(|_| OpError::param(param, "exponents must be non-negative integers"))?;
        terms.push((e, r[0].clone()));
    }
    MPoly::from_terms(nvars, terms).map_err(|e| OpError::param(param, e.to_string()))
}

/// `count` polynomials from indexed terms `(i, [c, e₁, …, e_nvars])` (term added to
/// polynomial `i < count`, checked by the caller).
///
/// # Errors
/// As [`terms_mpoly`].
pub fn indexed_terms_mpolys(
    terms: &[(usize, Vec<Q>)],
    count: usize,
    nvars: usize,
    param: &'static str,
) -> Result<Vec<MPoly<Q>>, OpError> {
    // the first malformed term (in the given order) is the one named
    for (_, r) in terms {
        terms_mpoly(core::slice::from_ref(r), nvars, param)?;
    }
    (0..count)
        .map(|i| {
            let rows: Vec<Vec<Q>> = terms
                .iter()
                .filter(|(j, _)| *j == i)
                .map(|(_, r)| r.clone())
                .collect();
            terms_mpoly(&rows, nvars, param)
        })
        .collect()
}

// ---------------------------------------------------------------- writing (wrapping)

/// A list of polynomials in `t` as a vector value.
pub fn polys_value(name: &str, doc: &str, v: &[Poly<Q>]) -> NamedQuantity {
    NamedQuantity::new(
        name,
        doc,
        Quantity::Vector(v.iter().cloned().map(Quantity::poly_t).collect()),
    )
}

/// Polynomials over `Q(√d)` as a vector value: each as `[a(t), b(t)]` with `a + b·√d`.
pub fn quad_polys_parts_value(name: &str, doc: &str, v: &[Poly<QuadExt>]) -> NamedQuantity {
    let part = |x: &Poly<QuadExt>, b: bool| {
        Poly::new(
            x.coeffs()
                .iter()
                .map(|c| if b { c.b().clone() } else { c.a().clone() })
                .collect(),
        )
    };
    NamedQuantity::new(
        name,
        doc,
        Quantity::Vector(
            v.iter()
                .map(|x| {
                    Quantity::Vector(vec![
                        Quantity::poly_t(part(x, false)),
                        Quantity::poly_t(part(x, true)),
                    ])
                })
                .collect(),
        ),
    )
}

/// A polynomial over `Q(√d)` as a value: a rational polynomial in `var` when it is one,
/// else the vector of its power coefficients.
pub fn quad_poly_value(p: &Poly<QuadExt>, var: &str) -> Quantity {
    if p.coeffs().iter().all(|c| c.b().is_zero()) {
        Quantity::Polynomial {
            variable: var.into(),
            poly: p.map(|c| c.a().clone()),
        }
    } else {
        Quantity::Vector(
            p.coeffs()
                .iter()
                .cloned()
                .map(Quantity::Quadratic)
                .collect(),
        )
    }
}

/// The polynomial over `Q` of a polynomial over `Q(√d)` whose coefficients are rational.
pub fn rational_poly(p: &Poly<QuadExt>) -> Option<Poly<Q>> {
    p.coeffs()
        .iter()
        .map(QuadExt::to_rational)
        .collect::<Option<Vec<Q>>>()
        .map(Poly::new)
}

/// `c·y1^a·y2^b + …` (highest exponents first; [`MPoly::format_with`]).
pub fn format_mpoly(p: &MPoly<Q>) -> String {
    p.format_with(|i| format!("y{}", i + 1), "·", |c, _| format_rational(c))
        .replace("+ -", "− ")
}

/// The exact homogeneous map of an n-dimensional object as a value.
///
/// # Errors
/// [`OpError`] if the names do not fit the coordinates.
pub fn map_value(
    names: Vec<String>,
    coords: &[MPoly<Q>],
    what: &str,
) -> Result<NamedQuantity, OpError> {
    let map = NdimMap::new(names, coords.to_vec()).map_err(|e| OpError::new(e.to_string()))?;
    Ok(NamedQuantity::new(
        "homogeneous_map",
        format!("{what}: exact homogeneous coordinates (X₀, X₁, …, Xₙ), each a list of terms [c, e₁, …] of c·∏ parameterᵢ^eᵢ"),
        map.quantity(),
    ))
}

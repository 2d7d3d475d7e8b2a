//! The arithmetic an op builder runs in: one builder per op, generic over the scalar.
//!
//! Every construction of the library is generic over [`rcagd_algebra::Scalar`]; so are
//! the op builders that have a float path (`rcagd build --float`, [`crate::float`]). A
//! builder `fn build_x<T: OpScalar>(args: &OpArgs)` reads the exact parameters, converts
//! them with [`Scalar::from_rational`] (the identity for `Rational`, the nearest `f64`
//! otherwise), runs the construction in `T`, and hands its geometry back through this
//! trait: the exact registry ([`super::OpSpec::build`]) instantiates it with
//! `T = Rational`, the float registry ([`crate::float::FLOAT_OPS`]) with `T = f64`, or
//! with `T = DoubleDouble` for the ops whose `f64` construction cancels digits (its
//! results rounded once to `f64`).
//!
//! What differs between the two arithmetics is said here, once:
//! * the geometry of an object is exact; an `f64` result is stored as the *exact binary
//!   values* of its floats (nothing is rounded a second time), an exact one as it is;
//! * an `f64` object is marked `arithmetic = "f64"` ([`crate::float::mark`]);
//! * a user's weights of mixed sign are decided exactly (exact real-root isolation or
//!   bisection, [`rcagd_geom::weight_sign`]) and refused in `f64`.

use super::{OpArgs, OpError};
use crate::model::{Geometry, Object};
use rcagd_algebra::{Certificate, DoubleDouble, Rational, Scalar};
use rcagd_geom::weight_sign::{curve_has_one_sign, patch_has_one_sign, WeightZero};
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::quantity::Quantity;

/// A scalar an op builder can run in: `Rational` (the exact ops) or `f64` (the float
/// path).
pub trait OpScalar: Scalar + 'static {
    /// The curve with exact control points.
    fn exact_curve(c: BezierCurve<Self>) -> Result<BezierCurve<Rational>, OpError>;
    /// The patch with exact control points.
    fn exact_patch(p: BezierPatch<Self>) -> Result<BezierPatch<Rational>, OpError>;
    /// The object as this arithmetic reports it (an `f64` one is marked).
    fn finish(o: Object) -> Object;
    /// A computed number as a value of an object.
    fn quantity(x: Self) -> Quantity;
    /// The certificate that a user's curve has no pole on `[0, 1]`; `Err(Some(zeros))`:
    /// the weight function vanishes there (exact), `Err(None)`: weights of mixed sign,
    /// not decided (`f64`).
    fn curve_pole_free(c: &BezierCurve<Self>) -> Result<Certificate, Option<WeightZero>>;
    /// The certificate that a user's patch has no pole on `[0, 1]²`, `None` if not
    /// decided (exact: bisection, [`rcagd_geom::weight_sign::patch_pole_free`]; `f64`:
    /// weights of one sign only).
    fn patch_pole_free(p: &BezierPatch<Self>) -> Option<Certificate>;
}

impl OpScalar for Rational {
    fn exact_curve(c: BezierCurve<Self>) -> Result<BezierCurve<Rational>, OpError> {
        Ok(c)
    }
    fn exact_patch(p: BezierPatch<Self>) -> Result<BezierPatch<Rational>, OpError> {
        Ok(p)
    }
    fn finish(o: Object) -> Object {
        o
    }
    fn quantity(x: Self) -> Quantity {
        Quantity::Rational(x)
    }
    fn curve_pole_free(c: &BezierCurve<Self>) -> Result<Certificate, Option<WeightZero>> {
        rcagd_geom::weight_sign::curve_pole_free(c).map_err(Some)
    }
    fn patch_pole_free(p: &BezierPatch<Self>) -> Option<Certificate> {
        rcagd_geom::weight_sign::patch_pole_free(p)
    }
}

impl OpScalar for f64 {
    fn exact_curve(c: BezierCurve<Self>) -> Result<BezierCurve<Rational>, OpError> {
        crate::float::exact_curve(&c)
    }
    fn exact_patch(p: BezierPatch<Self>) -> Result<BezierPatch<Rational>, OpError> {
        crate::float::exact_patch(&p)
    }
    fn finish(o: Object) -> Object {
        crate::float::mark(o)
    }
    fn quantity(x: Self) -> Quantity {
        Quantity::Approx(x)
    }
    fn curve_pole_free(c: &BezierCurve<Self>) -> Result<Certificate, Option<WeightZero>> {
        inexact_curve_pole_free(c)
    }
    fn patch_pole_free(p: &BezierPatch<Self>) -> Option<Certificate> {
        inexact_patch_pole_free(p)
    }
}

/// Double-double (`hi + lo`, about 106 bits; [`DoubleDouble`]): the float path of the ops
/// whose `f64` constructions lose digits to cancellation (docs/plans/float.md, "Session 18,
/// ddfloat"). The construction, its decisions by tolerance and its certificates (inexact,
/// checked in double-double) run in `DoubleDouble`; the curves and patches are rounded once
/// to `f64` at the end (each control point to its leading part) and stored as the exact
/// binary values of those `f64`s, as for `f64`; the object is marked `arithmetic = "f64"`
/// (its geometry is `f64` numbers).
impl OpScalar for DoubleDouble {
    fn exact_curve(c: BezierCurve<Self>) -> Result<BezierCurve<Rational>, OpError> {
        crate::float::rounded_curve(&c)
    }
    fn exact_patch(p: BezierPatch<Self>) -> Result<BezierPatch<Rational>, OpError> {
        crate::float::rounded_patch(&p)
    }
    fn finish(o: Object) -> Object {
        crate::float::mark(o)
    }
    fn quantity(x: Self) -> Quantity {
        Quantity::Approx(x.to_f64())
    }
    fn curve_pole_free(c: &BezierCurve<Self>) -> Result<Certificate, Option<WeightZero>> {
        inexact_curve_pole_free(c)
    }
    fn patch_pole_free(p: &BezierPatch<Self>) -> Option<Certificate> {
        inexact_patch_pole_free(p)
    }
}

/// The pole certificate of an inexact arithmetic (`f64`, double-double): weights of one
/// sign only; `Err(None)` for mixed signs (not decided).
fn inexact_curve_pole_free<T: Scalar>(
    c: &BezierCurve<T>,
) -> Result<Certificate, Option<WeightZero>> {
    if curve_has_one_sign(c) {
        Ok(Certificate::holds(
            "the weights wᵢ all have one sign (Σ wᵢ Bᵢ ≠ 0 on [0, 1]: no pole)",
            false,
        ))
    } else {
        Err(None)
    }
}

/// [`inexact_curve_pole_free`] for a patch (`None`: mixed signs, not decided).
fn inexact_patch_pole_free<T: Scalar>(p: &BezierPatch<T>) -> Option<Certificate> {
    patch_has_one_sign(p).then(|| {
        Certificate::holds(
            "the weights wᵢⱼ all have one sign (Σ wᵢⱼ Bᵢ Bⱼ ≠ 0 on [0, 1]²: no pole)",
            false,
        )
    })
}

/// The message for a user's weights of mixed sign that `f64` does not decide.
pub const MIXED_SIGNS_IN_F64: &str = "weights of mixed sign: the float path does not decide whether the weight function has a zero; build without --float";

/// The object of an op built in `T` (as [`OpArgs::object`], marked if `f64`).
pub fn object<T: OpScalar>(args: &OpArgs, geometry: Geometry, certs: Vec<Certificate>) -> Object {
    T::finish(args.object(geometry, certs))
}

/// [`object`] with the op's computed values (after the `f64` mark, if any).
pub fn object_with<T: OpScalar>(
    args: &OpArgs,
    geometry: Geometry,
    certs: Vec<Certificate>,
    values: Vec<rcagd_io::quantity::NamedQuantity>,
) -> Object {
    T::finish(args.object(geometry, certs).with_values(values))
}

/// `Curve` for one curve, `Curves` for several, with exact control points.
pub fn curves<T: OpScalar>(cs: Vec<BezierCurve<T>>) -> Result<Geometry, OpError> {
    let mut v = cs
        .into_iter()
        .map(T::exact_curve)
        .collect::<Result<Vec<_>, _>>()?;
    Ok(if v.len() == 1 {
        Geometry::Curve(v.remove(0))
    } else {
        Geometry::Curves(v)
    })
}

/// `Patch` for one patch, `Patches` for several, with exact control points.
pub fn patches<T: OpScalar>(ps: Vec<BezierPatch<T>>) -> Result<Geometry, OpError> {
    let mut v = exact_patches(ps)?;
    Ok(if v.len() == 1 {
        Geometry::Patch(v.remove(0))
    } else {
        Geometry::Patches(v)
    })
}

/// The patches with exact control points.
pub fn exact_patches<T: OpScalar>(
    ps: Vec<BezierPatch<T>>,
) -> Result<Vec<BezierPatch<Rational>>, OpError> {
    ps.into_iter().map(T::exact_patch).collect()
}

/// The curves with exact control points.
pub fn exact_curves<T: OpScalar>(
    cs: Vec<BezierCurve<T>>,
) -> Result<Vec<BezierCurve<Rational>>, OpError> {
    cs.into_iter().map(T::exact_curve).collect()
}

/// An exact number in `T`.
pub fn of<T: Scalar>(q: &Rational) -> T {
    T::from_rational(q)
}

/// Exact numbers in `T`.
pub fn all_of<T: Scalar>(v: &[Rational]) -> Vec<T> {
    v.iter().map(T::from_rational).collect()
}

/// A number parameter in `T`.
pub fn number<T: Scalar>(args: &OpArgs, param: &str) -> Result<T, OpError> {
    Ok(of(&args.number(param)?))
}

/// A point parameter of `N` coordinates in `T` (`what` names the expected form in the
/// error message).
pub fn point<T: Scalar, const N: usize>(
    args: &OpArgs,
    param: &'static str,
    what: &str,
) -> Result<[T; N], OpError> {
    let p = args.point(param)?;
    array(&p, param, what)
}

/// Exact numbers as an array of `N` values in `T`.
pub fn array<T: Scalar, const N: usize>(
    v: &[Rational],
    param: &'static str,
    what: &str,
) -> Result<[T; N], OpError> {
    <[T; N]>::try_from(all_of::<T>(v)).map_err(|_| OpError::param(param, what.to_string()))
}

/// `a` as a `B` if `A` and `B` are the same type (`Err(a)` otherwise): lets a generic
/// builder keep an exact intermediate result (`T = Rational`) as it is, and convert it
/// only for another scalar.
pub fn same<A: 'static, B: 'static>(a: A) -> Result<B, A> {
    let any: Box<dyn core::any::Any> = Box::new(a);
    match any.downcast::<B>() {
        Ok(b) => Ok(*b),
        Err(any) => match any.downcast::<A>() {
            Ok(a) => Err(*a),
            // unreachable: `any` was built from an `A`
            Err(_) => unreachable!("a boxed A is an A"),
        },
    }
}

/// `a` as a `&B` if `A` and `B` are the same type (see [`same`]).
pub fn same_ref<A: 'static, B: 'static>(a: &A) -> Option<&B> {
    (a as &dyn core::any::Any).downcast_ref::<B>()
}

//! Named exact values that an op returns besides its geometry: the answers to
//! questions ("is this curve PH?", "what is its arc length?", "which axis?").
//!
//! A [`Quantity`] is exact wherever the mathematics is: a rational, an element
//! `a + b√d` of a quadratic field, a polynomial (with its Bernstein coefficients on
//! `[0, 1]`), a real algebraic number given by a polynomial and an isolating interval,
//! and vectors of those. Every kind carries its `f64` value beside the exact one in JSON
//! (module [`crate::json`]: `{"name", "doc", "type", "exact", "f64", …}`).

use crate::json::{f64_to_json, rational_to_json};
use rcagd_algebra::quadratic::QuadExt;
use rcagd_algebra::rational::{format_decimal, format_rational, round_decimal};
use rcagd_algebra::roots::RootInterval;
use rcagd_algebra::{bernstein, format_poly, Poly, Rational, Scalar};
use serde_json::{json, Value};
use std::fmt;

/// One exact value.
#[derive(Debug, Clone, PartialEq)]
pub enum Quantity {
    /// A yes/no answer.
    Bool(bool),
    /// An integer count (a degree, a number of solutions).
    Integer(i64),
    /// A word from a fixed vocabulary (a classification: `"helix"`, `"elliptic"`).
    Text(String),
    /// An exact rational.
    Rational(Rational),
    /// An element `a + b√d` of a real quadratic field (rational when `b = 0`).
    Quadratic(QuadExt),
    /// A polynomial in `variable`, power-basis coefficients from the constant term up.
    Polynomial {
        /// The variable's name (`"t"`).
        variable: String,
        /// The coefficients.
        poly: Poly<Rational>,
    },
    /// The real root of `poly` in `interval` (exact when the interval is a point).
    RealRoot {
        /// The defining polynomial.
        poly: Poly<Rational>,
        /// The isolating interval.
        interval: RootInterval,
    },
    /// A vector (a point, a direction, a list of solutions).
    Vector(Vec<Quantity>),
    /// A number known only approximately (a floating-point quantity), marked as
    /// such: JSON `"exact": null`.
    Approx(f64),
    /// A real number proven to lie in `[lo, hi]` (interval arithmetic, a validated
    /// quadrature); the end points are exact decimals.
    Enclosure {
        /// Lower end.
        lo: Rational,
        /// Upper end.
        hi: Rational,
    },
}

impl Quantity {
    /// A polynomial in `t`.
    pub fn poly_t(p: Poly<Rational>) -> Self {
        Quantity::Polynomial {
            variable: "t".into(),
            poly: p,
        }
    }

    /// An enclosure `[lo, hi]` with its end points rounded outward to `digits` significant
    /// decimal digits (so that they print exactly as short decimals).
    pub fn enclosure(lo: &Rational, hi: &Rational, digits: u32) -> Self {
        Quantity::Enclosure {
            lo: round_decimal(lo, digits, false),
            hi: round_decimal(hi, digits, true),
        }
    }

    /// A vector of rationals.
    pub fn rationals(v: &[Rational]) -> Self {
        Quantity::Vector(v.iter().cloned().map(Quantity::Rational).collect())
    }

    /// The type name used in JSON.
    pub fn type_name(&self) -> &'static str {
        match self {
            Quantity::Bool(_) => "bool",
            Quantity::Integer(_) => "integer",
            Quantity::Text(_) => "text",
            Quantity::Rational(_) => "rational",
            Quantity::Quadratic(_) => "quadratic",
            Quantity::Polynomial { .. } => "polynomial",
            Quantity::RealRoot { .. } => "real_root",
            Quantity::Vector(_) => "vector",
            Quantity::Approx(_) => "float",
            Quantity::Enclosure { .. } => "enclosure",
        }
    }

    /// The value as `f64` (`None` for booleans, text, polynomials and vectors).
    pub fn to_f64(&self) -> Option<f64> {
        match self {
            Quantity::Integer(n) => Some(*n as f64),
            Quantity::Rational(q) => Some(Scalar::to_f64(q)),
            Quantity::Quadratic(x) => Some(quad_f64(x)),
            Quantity::RealRoot { poly, interval } => interval.root_f64(poly).ok(),
            Quantity::Approx(x) => Some(*x),
            Quantity::Enclosure { lo, hi } => {
                Some(Scalar::to_f64(&((lo + hi) / Rational::from(2))))
            }
            _ => None,
        }
    }

    /// The JSON form: `{"type", "exact", "f64"}` plus per-type fields
    /// (`a, b, d` of a quadratic; `variable, power, bernstein, degree` of a polynomial;
    /// `polynomial, interval` of a real root; `items` of a vector).
    pub fn to_json(&self) -> Value {
        let mut v = json!({ "type": self.type_name(), "exact": self.to_string() });
        let Value::Object(map) = &mut v else {
            return v;
        };
        if let Some(x) = self.to_f64() {
            map.insert("f64".into(), f64_to_json(x));
        }
        match self {
            Quantity::Bool(b) => {
                map.insert("exact".into(), json!(b));
            }
            Quantity::Integer(n) => {
                map.insert("exact".into(), json!(n));
            }
            Quantity::Quadratic(x) => {
                map.insert("a".into(), rational_to_json(x.a()));
                map.insert("b".into(), rational_to_json(x.b()));
                map.insert("d".into(), rational_to_json(x.d()));
            }
            Quantity::Polynomial { variable, poly } => {
                let power: Vec<Value> = poly.coeffs().iter().map(rational_to_json).collect();
                map.insert("variable".into(), json!(variable));
                map.insert("degree".into(), json!(poly.degree()));
                map.insert("power".into(), Value::Array(power));
                let n = poly.degree().unwrap_or(0);
                if let Ok(b) = bernstein::to_bernstein(poly, n) {
                    map.insert(
                        "bernstein".into(),
                        Value::Array(b.iter().map(rational_to_json).collect()),
                    );
                }
            }
            Quantity::RealRoot { poly, interval } => {
                map.insert(
                    "polynomial".into(),
                    Value::Array(poly.coeffs().iter().map(rational_to_json).collect()),
                );
                map.insert(
                    "interval".into(),
                    json!([
                        rational_to_json(&interval.lo),
                        rational_to_json(&interval.hi)
                    ]),
                );
            }
            Quantity::Vector(items) => {
                map.insert(
                    "items".into(),
                    Value::Array(items.iter().map(Quantity::to_json).collect()),
                );
                let f: Option<Vec<f64>> = items.iter().map(Quantity::to_f64).collect();
                if let Some(f) = f {
                    map.insert(
                        "f64".into(),
                        Value::Array(f.into_iter().map(f64_to_json).collect()),
                    );
                }
            }
            Quantity::Approx(_) => {
                map.insert("exact".into(), Value::Null);
            }
            Quantity::Enclosure { lo, hi } => {
                map.insert("exact".into(), Value::Null);
                map.insert(
                    "interval".into(),
                    json!([rational_to_json(lo), rational_to_json(hi)]),
                );
                map.insert("text".into(), json!(self.to_string()));
            }
            Quantity::Text(_) | Quantity::Rational(_) => {}
        }
        v
    }
}

fn quad_f64(x: &QuadExt) -> f64 {
    Scalar::to_f64(x.a()) + Scalar::to_f64(x.b()) * Scalar::to_f64(x.d()).sqrt()
}

/// Exact text: `true`, `3`, `-1/2`, `3/2 + (1/4)√34`, `2·t^2 - 1`,
/// `root of t^2 - 2 in [1, 3/2]`, `(1, 0, -1/2)`.
impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Quantity::Bool(b) => write!(f, "{b}"),
            Quantity::Integer(n) => write!(f, "{n}"),
            Quantity::Text(s) => f.write_str(s),
            Quantity::Rational(q) => f.write_str(&format_rational(q)),
            Quantity::Quadratic(x) => write!(f, "{x}"),
            Quantity::Polynomial { variable, poly } => f.write_str(&format_poly(poly, variable)),
            Quantity::RealRoot { poly, interval } => {
                if interval.is_exact() {
                    return f.write_str(&format_rational(&interval.lo));
                }
                f.write_str("root of ")?;
                f.write_str(&format_poly(poly, "x"))?;
                write!(
                    f,
                    " in ({}, {})",
                    format_rational(&interval.lo),
                    format_rational(&interval.hi)
                )
            }
            Quantity::Approx(x) => write!(f, "≈ {x}"),
            Quantity::Enclosure { lo, hi } => {
                write!(f, "in [{}, {}]", format_decimal(lo), format_decimal(hi))
            }
            Quantity::Vector(items) => {
                f.write_str("(")?;
                for (i, x) in items.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    write!(f, "{x}")?;
                }
                f.write_str(")")
            }
        }
    }
}

/// A value with its name and a one-line description (formula, meaning).
#[derive(Debug, Clone, PartialEq)]
pub struct NamedQuantity {
    /// The name (an identifier: `sigma`, `arc_length`, `axis`).
    pub name: String,
    /// What it is (`"parametric speed σ(t) = |r'(t)|"`).
    pub doc: String,
    /// The value.
    pub value: Quantity,
}

impl NamedQuantity {
    /// Assembles a named value.
    pub fn new(name: impl Into<String>, doc: impl Into<String>, value: Quantity) -> Self {
        NamedQuantity {
            name: name.into(),
            doc: doc.into(),
            value,
        }
    }

    /// `{"name", "doc", "type", "exact", "f64", …}` (see [`Quantity::to_json`]).
    pub fn to_json(&self) -> Value {
        let mut v = self.value.to_json();
        if let Value::Object(map) = &mut v {
            map.insert("name".into(), json!(self.name));
            map.insert("doc".into(), json!(self.doc));
        }
        v
    }

    /// One line for summaries: `name = exact (≈ f64)`.
    pub fn summary_line(&self) -> String {
        let exact = self.value.to_string();
        match (&self.value, self.value.to_f64()) {
            (Quantity::Approx(x), _) => format!("{} ≈ {x}", self.name),
            (Quantity::Enclosure { .. }, _) => format!("{} {exact}", self.name),
            (Quantity::Rational(_) | Quantity::Integer(_), _) | (_, None) => {
                format!("{} = {exact}", self.name)
            }
            (_, Some(x)) => format!("{} = {exact} ≈ {x}", self.name),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> Rational {
        Rational::from_ratio(p, d)
    }

    #[test]
    fn display_and_json() {
        assert_eq!(Quantity::Rational(q(-3, 6)).to_string(), "-1/2");
        let x = QuadExt::new(q(3, 2), q(1, 4), q(34, 1)).expect("valid");
        let v = Quantity::Quadratic(x);
        assert_eq!(v.to_string(), "3/2 + (1/4)√34");
        let j = v.to_json();
        assert_eq!(j["type"], "quadratic");
        assert_eq!(j["d"], "34");
        let f = j["f64"].as_f64().expect("f64");
        assert!((f - (1.5 + 34f64.sqrt() / 4.0)).abs() < 1e-15);
        let p = Quantity::poly_t(Poly::new(vec![q(-1, 1), q(0, 1), q(2, 1)]));
        assert_eq!(p.to_string(), "2·t^2 - 1");
        let j = p.to_json();
        assert_eq!(j["power"], json!(["-1", "0", "2"]));
        // 2t² − 1 = −B₀ − B₁ + B₂ on [0, 1]
        assert_eq!(j["bernstein"], json!(["-1", "-1", "1"]));
        let r = Quantity::RealRoot {
            poly: Poly::new(vec![q(-2, 1), q(0, 1), q(1, 1)]),
            interval: RootInterval {
                lo: q(1, 1),
                hi: q(3, 2),
            },
        };
        assert_eq!(r.to_string(), "root of x^2 - 2 in (1, 3/2)");
        let f = r.to_json()["f64"].as_f64().expect("f64");
        assert!((f - 2f64.sqrt()).abs() < 1e-15);
        let v = Quantity::rationals(&[q(1, 1), q(0, 1), q(-1, 2)]);
        assert_eq!(v.to_string(), "(1, 0, -1/2)");
        assert_eq!(v.to_json()["f64"], json!([1.0, 0.0, -0.5]));
        let n = NamedQuantity::new("helix", "is a helix", Quantity::Bool(true));
        assert_eq!(n.to_json()["exact"], json!(true));
        assert_eq!(n.summary_line(), "helix = true");
        let e = NamedQuantity::new("energy", "a quadrature", Quantity::Approx(1.5));
        assert_eq!(e.to_json()["exact"], Value::Null);
        assert_eq!(e.to_json()["f64"], json!(1.5));
        assert_eq!(e.to_json()["type"], "float");
        assert_eq!(e.summary_line(), "energy ≈ 1.5");
        // an enclosure of 1/3 to 4 digits, rounded outward
        let c = NamedQuantity::new("third", "1/3", Quantity::enclosure(&q(1, 3), &q(1, 3), 4));
        assert_eq!(c.summary_line(), "third in [0.3333, 0.3334]");
        let j = c.to_json();
        assert_eq!(j["type"], "enclosure");
        assert_eq!(j["exact"], Value::Null);
        assert_eq!(j["interval"], json!(["3333/10000", "1667/5000"]));
        assert!((j["f64"].as_f64().expect("f64") - 0.33335).abs() < 1e-12);
    }
}

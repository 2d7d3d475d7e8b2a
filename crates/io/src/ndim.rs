//! Exact exchange of objects of dimension greater than 3: a rational map from `p`
//! parameters into `Rⁿ` (a PN hypersurface of `Rⁿ`, the offset of a ruled manifold),
//! stored as its homogeneous polynomial coordinates `(X₀, X₁, …, Xₙ)`, `x = (X₁, …)/X₀`, in
//! sparse terms with exact rational coefficients.
//!
//! JSON form ([`NdimMap::to_json`], read back by [`NdimMap::from_json`]):
//! `{"type": "ndim_map", "dimension": n, "parameters": ["t", "s1", …],
//!   "homogeneous": [[{"c": "p/q", "e": [e₁, …, e_p]}, …], …]}` — one term list per
//! homogeneous coordinate, `X₀` first. Inside an [`crate::Object`] the map travels as a
//! named value ([`NdimMap::quantity`]): a vector of coordinates, each a vector of terms
//! `[c, e₁, …, e_p]`. A 3-dimensional picture (a parameter slice projected onto three
//! coordinates) is the object's ordinary patch geometry.

use crate::json::rational_to_json;
use crate::quantity::Quantity;
use crate::IoError;
use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::rational::parse_rational;
use rcagd_algebra::Rational;
use serde_json::{json, Value};

/// A rational map into `Rⁿ` by homogeneous polynomial coordinates (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct NdimMap {
    /// The parameter names, in variable order.
    pub parameters: Vec<String>,
    /// `(X₀, X₁, …, Xₙ)`.
    pub homogeneous: Vec<MPoly<Rational>>,
}

impl NdimMap {
    /// The map `(X₀, …, Xₙ)` in the named parameters.
    ///
    /// # Errors
    /// [`IoError::Invalid`] for fewer than two coordinates or a polynomial in more
    /// variables than parameters.
    pub fn new(
        parameters: Vec<String>,
        homogeneous: Vec<MPoly<Rational>>,
    ) -> Result<Self, IoError> {
        if homogeneous.len() < 2 {
            return Err(IoError::Invalid(
                "an n-dimensional map needs X₀ and at least one coordinate".into(),
            ));
        }
        let p = parameters.len();
        if homogeneous
            .iter()
            .any(|x| x.terms().any(|(e, _)| e.iter().skip(p).any(|&k| k > 0)))
        {
            return Err(IoError::Invalid(format!(
                "a coordinate uses more than the {p} parameters {parameters:?}"
            )));
        }
        Ok(NdimMap {
            parameters,
            homogeneous,
        })
    }

    /// The ambient dimension `n`.
    pub fn dimension(&self) -> usize {
        self.homogeneous.len() - 1
    }

    fn terms(&self, x: &MPoly<Rational>) -> Vec<(Rational, Vec<u32>)> {
        let p = self.parameters.len();
        x.terms()
            .map(|(e, c)| {
                let mut e = e.to_vec();
                e.resize(p, 0);
                (c.clone(), e)
            })
            .collect()
    }

    /// The JSON form (module docs).
    pub fn to_json(&self) -> Value {
        let coords: Vec<Value> = self
            .homogeneous
            .iter()
            .map(|x| {
                Value::Array(
                    self.terms(x)
                        .into_iter()
                        .map(|(c, e)| json!({"c": rational_to_json(&c), "e": e}))
                        .collect(),
                )
            })
            .collect();
        json!({
            "type": "ndim_map",
            "dimension": self.dimension(),
            "parameters": self.parameters,
            "homogeneous": coords,
        })
    }

    /// Reads the JSON form back.
    ///
    /// # Errors
    /// [`IoError::Invalid`] naming the malformed field.
    pub fn from_json(v: &Value) -> Result<Self, IoError> {
        let bad = |what: &str| IoError::Invalid(format!("ndim_map: {what}"));
        if v.get("type").and_then(Value::as_str) != Some("ndim_map") {
            return Err(bad("\"type\" must be \"ndim_map\""));
        }
        let parameters: Vec<String> = v
            .get("parameters")
            .and_then(Value::as_array)
            .ok_or_else(|| bad("missing \"parameters\""))?
            .iter()
            .map(|x| {
                x.as_str()
                    .map(str::to_string)
                    .ok_or_else(|| bad("a parameter name is not a string"))
            })
            .collect::<Result<_, _>>()?;
        let p = parameters.len();
        let coords = v
            .get("homogeneous")
            .and_then(Value::as_array)
            .ok_or_else(|| bad("missing \"homogeneous\""))?;
        let mut homogeneous = Vec::with_capacity(coords.len());
        for (k, coord) in coords.iter().enumerate() {
            let terms = coord
                .as_array()
                .ok_or_else(|| bad(&format!("coordinate {k} is not a list of terms")))?;
            let mut poly = MPoly::zero(p);
            for t in terms {
                let c = t
                    .get("c")
                    .and_then(Value::as_str)
                    .and_then(|s| parse_rational(s).ok())
                    .ok_or_else(|| bad(&format!("a term of coordinate {k} has no exact \"c\"")))?;
                let e: Vec<u32> = t
                    .get("e")
                    .and_then(Value::as_array)
                    .filter(|e| e.len() == p)
                    .ok_or_else(|| {
                        bad(&format!(
                            "a term of coordinate {k} needs {p} exponents \"e\""
                        ))
                    })?
                    .iter()
                    .map(|x| x.as_u64().and_then(|x| u32::try_from(x).ok()))
                    .collect::<Option<_>>()
                    .ok_or_else(|| bad("an exponent is not a non-negative integer"))?;
                poly = &poly + &MPoly::monomial(p, &e, c);
            }
            homogeneous.push(poly);
        }
        Self::new(parameters, homogeneous)
    }

    /// The map as a named value of an object: a vector of coordinates `X₀, …, Xₙ`, each a
    /// vector of terms `[c, e₁, …, e_p]`.
    pub fn quantity(&self) -> Quantity {
        Quantity::Vector(
            self.homogeneous
                .iter()
                .map(|x| {
                    Quantity::Vector(
                        self.terms(x)
                            .into_iter()
                            .map(|(c, e)| {
                                let mut t = vec![Quantity::Rational(c)];
                                t.extend(e.into_iter().map(|k| Quantity::Integer(i64::from(k))));
                                Quantity::Vector(t)
                            })
                            .collect(),
                    )
                })
                .collect(),
        )
    }

    /// The point at the parameters `u` (`None` where `X₀ = 0`).
    pub fn eval(&self, u: &[Rational]) -> Option<Vec<Rational>> {
        let v: Vec<Rational> = self
            .homogeneous
            .iter()
            .map(|x| (&MPoly::zero(u.len()) + x).eval(u).ok())
            .collect::<Option<_>>()?;
        if v[0] == Rational::ZERO {
            return None;
        }
        Some(v[1..].iter().map(|x| x.clone() / v[0].clone()).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rcagd_algebra::Scalar;

    #[test]
    fn json_round_trip_is_exact() {
        let (s, t) = (MPoly::<Rational>::var(2, 0), MPoly::<Rational>::var(2, 1));
        let one = MPoly::constant(2, Rational::from(1));
        let w = &(&(&s * &s) + &(&t * &t)) + &one;
        let x = (&s * &t).scale(&Rational::from_ratio(2, 3));
        let map = NdimMap::new(
            vec!["s".into(), "t".into()],
            vec![w.clone(), x.clone(), s.clone(), t.clone(), one],
        )
        .expect("map");
        assert_eq!(map.dimension(), 4);
        let back = NdimMap::from_json(&map.to_json()).expect("read back");
        assert_eq!(back, map);
        let p = back
            .eval(&[Rational::from(1), Rational::from(2)])
            .expect("point");
        assert_eq!(p[0], Rational::from_ratio(4, 18));
        assert!(matches!(map.quantity(), Quantity::Vector(v) if v.len() == 5));
        assert!(NdimMap::from_json(&json!({"type": "curve"})).is_err());
        assert!(NdimMap::new(vec!["s".into()], vec![w, x]).is_err());
    }
}

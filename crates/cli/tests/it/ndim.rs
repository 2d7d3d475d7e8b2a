//! The n-dimensional ops: the exact homogeneous map of a hypersurface of R⁴ read back from
//! the JSON output and checked by hand, and named errors.

use crate::common::{build_json_in, build_refused, read_json, temp_dir};
use rcagd_algebra::{parse_rational, Rational, Scalar};
use serde_json::Value;

type Q = Rational;

fn rat(v: &Value) -> Q {
    parse_rational(v.as_str().expect("exact string")).expect("rational")
}

/// The homogeneous coordinates of the `homogeneous_map` value evaluated at `u`.
fn eval_map(obj: &Value, u: &[Q]) -> Vec<Q> {
    let map = obj["values"]
        .as_array()
        .expect("values")
        .iter()
        .find(|v| v["name"] == "homogeneous_map")
        .expect("homogeneous_map");
    map["items"]
        .as_array()
        .expect("coordinates")
        .iter()
        .map(|coord| {
            coord["items"]
                .as_array()
                .expect("terms")
                .iter()
                .fold(Q::from(0), |acc, term| {
                    let it = term["items"].as_array().expect("term");
                    let mut t = rat(&it[0]["exact"]);
                    for (e, x) in it[1..].iter().zip(u) {
                        for _ in 0..e["exact"].as_u64().expect("exponent") {
                            t *= x.clone();
                        }
                    }
                    acc + t
                })
        })
        .collect()
}

#[test]
fn hypersphere_of_r4_is_exported_exactly() {
    let dir = temp_dir("ndim-sphere");
    let recipe = r#"[[object]]
name = "s"
op = "pn_hypersurface"
dimension = 4
support = [["-3/2", 0, 0, 0]]
slice = [0, 0, "1/3"]
project = [1, 2, 4]
domain = ["-1/2", "1/2", "-1/2", "1/2"]
distances = ["1/2"]
"#;
    let out = build_json_in(&dir, recipe);
    for (name, r) in [("s", Q::from_ratio(3, 2)), ("s_offset1", Q::from(2))] {
        let obj = read_json(&out, name);
        assert_eq!(obj["all_certificates_hold"], true);
        let u = [Q::from_ratio(1, 2), Q::from_ratio(-2, 3), Q::from(3)];
        let x = eval_map(&obj, &u);
        assert_eq!(x.len(), 5);
        let norm2 = x[1..]
            .iter()
            .fold(Q::from(0), |a, c| a + c.clone() * c.clone());
        assert_eq!(
            norm2,
            r.clone() * r.clone() * x[0].clone() * x[0].clone(),
            "{name}"
        );
    }
}

#[test]
fn ndim_errors_name_the_parameter() {
    let dir = temp_dir("ndim-errors");
    let e = build_refused(
        &dir,
        "[[object]]\nname = \"x\"\nop = \"pn_hypersurface\"\ndimension = 9\nsupport = [[1, 0, 0]]\n",
    );
    assert!(e.contains("dimension"), "{e}");
    // the developable surface of the twisted cubic in R³: Theorem 5.2's excluded case
    let e = build_refused(
        &dir,
        "[[object]]\nname = \"y\"\nop = \"ruled_manifold_offset\"\ndirectrix = [[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\ngenerators = [[1, 0, 0], [0, 2, 0], [0, 0, 3]]\ndistance = 1\n",
    );
    assert!(e.contains("not rational"), "{e}");
}

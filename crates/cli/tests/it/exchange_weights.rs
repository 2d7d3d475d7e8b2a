//! The exchanged weights of a biquadratic patch whose weights grow geometrically along
//! `u` (1, 32, 1024: a ratio 1024 and a difference > 1000, which OpenCascade's IGES reader
//! flags: "Difference between weights is too big", `max w − min w > 1000` per entity,
//! `IGES_1374`) and of the Dupin cyclide (op `dupin_canal`, as in
//! `examples/recipes/canal.toml`; session 2's Peternell–Pottmann patches varied by 108×,
//! session 3's Krasauskas patches are biquadratic and milder). The exported NURBS (STEP,
//! IGES, sidecar) carry balanced weights (`rcagd_io::balance`): every surface of the
//! sidecar must stay below that threshold, by a wide margin.

use crate::common::{bin, run_ok, temp_dir};

const RECIPE: &str = r#"
[[object]]
name = "wild_weights"
op = "bezier_patch"
net = [
  [[0, 0, 0], [1, 0, "1/2"], [2, 0, 0]],
  [[0, 1, "1/2"], [1, 1, 0], [2, 1, "1/2"]],
  [[0, 2, 0], [1, 2, "1/2"], [2, 2, 0]],
]
weights = [[1, 1, 1], [32, 32, 32], [1024, 1024, 1024]]

[[object]]
name = "dupin_cyclide"
op = "dupin_canal"
rho = 4
r0 = "3/2"
s = "1/7"
"#;

/// `p/q` or `p` as f64.
fn num(v: &serde_json::Value) -> f64 {
    let s = v.as_str().expect("exact string");
    match s.split_once('/') {
        Some((p, q)) => p.parse::<f64>().expect("num") / q.parse::<f64>().expect("den"),
        None => s.parse().expect("num"),
    }
}

/// All weights (first homogeneous coordinate) of a nested list of points.
fn weights(v: &serde_json::Value, out: &mut Vec<f64>) {
    let Some(a) = v.as_array() else { return };
    if a.first().is_some_and(|x| x.is_string()) {
        out.push(num(&a[0]));
    } else {
        for x in a {
            weights(x, out);
        }
    }
}

fn spread(w: &[f64]) -> (f64, f64) {
    let lo = w.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = w.iter().copied().fold(0.0, f64::max);
    (hi / lo, hi - lo)
}

#[test]
fn dupin_cyclide_weights_are_balanced_for_exchange() {
    let dir = temp_dir("exchange-weights");
    let recipe = dir.join("dupin.toml");
    std::fs::write(&recipe, RECIPE).expect("write recipe");
    run_ok(
        bin()
            .args(["build", "--format", "json,exact,iges", "--out"])
            .arg(&dir)
            .arg(&recipe),
    );
    let read = |name: &str| -> serde_json::Value {
        let text = std::fs::read_to_string(dir.join(name)).expect("output file");
        serde_json::from_str(&text).expect("json")
    };
    let check = |name: &str, n: usize| {
        let side = read(&format!("{name}.exact.json"));
        let surfaces = side["objects"][0]["surfaces"].as_array().expect("surfaces");
        assert_eq!(surfaces.len(), n, "{name}");
        for (k, s) in surfaces.iter().enumerate() {
            let mut w = Vec::new();
            weights(&s["control_points"], &mut w);
            assert!(w.iter().all(|x| *x > 0.0), "{name} surface {k}");
            let (r, d) = spread(&w);
            assert!(r <= 16.0, "{name} surface {k}: weight ratio {r}");
            assert!(
                d <= 100.0,
                "{name} surface {k}: weight difference {d} (OpenCascade warns above 1000)"
            );
        }
    };
    // the construction itself: weights spread over > 100× and > 1000
    let obj = read("wild_weights.json");
    let mut w = Vec::new();
    weights(&obj["control_points"], &mut w);
    let (r, d) = spread(&w);
    assert!(r > 100.0 && d > 1000.0, "{r} {d}");
    // the exchanged surfaces: ratio ≤ 16 after balancing, difference far below 1000
    check("wild_weights", 1);
    check("dupin_cyclide", 16);
    assert!(dir.join("dupin_cyclide.igs").exists());
}

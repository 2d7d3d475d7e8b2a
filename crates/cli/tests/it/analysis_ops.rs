//! The analysis ops `ph_preimage` and `ph_qiq`: values compared with hand derivations.

use crate::common::{build_json_in, build_refused, read_json, temp_dir};
use rcagd_algebra::{parse_rational, Rational};
use serde_json::Value;

type Q = Rational;

fn build_json(tag: &str, recipe: &str, name: &str) -> Value {
    let dir = temp_dir(tag);
    read_json(&build_json_in(&dir, recipe), name)
}

fn value<'a>(obj: &'a Value, name: &str) -> &'a Value {
    obj["values"]
        .as_array()
        .expect("values")
        .iter()
        .find(|v| v["name"] == name)
        .unwrap_or_else(|| panic!("no value {name}"))
}

fn rat(v: &Value) -> Q {
    parse_rational(v.as_str().expect("exact string")).expect("rational")
}

/// `[w, x, y, z]` rows of a vector-of-vectors value.
fn quats(v: &Value) -> Vec<[Q; 4]> {
    v["items"]
        .as_array()
        .expect("items")
        .iter()
        .map(|q| {
            let it = q["items"].as_array().expect("items");
            [
                rat(&it[0]["exact"]),
                rat(&it[1]["exact"]),
                rat(&it[2]["exact"]),
                rat(&it[3]["exact"]),
            ]
        })
        .collect()
}

fn qmul(a: &[Q; 4], b: &[Q; 4]) -> [Q; 4] {
    let [a0, a1, a2, a3] = a.clone();
    let [b0, b1, b2, b3] = b.clone();
    [
        a0.clone() * b0.clone()
            - a1.clone() * b1.clone()
            - a2.clone() * b2.clone()
            - a3.clone() * b3.clone(),
        a0.clone() * b1.clone() + a1.clone() * b0.clone() + a2.clone() * b3.clone()
            - a3.clone() * b2.clone(),
        a0.clone() * b2.clone() - a1.clone() * b3.clone()
            + a2.clone() * b0.clone()
            + a3.clone() * b1.clone(),
        a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0,
    ]
}

fn q(s: &str) -> Q {
    parse_rational(s).expect("number")
}

/// Lemma 2.1 for `c = (−1, 2, 2)`: `Q(0) = i + j + k`, so by hand
/// `Q(φ) = (i + j + k)(3/5 + 4/5 i) = −4/5 + 3/5 i + 7/5 j − 1/5 k`.
#[test]
fn ph_qiq_matches_the_hand_derivation() {
    let o = build_json(
        "qiq",
        "[[object]]\nname = \"s\"\nop = \"ph_qiq\"\nc = [-1, 2, 2]\nrotation = [\"3/5\", \"4/5\"]\n",
        "s",
    );
    assert_eq!(o["all_certificates_hold"], true);
    assert_eq!(
        quats(value(&o, "q")),
        vec![[q("-4/5"), q("3/5"), q("7/5"), q("-1/5")]]
    );
    // the exceptional branch c = −|c| i: Q = √|c| j = 2j
    let o = build_json(
        "qiq2",
        "[[object]]\nname = \"s\"\nop = \"ph_qiq\"\nc = [-4, 0, 0]\n",
        "s",
    );
    assert_eq!(
        quats(value(&o, "q")),
        vec![[q("0"), q("0"), q("2"), q("0")]]
    );
}

/// The cubic with preimage `A_0 = 1 + j`, `A_1 = 1 + i + k` given by its control points
/// (computed by hand with (8.2): `p_1 = A_0 i A_0*/3 = (0, 0, −2/3)`, …): the recovered
/// preimage is `(A_0, A_1)·q` with a unit complex `q`, `σ = |A|²`, content 1.
#[test]
fn ph_preimage_recovers_the_cubic_preimage() {
    let o = build_json(
        "preimage",
        "[[object]]\nname = \"c\"\nop = \"ph_preimage\"\npoints = [[0, 0, 0], [0, 0, \"-2/3\"], [\"1/3\", \"2/3\", -1], [\"2/3\", \"4/3\", \"-1/3\"]]\n",
        "c",
    );
    assert_eq!(o["all_certificates_hold"], true);
    let got = quats(value(&o, "quaternion_coefficients"));
    let given = [
        [q("1"), q("0"), q("1"), q("0")],
        [q("1"), q("1"), q("0"), q("1")],
    ];
    // q = A_0⁻¹ R_0 = A_0* R_0 / |A_0|²
    let a0c = [q("1/2"), q("0"), q("-1/2"), q("0")];
    let unit = qmul(&a0c, &got[0]);
    assert_eq!(unit[2], q("0"));
    assert_eq!(unit[3], q("0"));
    assert_eq!(
        unit[0].clone() * unit[0].clone() + unit[1].clone() * unit[1].clone(),
        q("1")
    );
    for (g, r) in given.iter().zip(&got) {
        assert_eq!(&qmul(g, &unit), r);
    }
    // σ = |A|² = |A_0|²(1 − t)² + 2⟨A_0, A_1⟩ t(1 − t) + |A_1|² t² = 2 − 2t + 3t²
    let sigma: Vec<Q> = value(&o, "sigma")["power"]
        .as_array()
        .expect("power")
        .iter()
        .map(rat)
        .collect();
    assert_eq!(sigma, vec![q("2"), q("-2"), q("3")]);
    assert_eq!(value(&o, "content")["exact"], "1");
}

/// No preimage: the message names the content and says why.
#[test]
fn ph_preimage_without_preimage_is_an_error() {
    let dir = temp_dir("preimage-err");
    let e = build_refused(
        &dir,
        "[[object]]\nname = \"c\"\nop = \"ph_preimage\"\npower = [[0, 0, 0], [0, 0, 0], [1, 0, 0]]\n",
    );
    assert!(e.contains("gcd(x', y', z')"), "{e}");
}

fn poly_value(o: &Value, name: &str) -> Vec<Q> {
    value(o, name)["power"]
        .as_array()
        .expect("power")
        .iter()
        .map(rat)
        .collect()
}

/// The cubic `A = (1 − t)(1 + j) + t(i + k)`: by hand `α = 1 − t + it`, `β = i(1 − t) + t`,
/// so `αβ' − α'β = α₀β₁ − α₁β₀ = 1·1 − i·i = 2 = g + i f`: `f = 0`, `g = 2`; every
/// factorization must reproduce `f + ig = h(a + ib)²` and `g + if = h̃(ã + ib̃)²`.
#[test]
fn ph_dph_forms_match_the_hand_derivation() {
    let o = build_json(
        "dph-forms",
        "[[object]]\nname = \"c\"\nop = \"ph_dph_forms\"\nquaternions = [[1, 0, 1, 0], [0, 1, 0, 1]]\n",
        "c",
    );
    assert_eq!(o["all_certificates_hold"], true);
    assert!(poly_value(&o, "f").iter().all(|x| *x == q("0")));
    assert_eq!(poly_value(&o, "g"), vec![q("2")]);
    let c0 = |n: &str| poly_value(&o, n).first().cloned().unwrap_or(q("0"));
    let (h, a, b) = (c0("h"), c0("a"), c0("b"));
    // f + ig = h(a² − b²) + 2hab i = 2i
    assert_eq!(
        h.clone() * (a.clone() * a.clone() - b.clone() * b.clone()),
        q("0")
    );
    assert_eq!(q("2") * h * a * b, q("2"));
    let (h, a, b) = (c0("h_hopf"), c0("a_hopf"), c0("b_hopf"));
    // g + if = h̃(ã² − b̃²) + 2h̃ãb̃ i = 2
    assert_eq!(
        h.clone() * (a.clone() * a.clone() - b.clone() * b.clone()),
        q("2")
    );
    assert_eq!(q("2") * h * a * b, q("0"));
}

fn approx(o: &Value, name: &str) -> f64 {
    value(o, name)["f64"].as_f64().expect("f64")
}

/// Besednjak Example 9.1 (`p_s = 0`, `d_s = (1, 0, 1)`, `p_f = (1, 1, 1)`,
/// `d_f = (0, 1, 1)`), printed values: energies 1.2735954 (least), 89.576305 and
/// 322.29811 (twice); axes (0.354664, 0.354664, 0.865117) and (0.309913, 0.309913,
/// 0.898837) (up to sign); |κ/τ| = 0.586692 and 0.607333. The elimination quartic has
/// four real roots, two of them valid.
#[test]
fn ph_hermite_values_reproduce_example_9_1() {
    let o = build_json(
        "hermite",
        "[[object]]\nname = \"h\"\nop = \"ph_hermite\"\np_s = [0, 0, 0]\nd_s = [1, 0, 1]\np_f = [1, 1, 1]\nd_f = [0, 1, 1]\n",
        "h",
    );
    assert_eq!(
        value(&o, "quartic_roots")["items"]
            .as_array()
            .unwrap()
            .len(),
        4
    );
    assert_eq!(value(&o, "valid_roots")["exact"], 2);
    assert_eq!(value(&o, "interpolants")["exact"], 4);
    assert_eq!(value(&o, "elimination_quartic")["type"], "polynomial");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs().max(1.0);
    assert!(close(approx(&o, "bending_energy"), 1.2735954));
    // the energy is an enclosure proven to contain the exact value; the written control
    // points are within the stated bound of the exact ones
    let e = value(&o, "bending_energy");
    assert_eq!(e["type"], "enclosure");
    let iv: Vec<f64> = e["interval"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| {
            let (p, q) = x.as_str().unwrap().split_once('/').unwrap();
            p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap()
        })
        .collect();
    assert!(
        iv[0] <= 1.273_595_441_493 && 1.273_595_441_493 <= iv[1] && iv[1] - iv[0] < 1e-11,
        "{iv:?}"
    );
    assert_eq!(value(&o, "control_point_error")["type"], "rational");
    assert!(value(&o, "control_point_error")["f64"].as_f64().unwrap() < 1e-15);
    assert!(close(approx(&o, "kappa_over_tau"), 0.586692));
    let axis: Vec<f64> = value(&o, "axis")["f64"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap().abs())
        .collect();
    for (a, b) in axis.iter().zip([0.354664, 0.354664, 0.865117]) {
        assert!((a - b).abs() < 1e-6, "{axis:?}");
    }
    assert_eq!(value(&o, "least_energy")["exact"], true);
    // the other interpolants are the objects h_2, h_3, …
    let o2 = build_json(
        "hermite2",
        "[[object]]\nname = \"h\"\nop = \"ph_hermite\"\np_s = [0, 0, 0]\nd_s = [1, 0, 1]\np_f = [1, 1, 1]\nd_f = [0, 1, 1]\n",
        "h_3",
    );
    assert!(close(approx(&o2, "bending_energy"), 322.29811));
    assert!(close(approx(&o2, "kappa_over_tau"), 0.607333));
    assert_eq!(value(&o2, "rank")["exact"], 3);
}

/// Besednjak Example 8.9 through `ph_analyze`: not a helix, decided by Prop. 7.9 with
/// `Δ < 0` (printed Δ = −9 for the printed h; ours is for h monic, same sign).
#[test]
fn ph_analyze_reports_the_chapter_7_criterion() {
    let o = build_json(
        "ch7",
        "[[object]]\nname = \"c\"\nop = \"ph_analyze\"\nquaternions = [[1, 0, 0, -1], [1, 0, 0, \"-2/3\"], [2, 1, -1, \"-2/3\"], [2, 3, -2, 0]]\n",
        "c",
    );
    assert_eq!(o["all_certificates_hold"], true);
    assert_eq!(value(&o, "ch7_statement")["exact"], "Besednjak Prop. 7.9");
    assert_eq!(value(&o, "ch7_helical")["exact"], false);
    assert_eq!(value(&o, "helix")["exact"], "not a helix");
    assert!(rat(&value(&o, "ch7_delta")["exact"]) < q("0"));
}

/// Besednjak Lemma 7.2 through `ph_analyze`: α = (t + 2)(1 + t²), β = (t + 2)(t + 1) have
/// r = 1; the reduced Wronskian 1 − 2t − t² has discriminant 8 ≠ 0 (hand computation).
#[test]
fn ph_analyze_reports_lemma_7_2() {
    let o = build_json(
        "lemma72",
        "[[object]]\nname = \"c\"\nop = \"ph_analyze\"\nquaternions = [[2, 0, 0, 2], [\"7/3\", 0, 0, 3], [\"10/3\", 0, 0, \"13/3\"], [6, 0, 0, 6]]\n",
        "c",
    );
    assert_eq!(o["all_certificates_hold"], true);
    let d = value(&o, "reduced_wronskian_discriminant");
    assert_eq!(d["items"][0]["exact"], "8");
    assert_eq!(d["items"][1]["exact"], "0");
}

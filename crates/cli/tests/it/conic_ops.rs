//! The conic-family ops: `conic_point` (the engine's decision as values, with the proof
//! re-checked as a certificate) and `quadric_family` (Peternell §5.1): values compared
//! with hand derivations, and bad input refused with the parameter named.

use crate::common::{
    build_json_certified as build_json, build_refused, temp_dir, value_exact as exact,
};

/// X² + Y² − (t² + 9)Z² = 0: (t, ±3, 1) by hand; the engine returns a primitive point.
/// X² + Y² − (t² + 2)Z² = 0: −1 is not a square modulo t² + 2 (Q(√−2) has no √−1).
/// X² − 3Y² + t²Z² = 0: the leading conic X² − 3Y² + Z² has no point over Q₃, and
/// (√3·t, t, 0) is a point over Q(√3).
#[test]
fn conic_point_decisions() {
    let v = build_json(
        "cp_9",
        "[[object]]\nname = \"a\"\nop = \"conic_point\"\nL = [1]\nM = [1]\nN = [-9, 0, -1]\n",
        "a",
    );
    assert_eq!(exact(&v, "decision"), "rational");
    // (t, ±3, ±1): the signs of Y and Z are free
    assert!(["(t, -3, 1)", "(t, 3, 1)", "(t, -3, -1)", "(t, 3, -1)"]
        .contains(&exact(&v, "point").as_str()));
    let v = build_json(
        "cp_2",
        "[[object]]\nname = \"b\"\nop = \"conic_point\"\nL = [1]\nM = [1]\nN = [-2, 0, -1]\n",
        "b",
    );
    assert_eq!(exact(&v, "decision"), "no_point");
    let o = exact(&v, "obstruction");
    assert!(o.contains("t^2 + 2") && o.contains("not a square"), "{o}");
    let v = build_json(
        "cp_3",
        "[[object]]\nname = \"c\"\nop = \"conic_point\"\nL = [1]\nM = [-3]\nN = [0, 0, 1]\n",
        "c",
    );
    assert_eq!(exact(&v, "decision"), "quadratic_field");
    assert_eq!(exact(&v, "radicand"), "3");
    assert!(exact(&v, "obstruction").contains("Q_3"));
}

/// x₁² + (1 + t²)x₂² + 2x₃² = (1 + t²)x₀²: the section (x₀, x₁, x₂) has the point
/// (1, 0, ±1); the map has degree 2 in t (from Q(t)) and 2 in (u₁, u₂).
#[test]
fn quadric_family_values() {
    let recipe = "[[object]]\nname = \"e\"\nop = \"quadric_family\"\nmatrix = [[[-1, 0, -1], [0, 0, 0], [0, 0, 0], [0, 0, 0]], [[0, 0, 0], [1, 0, 0], [0, 0, 0], [0, 0, 0]], [[0, 0, 0], [0, 0, 0], [1, 0, 1], [0, 0, 0]], [[0, 0, 0], [0, 0, 0], [0, 0, 0], [2, 0, 0]]]\nt = \"1/2\"\n";
    let v = build_json("qf_e", recipe, "e");
    let p = exact(&v, "point");
    assert!(p == "(1, 0, -1, 0)" || p == "(1, 0, 1, 0)", "{p}");
    assert_eq!(exact(&v, "degree"), "(2, 2)");
    // a definite family: no real point at t = 0
    let e = build_refused(
        &temp_dir("qf_def"),
        "[[object]]\nname = \"d\"\nop = \"quadric_family\"\nmatrix = [[[1], [0], [0]], [[0], [1], [0]], [[0], [0], [1]]]\n",
    );
    assert!(e.contains("matrix") && e.contains("definite"), "{e}");
    let e = build_refused(
        &temp_dir("qf_ns"),
        "[[object]]\nname = \"d\"\nop = \"quadric_family\"\nmatrix = [[[1], [1], [0]], [[0], [1], [0]], [[0], [0], [-1]]]\n",
    );
    assert!(e.contains("not symmetric"), "{e}");
}

/// The Möbius curve (t²/4, t, 0, 0, t²/4 − 1) of P⁴: spheres (t, 0, 0), r² = 1 + t²/2; the
/// canal surface has degree 2 in u. A curve with c₀ ≡ c₄ is refused with the parameter named.
#[test]
fn canal_hypersurface_from_the_mobius_model() {
    let v = build_json(
        "ch_m",
        "[[object]]\nname = \"h\"\nop = \"canal_hypersurface\"\nmobius_curve = [[0, 0, \"1/4\"], [0, 1, 0], [0, 0, 0], [0, 0, 0], [-1, 0, \"1/4\"]]\ndomain = [-1, 1, \"-1/2\", \"1/2\"]\n",
        "h",
    );
    assert_eq!(exact(&v, "dimension"), "3");
    assert!(exact(&v, "degree").ends_with(", 2)"));
    let e = build_refused(
        &temp_dir("ch_bad"),
        "[[object]]\nname = \"h\"\nop = \"canal_hypersurface\"\nmobius_curve = [[1, 1], [0, 1], [0, 0], [0, 0], [1, 1]]\n",
    );
    assert!(
        e.contains("mobius_curve") && e.contains("hyperplane"),
        "{e}"
    );
}

/// The dual construction exported: with `developable = [v0, v1]` the `conic_surface` op
/// also builds the developable of the tangent planes F(t) of Thm 1.3 as a point surface
/// `NAME_developable`, certified (on the rulings F ∩ Ḟ, every plane tangent to the
/// surface, touching it along k(t)); a malformed range is refused with the parameter named.
#[test]
fn conic_surface_with_its_developable() {
    // a surface of revolution: circles x² + y² = (1 + t²)², z = t
    let recipe = "[[object]]\nname = \"s\"\nop = \"conic_surface\"\nmatrix = [[[1,0,0,0,0],[0,0,0,0,0],[0,0,0,0,0],[0,1,0,0,0]], [[0,0,0,0,0],[-1,0,-2,0,-1],[0,0,0,0,0],[0,0,0,0,0]], [[0,0,0,0,0],[0,0,0,0,0],[-1,0,-2,0,-1],[0,0,0,0,0]], [[0,1,0,0,0],[0,0,0,0,0],[0,0,0,0,0],[0,0,1,0,0]]]\ndomain = [\"-1/2\", \"1/2\", -1, 1]\ndevelopable = [\"-1/10\", \"1/10\"]\n";
    // the hyperboloid x² + y² − z² = 1 (circles x² + y² = 1 + t²): the engine's curve is
    // a line of the ruled surface, the tangent planes along it a pencil — refused, named
    let hyp = recipe.replace("[-1,0,-2,0,-1]", "[-1,0,-1,0,0]");
    let err = build_refused(&temp_dir("cs_dev_hyp"), &hyp);
    assert!(err.contains("pencil"), "{err}");
    let d = build_json("cs_dev", recipe, "s_developable");
    let text = d.to_string();
    assert!(text.contains("ruling F ∩ Ḟ"), "{text}");
    assert!(text.contains("touches the surface along k(t)"), "{text}");
    let s = build_json("cs_dev_s", recipe, "s");
    assert!(s.to_string().contains("F(t, u) touches ċ(t)"));
    let bad = recipe.replace("developable = [\"-1/10\", \"1/10\"]", "developable = [1]");
    let err = build_refused(&temp_dir("cs_dev_bad"), &bad);
    assert!(err.contains("developable"), "{err}");
}

//! The query ops of the quadric and Laguerre topics: values compared with hand
//! derivations (in the comments), and bad input refused with the parameter named.

use crate::common::{
    build_json_certified as build_json, build_refused, temp_dir, value_exact as exact,
};

fn refused(tag: &str, recipe: &str, words: &[&str]) {
    let e = build_refused(&temp_dir(tag), recipe);
    for w in words {
        assert!(e.contains(w), "{w:?} not in {e}");
    }
}

/// δ(1, 2, −1, 3) = (15, 10, 10, −5) (Jüttler (9)); σ⁻¹(k) = (k0 − k3, k1, k2, 0) = (20, 10, 10, 0).
#[test]
fn quadric_fibre_of_the_hopf_map() {
    let v = build_json(
        "q_fibre",
        "[[object]]\nname = \"f\"\nop = \"quadric_fibre\"\npreimage_point = [1, 2, -1, 3]\n",
        "f",
    );
    assert_eq!(exact(&v, "k"), "(15, 10, 10, -5)");
    assert_eq!(exact(&v, "sigma_inverse"), "(20, 10, 10, 0)");
    // on z = xy: ψ(1, 2, 3, 4) = (4, 8, 3, 6), τ⁻¹ = (4, 8, 3, 4)
    let v = build_json(
        "q_fibre_psi",
        "[[object]]\nname = \"g\"\nop = \"quadric_fibre\"\nquadric = \"hyperbolic_paraboloid_xy\"\npreimage_point = [1, 2, 3, 4]\n",
        "g",
    );
    assert_eq!(exact(&v, "k"), "(4, 8, 3, 6)");
    assert_eq!(exact(&v, "tau_inverse"), "(4, 8, 3, 4)");
    refused(
        "q_fibre_off",
        "[[object]]\nname = \"f\"\nop = \"quadric_fibre\"\npoint = [1, 1, 1]\n",
        &["point", "not on the quadric"],
    );
}

/// The circle through (1,0,0), (0,1,0), (3/5,0,4/5) lies in x + y + z/2 = 1, i.e.
/// π = (−2, 2, 2, 1); it misses z = (0,0,1), so its preimage is a one-sheet hyperboloid.
#[test]
fn quadric_preimage_of_a_circle() {
    let v = build_json(
        "q_pre",
        "[[object]]\nname = \"c\"\nop = \"quadric_preimage\"\npoints = [[1, 0, 0], [0, 1, 0], [\"3/5\", 0, \"4/5\"]]\n",
        "c",
    );
    let plane = exact(&v, "plane");
    assert!(
        plane == "(-2, 2, 2, 1)"
            || plane == "(2, -2, -2, -1)"
            || plane == "(-1, 1, 1, 1/2)"
            || plane == "(1, -1, -1, -1/2)",
        "{plane}"
    );
    assert_eq!(exact(&v, "kind"), "hyperboloid_one_sheet");
}

/// diag(1, 2, 3, 4) maps the unit sphere to x²/4 + y²/9 + z²/16 = 1.
#[test]
fn quadric_collineation_to_an_ellipsoid() {
    let v = build_json(
        "q_col",
        "[[object]]\nname = \"e\"\nop = \"quadric_collineation\"\ncollineation = [[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, 3, 0], [0, 0, 0, 4]]\nhomogeneous = true\npoints = [[1, 0, 0, -1], [1, 0, 1, -1], [2, 0, 2, 0]]\non_quadric = [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n",
        "e",
    );
    assert_eq!(exact(&v, "det"), "24");
    assert_eq!(
        exact(&v, "image_quadric"),
        "((-1, 0, 0, 0), (0, 1/4, 0, 0), (0, 0, 1/9, 0), (0, 0, 0, 1/16))"
    );
    refused(
        "q_col_sing",
        "[[object]]\nname = \"e\"\nop = \"quadric_collineation\"\ncollineation = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]\npoints = [[0, 0, 0], [1, 0, 0]]\n",
        &["collineation", "singular"],
    );
}

/// The δ-image of a bilinear patch is Miquel (Satz 7).
#[test]
fn quadric_miquel_points_of_a_delta_patch() {
    let v = build_json(
        "q_miq",
        "[[object]]\nname = \"m\"\nop = \"quadric_miquel_points\"\nhomogeneous = true\nnet = [[[1, 0, 0, -1], [1, 0, 1, -1], [2, 0, 2, 0]], [[1, 1, 0, -1], [\"3/2\", 1, 1, \"-3/2\"], [3, 0, 3, -1]], [[2, 2, 0, 0], [3, 3, 2, -1], [7, 2, 6, -3]]]\n",
        "m",
    );
    assert_eq!(exact(&v, "miquel"), "true");
    assert_eq!(exact(&v, "miquel_residual_1"), "0");
    assert_eq!(exact(&v, "miquel_residual_2"), "0");
}

/// Three points of the twisted cubic (t, t², t³) on z = xy at t = 0, 1/2, 1. By hand the
/// Segre factors u = (w, x) = (1, t) fit u of degree 1, and v = (w, y) ∥ (1, 0), (1, 1/4),
/// (1, 1) fit v = (3 − 2t, t) of degree 1: lowest (1, 1), a conic. A quartic takes
/// (2, 2), each solution space of dimension 2·3 − 3 = 3, so 2 + 2 free parameters.
#[test]
fn quadric_psi_interpolate_any_degree() {
    let v = build_json(
        "q_psi",
        "[[object]]\nname = \"p\"\nop = \"quadric_psi_interpolate\"\npoints = [[0, 0, 0], [\"1/2\", \"1/4\", \"1/8\"], [1, 1, 1]]\ndegree = 4\n",
        "p",
    );
    assert_eq!(exact(&v, "lowest_degrees"), "(1, 1)");
    assert_eq!(exact(&v, "degrees"), "(2, 2)");
    assert_eq!(exact(&v, "u_dimension"), "3");
    assert_eq!(exact(&v, "free_parameters"), "4");
    assert_eq!(v["degree"], 4);
    refused(
        "q_psi_low",
        "[[object]]\nname = \"p\"\nop = \"quadric_psi_interpolate\"\npoints = [[0, 0, 0], [\"1/2\", \"1/4\", \"1/8\"], [1, 1, 1]]\ndegree = 1\n",
        &["degree", "lowest degree"],
    );
}

/// (m; r) = ((1, 2, 3); 4): isotropic sphere (−7/2, −1, −2, −1/2), Möbius point
/// (−1/2, 1, 2, 3, −3/2) (hand values, Peternell (3.12), (2.13)); back from the Möbius
/// point: the two orientations.
#[test]
fn laguerre_models_of_a_cycle_and_a_plane() {
    let v = build_json(
        "l_cyc",
        "[[object]]\nname = \"c\"\nop = \"laguerre_models\"\ncycle = [1, 2, 3, 4]\n",
        "c",
    );
    assert_eq!(exact(&v, "isotropic_sphere"), "(-7/2, -1, -2, -1/2)");
    assert_eq!(exact(&v, "mobius_point"), "(-1/2, 1, 2, 3, -3/2)");
    let v = build_json(
        "l_mob",
        "[[object]]\nname = \"s\"\nop = \"laguerre_models\"\nmobius_point = [\"-1/2\", 1, 2, 3, \"-3/2\"]\n",
        "s_negative",
    );
    assert_eq!(exact(&v, "cycle"), "(1, 2, 3, -4)");
    // n = (2, 3, 6)/7, e0 = 5/3: Λ(e) = (2, 3, 35/3)
    let v = build_json(
        "l_pl",
        "[[object]]\nname = \"e\"\nop = \"laguerre_models\"\nplane = [\"5/3\", \"2/7\", \"3/7\", \"6/7\"]\n",
        "e",
    );
    assert_eq!(exact(&v, "isotropic_point"), "(2, 3, 35/3)");
    // and back from the isotropic point
    let v = build_json(
        "l_iso",
        "[[object]]\nname = \"e\"\nop = \"laguerre_models\"\nisotropic_point = [2, 3, \"35/3\"]\n",
        "e",
    );
    assert_eq!(exact(&v, "plane"), "(5/3, 2/7, 3/7, 6/7)");
    refused(
        "l_mob_irr",
        "[[object]]\nname = \"s\"\nop = \"laguerre_models\"\nmobius_point = [\"-1/2\", 0, 0, 0, \"-3/2\"]\n",
        &["mobius_point", "r² = 2"],
    );
    refused(
        "l_two",
        "[[object]]\nname = \"s\"\nop = \"laguerre_models\"\ncycle = [0, 0, 0, 1]\nplane = [0, 0, 0, 1]\n",
        &["exactly one"],
    );
}

/// An elliptic paraboloid touches the plane at infinity, so A = 4Q*₀₀ = 0 and the isotropic
/// function is rational; for the unit sphere A = −4.
#[test]
fn laguerre_isotropic_function_of_quadrics() {
    let v = build_json(
        "l_isoq",
        "[[object]]\nname = \"p\"\nop = \"laguerre_isotropic_quadric\"\nquadric = \"elliptic_paraboloid\"\ncoefficients = [1, 1]\n",
        "p",
    );
    assert_eq!(exact(&v, "A"), "0");
    assert_eq!(exact(&v, "rational"), "true");
    let v = build_json(
        "l_isos",
        "[[object]]\nname = \"s\"\nop = \"laguerre_isotropic_quadric\"\n",
        "s",
    );
    // unit sphere K = diag(1, −1, −1, −1) (Jüttler (5)): det K = −1, Q* = adj K = −K⁻¹ =
    // diag(−1, 1, 1, 1), A = 4·(−1) = −4
    assert_eq!(exact(&v, "A"), "-4");
    assert_eq!(exact(&v, "rational"), "false");
}

/// The boost with cosh = 5/4, sinh = 3/4 along x and the dilatation 1/2: the fixed cycle
/// solves (I − A)x = a: x = (−3/4, 0, 0, 1/4) (by hand: A x = (−3/4, 0, 0, −1/4)).
#[test]
fn laguerre_cycles_of_a_boost() {
    let v = build_json(
        "l_cycles",
        "[[object]]\nname = \"b\"\nop = \"laguerre_cycles\"\ncycles = [[1, 2, 3, 4]]\nshift = [0, 0, 0, \"1/2\"]\nmatrix = [[\"5/4\", 0, 0, \"3/4\"], [0, 1, 0, 0], [0, 0, 1, 0], [\"3/4\", 0, 0, \"5/4\"]]\n",
        "b",
    );
    // (1, 2, 3; 4) ↦ (5/4 + 3, 2, 3, 3/4 + 5 + 1/2) = (17/4, 2, 3, 25/4)
    assert_eq!(exact(&v, "images"), "((17/4, 2, 3, 25/4))");
    assert_eq!(exact(&v, "fixed_cycle"), "(-3/4, 0, 0, 1/4)");
    refused(
        "l_cycles_bad",
        "[[object]]\nname = \"b\"\nop = \"laguerre_cycles\"\ncycles = [[1, 2, 3, 4]]\nmatrix = [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]\n",
        &["matrix", "pe-orthogonal"],
    );
}

/// Farouki–Neff for p0 = 0, d0 = 1, p1 = 2/15 + 2/3 i, d1 = 2i (all complex): w0 = 1,
/// w2 = ±√(2i) = ±(1 + i). By hand for w2 = 1 + i: c1 = 3(w0 + w2) = 6 + 3i,
/// c0 = 3 + (1 + i) + 3·2i − 15Δp = 2 − 3i, discriminant 120Δp − 15(d0 + d1) + 10w0w2 =
/// 11 + 60i = (6 + 5i)², so w1 = (−(6 + 3i) ± (6 + 5i))/4 = i/2 or −3 − 2i.
#[test]
fn ph_planar_hermite_values() {
    let v = build_json(
        "h_planar",
        "[[object]]\nname = \"h\"\nop = \"ph_planar_hermite\"\np0 = [0, 0]\nd0 = [1, 0]\np1 = [\"2/15\", \"2/3\"]\nd1 = [0, 2]\n",
        "h",
    );
    assert_eq!(exact(&v, "solutions"), "4");
    assert_eq!(exact(&v, "quadratic_0"), "((2, -3), (6, 3), (2, 0))");
    assert_eq!(exact(&v, "discriminant_0"), "(11, 60)");
    assert_eq!(exact(&v, "w_0"), "((1, 0), (0, 1/2), (1, 1))");
    assert_eq!(exact(&v, "w_1"), "((1, 0), (-3, -2), (1, 1))");
    // every interpolant has the arc length ∫|w|² = 4/5 here; the energies are quadratures
    for k in 0..4 {
        assert_eq!(exact(&v, &format!("arc_length_{k}")), "4/5");
    }
    assert_eq!(exact(&v, "best_0"), "true");
}

/// The spatial Hermite member τ0 = τ2 = 0 reports its angles (cos, sin) = (1, 0) and the
/// exact arc length of its preimage.
#[test]
fn ph_spatial_hermite_values() {
    let v = build_json(
        "h_spatial",
        "[[object]]\nname = \"s\"\nop = \"ph_spatial_hermite\"\np0 = [0, 0, 0]\nd0 = [1, 0, 0]\np1 = [\"-1/15\", \"9/5\", \"-1/15\"]\nd1 = [-1, 2, 2]\ntau0 = 0\ntau2 = 0\n",
        "s",
    );
    assert_eq!(exact(&v, "rotation0"), "(1, 0)");
    assert_eq!(exact(&v, "arc_length"), "31/15");
}

/// `quadric_interpolate` matches tangent lines; the sense of the curve along each given
/// direction is returned. Quarter arc from (1, 0, 0) to (0, 0, 1) on the unit sphere with
/// tangents (0, 1, 0) and (0, −1, 0): the lowest-degree interpolant leaves along +y and
/// arrives moving along +y (against the second direction) — reported, not hidden.
#[test]
fn quadric_interpolate_reports_tangent_senses() {
    let o = build_json(
        "interp-senses",
        "[[object]]\nname = \"q\"\nop = \"quadric_interpolate\"\npoints = [[1, 0, 0], [0, 0, 1]]\ntangents = [[0, 1, 0], [0, -1, 0]]\n",
        "q",
    );
    assert_eq!(exact(&o, "tangent_senses"), "(1, -1)");
}

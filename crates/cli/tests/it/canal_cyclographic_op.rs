//! The `canal_surface` op's rational fallback: a quadratic family whose discriminant splits
//! only over Q(√d) is built over Q by the cyclographic parametrization Γ(s, t) (Gruber §2.3)
//! on the `cyclographic_domain` rectangle; without it the error says so at `radius`.

use rcagd_cli::build::build_recipe;
use rcagd_cli::recipe::Recipe;

const SPINE: &str = "[[object]]\nname = \"c\"\nop = \"canal_surface\"\npoints = [[0, 0, 0], [\"1/2\", 0, 0], [1, 0, 1]]\nradius = [0, 0, \"1/4\"]\n";

#[test]
fn a_quadratic_family_over_q_sqrt_15_is_built_by_gamma() {
    let text = format!("{SPINE}cyclographic_domain = [\"-1/2\", \"-1/8\", \"1/8\", \"1/2\"]\n");
    let recipe = Recipe::parse("t.toml", &text, None).expect("recipe parses");
    let objs = build_recipe(&recipe, |_| {}).expect("recipe builds");
    let o = &objs[0];
    crate::common::assert_exact_patches_certifying(o, "Gruber §2.3");
}

#[test]
fn without_a_rectangle_the_error_names_gamma_at_the_radius() {
    let recipe = Recipe::parse("t.toml", SPINE, None).expect("recipe parses");
    let d = build_recipe(&recipe, |_| {}).expect_err("must fail");
    assert_eq!(d[0].line, 5, "{}", d[0].message);
    assert!(
        d[0].message.contains("Q(√15)") && d[0].message.contains("cyclographic"),
        "{}",
        d[0].message
    );
    // a rectangle across the pole: located at cyclographic_domain (line 6)
    let text = format!("{SPINE}cyclographic_domain = [-1, \"-1/4\", \"1/8\", \"1/2\"]\n");
    let recipe = Recipe::parse("t.toml", &text, None).expect("recipe parses");
    let d = build_recipe(&recipe, |_| {}).expect_err("must fail");
    assert_eq!(d[0].line, 6, "{}", d[0].message);
    assert!(d[0].message.contains("pole"), "{}", d[0].message);
}

// ---------------------------------------------------------------------------------------
// `canal_surface_normal_field`: (2.10) with a given rational unit normal field.

const NF: &str = "[[object]]\nname = \"n\"\nop = \"canal_surface_normal_field\"\nspine = [[0, 0, 0], [1, 0, 0], [0, \"1/2\", 0]]\nradius = [0, 1]\n";

#[test]
fn a_rational_normal_field_gives_a_certified_canal_surface() {
    // m = (t, t²/2, 0), r = t, n₀ = (−1, 0, 0): ⟨n₀, ṁ⟩ + ṙ = −1 + 1 = 0
    let text = format!("{NF}normal = [[-1, 0, 0]]\ndomain = [\"1/4\", 1, -1, 1]\n");
    let recipe = Recipe::parse("t.toml", &text, None).expect("recipe parses");
    let objs = build_recipe(&recipe, |_| {}).expect("recipe builds");
    crate::common::assert_exact_patches_certifying(&objs[0], "every Bernstein weight");
    assert!(
        objs[0].certificates.len() >= 5,
        "{:#?}",
        objs[0].certificates
    );
}

#[test]
fn a_wrong_normal_field_is_refused_at_its_parameter() {
    for (normal, den, want, line) in [
        // not a unit field
        ("[[0, 2, 0]]", "[1]", "unit", 6),
        // a unit field off the circles of normals: ⟨n₀, ṁ⟩ + ṙ = 2
        ("[[1, 0, 0]]", "[1]", "circles of normals", 6),
        // the zero denominator
        ("[[-1, 0, 0]]", "[0]", "denominator", 7),
    ] {
        let text = format!("{NF}normal = {normal}\ndenominator = {den}\n");
        let recipe = Recipe::parse("t.toml", &text, None).expect("recipe parses");
        let d = build_recipe(&recipe, |_| {}).expect_err("must fail");
        assert_eq!(d[0].line, line, "{}", d[0].message);
        assert!(d[0].message.contains(want), "{}", d[0].message);
    }
    // spine coefficients of the wrong dimension
    let text = "[[object]]\nname = \"n\"\nop = \"canal_surface_normal_field\"\nspine = [[0, 0, 0, 0], [1, 0, 0, 0]]\nradius = [0, 1]\nnormal = [[-1, 0, 0]]\n";
    let recipe = Recipe::parse("t.toml", text, None).expect("recipe parses");
    let d = build_recipe(&recipe, |_| {}).expect_err("must fail");
    assert_eq!(d[0].line, 4, "{}", d[0].message);
}

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

//! Unit tests of `rcagd_cli::fuzz::gen` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::fuzz::gen::*;
use rcagd_cli::recipe::Recipe;

#[test]
fn the_generator_is_deterministic_and_every_op_has_a_seed() {
    for op in rcagd_cli::ops::all() {
        let s = seeds(op);
        assert!(!s.is_empty(), "{} has no seed", op.name);
        let a = generate(&mut Rng::for_case(7, 3), op, &s);
        let b = generate(&mut Rng::for_case(7, 3), op, &s);
        assert_eq!(a, b);
    }
}

#[test]
fn rendered_recipes_parse() {
    let op = rcagd_cli::ops::find("bezier_curve").unwrap();
    let s = seeds(op);
    for c in 0..200 {
        let case = generate(&mut Rng::for_case(1, c), op, &s);
        if case.category.starts_with("valid") {
            assert!(
                Recipe::parse("x.toml", &case.toml(), None).is_ok(),
                "{}",
                case.toml()
            );
        }
    }
}

//! Unit tests of `rcagd_cli::fuzz::float_check` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::build::{build_recipe_with, Arithmetic};
use rcagd_cli::fuzz::float_check::*;
use rcagd_cli::recipe::{Format, Recipe};

const HELIX_WITH_FEED: &str =
    include_str!("../../fuzz-corpus/ph_helix-float-mismatch-display-feed.toml");

/// The finding of the CI batch (seed 20261203, case 105): a `ph_helix` with `feed`
/// builds exactly, and the float path refuses its display objects by design; neither
/// the exclusion in [`comparable`] nor the refusal's message is a disagreement.
#[test]
fn the_refusal_of_display_objects_is_not_a_disagreement() {
    let recipe = Recipe::parse("fuzz.toml", HELIX_WITH_FEED, Some(Format::Toml)).unwrap();
    let exact = build_recipe_with(&recipe, Arithmetic::Exact, |_| {}).unwrap();
    assert!(!comparable(&recipe));
    assert_eq!(check("fuzz.toml", HELIX_WITH_FEED, &exact), None);
    // the float build itself ends with the documented refusal
    let err = build_recipe_with(&recipe, Arithmetic::Float, |_| {}).unwrap_err();
    assert!(
        err[0]
            .message
            .contains(rcagd_cli::float::DISPLAY_OBJECTS_REFUSED),
        "{}",
        err[0].message
    );
    // the curve alone is compared, and agrees
    let curve_only = HELIX_WITH_FEED
        .lines()
        .filter(|l| !l.starts_with("feed") && !l.starts_with("frame_length"))
        .collect::<Vec<_>>()
        .join("\n");
    let r2 = Recipe::parse("fuzz.toml", &curve_only, Some(Format::Toml)).unwrap();
    assert!(comparable(&r2));
    let exact2 = build_recipe_with(&r2, Arithmetic::Exact, |_| {}).unwrap();
    assert_eq!(check("fuzz.toml", &curve_only, &exact2), None);
}

//! Unit tests of `rcagd_cli::gallery` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_cli::gallery::*;
use rcagd_cli::model::Object;
use rcagd_cli::recipe::{Format, Recipe};
use std::time::Duration;

fn objects(src: &str) -> Vec<Object> {
    let r = Recipe::parse("r.toml", src, Some(Format::Toml)).expect("recipe");
    rcagd_cli::build::build_recipe(&r, |_| {}).expect("builds")
}

/// The gallery's export phase runs under its own work budget: an object whose
/// exporters take over a second (fuzz corpus `sphere_family_envelope-timeout-a083bd00fa6deeb5`:
/// builds in about 0.15 s CPU, its exporters took about 8 s until session 19 and about
/// 1 s since, most of it in the `f64` meshes and pictures) ends with the named error and
/// nothing is written; a small object is written under the same budget.
#[test]
fn the_export_phase_has_a_budget_and_writes_nothing_over_it() {
    let slow = objects(
        "[[object]]\nname = \"fz\"\nop = \"sphere_family_envelope\"\nnet = \"hyperbolic\"\n\
         points = [[1, 0, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1], [0, 1, 0, 0]]\n\
         a = [[0], [0], [1]]\nb = [[0, 0, 1]]\ndomain = [\"1/4\", 1, \"1/4\", 1]\n\
         spheres = 2\nother_sheet = true\ncombine = true\n",
    );
    let dir = std::env::temp_dir().join(format!("rcagd-gallery-budget-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("dir");
    let limit = Some(Duration::from_millis(300));
    let start = std::time::Instant::now();
    let e = write_all_within(&dir, &slow, limit, |_| {}).expect_err("over the budget");
    assert!(
        e.contains("work limit exceeded: exporting \"fz\" as JSON, STEP"),
        "{e}"
    );
    assert!(e.contains("nothing was written"), "{e}");
    assert!(
        start.elapsed() < Duration::from_secs(30),
        "{:?}",
        start.elapsed()
    );
    assert_eq!(
        std::fs::read_dir(&dir).expect("dir").count(),
        0,
        "nothing written"
    );
    let small = objects(
        "[[object]]\nname = \"c\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 2], [3, 1]]\n",
    );
    let errors = write_all_within(&dir, &small, limit, |_| {}).expect("written");
    assert!(errors.is_empty(), "{errors:?}");
    assert!(dir.join("c.step").exists() && dir.join("report.json").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

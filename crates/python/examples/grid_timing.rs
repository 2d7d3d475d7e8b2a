//! The Rust side of the Python overhead measurement (docs/plans/python.md,
//! "Measurements"): the torus recipe, and the same 1000 × 1000 grid of the sphere cover's first patch that
//! `rcagd.sphere_cover().evaluate_grid(t, t)` evaluates, by the library call itself.
//!
//! `cargo run --profile pywheel -p rcagd-python --features timing --example grid_timing`
//! (the wheel's profile, so both sides run the same optimized code).

use std::time::Instant;

fn main() -> Result<(), String> {
    let recipe = rcagd_cli::recipe::Recipe::parse(
        "r.toml",
        "[[object]]\nname = \"s\"\nop = \"sphere_cover\"\n",
        None,
    )
    .map_err(|d| rcagd_cli::source::render_all(&d))?;
    let objs = rcagd_cli::build::build_recipe(&recipe, |_| {})
        .map_err(|d| rcagd_cli::source::render_all(&d))?;
    let obj = objs.first().ok_or("no object")?;
    let patches = obj.geometry.patches_f64().map_err(|e| e.to_string())?;
    let patch = patches.first().ok_or("no patch")?;
    let t: Vec<f64> = (0..1000).map(|i| f64::from(i) / 999.0).collect();
    // a small construction: the torus recipe, parsed and built (what `rcagd.torus(2,
    // Fraction(1, 2))` runs)
    let torus =
        "[[object]]\nname = \"torus\"\nop = \"torus\"\nmajor_radius = 2\nminor_radius = \"1/2\"\n";
    let mut best = f64::INFINITY;
    for _ in 0..50 {
        let start = Instant::now();
        let r = rcagd_cli::recipe::Recipe::parse("r.toml", torus, None)
            .map_err(|d| rcagd_cli::source::render_all(&d))?;
        let built = rcagd_cli::build::build_recipe(&r, |_| {})
            .map_err(|d| rcagd_cli::source::render_all(&d))?;
        std::hint::black_box(&built);
        best = best.min(start.elapsed().as_secs_f64());
    }
    println!(
        "rust torus recipe parse + build: best of 50 {:.3} ms",
        best * 1e3
    );
    // a fresh output per call (what one evaluation costs a caller) and a reused one
    for reuse in [false, true] {
        let mut out = Vec::new();
        let mut best = f64::INFINITY;
        for _ in 0..20 {
            if !reuse {
                out = Vec::new();
            }
            let start = Instant::now();
            rcagd_geom::grid::eval_patch_grid_flat(patch, &t, &t, &mut out)
                .map_err(|e| e.to_string())?;
            best = best.min(start.elapsed().as_secs_f64());
            std::hint::black_box(&out);
        }
        let what = if reuse { "reused" } else { "fresh" };
        println!(
            "rust eval_patch_grid_flat 1000x1000, {what} output: best of 20 {:.2} ms",
            best * 1e3
        );
    }
    Ok(())
}

//! Integration tests of the `rcagd` binary: gallery, build (TOML, JSON, stdin),
//! output formats, exit codes, exact numbers, and located errors of every kind.

use crate::common::{bin, stderr, stdout, temp_dir, write};
use std::path::Path;
use std::process::{Output, Stdio};

fn build(path: &Path) -> Output {
    bin().arg("build").arg(path).output().expect("run rcagd")
}

/// Builds `text` written to a file called `name`; expects exit code 2 and an error at
/// `line:col` whose first line contains `needle`. Returns stderr.
fn expect_error(name: &str, text: &str, line: usize, col: usize, needle: &str) -> String {
    let dir = temp_dir(&format!("cli-err-{}", name.replace('.', "-")));
    let p = write(&dir, name, text);
    let o = build(&p);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{name}: {err}");
    let want = format!("{}:{line}:{col}: error: ", p.display());
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.starts_with(&want),
        "{name}: expected {want:?}, got:\n{err}"
    );
    assert!(
        first.contains(needle),
        "{name}: expected {needle:?} in:\n{err}"
    );
    assert!(stdout(&o).is_empty(), "nothing printed on error");
    assert!(!err.contains("panicked"), "{err}");
    err
}

const QUARTER_TOML: &str = r#"# a quarter circle
[[object]]
name = "quarter"
op = "circle_arc"
radius = 1
from = [1, 0]
to = [0, 1]
"#;

#[test]
fn gallery_writes_everything_and_all_certificates_hold() {
    // CI keeps this gallery (`RCAGD_GALLERY_OUT`, an absolute path) for its OpenCascade
    // and mesh checks instead of building it a second time
    let keep = std::env::var_os("RCAGD_GALLERY_OUT").map(std::path::PathBuf::from);
    let tmp = temp_dir("cli-gallery");
    let dir: &std::path::Path = match &keep {
        Some(k) => {
            let _ = std::fs::remove_dir_all(k);
            k
        }
        None => &tmp,
    };
    let o = bin()
        .args(["gallery", "--out"])
        .arg(dir)
        .output()
        .expect("run rcagd gallery");
    let out = stdout(&o);
    assert_eq!(
        o.status.code(),
        Some(0),
        "stdout:\n{out}\nstderr:\n{}",
        stderr(&o)
    );
    // The summary table.
    let header = out.lines().next().expect("table");
    for col in ["name", "op", "kind", "degree", "#cp", "certificates"] {
        assert!(header.contains(col), "{header}");
    }
    assert!(out.contains("all hold"), "{out}");
    // No progress bar when stderr is not a terminal.
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("report.json")).expect("report.json"),
    )
    .expect("report is JSON");
    assert_eq!(report["all_certificates_hold"], true);
    let objects = report["objects"].as_array().expect("objects");
    // Every object of every embedded recipe is in the report.
    let mut expected = Vec::new();
    for (file, text) in rcagd_cli::gallery::RECIPES {
        let r = rcagd_cli::recipe::Recipe::parse(file, text, None).expect("gallery recipe parses");
        expected.extend(r.objects.into_iter().map(|o| o.name));
    }
    assert!(!expected.is_empty());
    // An op may build several objects (e.g. a curve and its frame), never fewer than one.
    assert!(objects.len() >= expected.len());
    for name in &expected {
        let o = objects
            .iter()
            .find(|o| o["name"] == name.as_str())
            .unwrap_or_else(|| panic!("{name} missing from report.json"));
        assert_eq!(o["all_certificates_hold"], true, "{name}");
        assert!(
            !o["certificates"]
                .as_array()
                .expect("certificates")
                .is_empty(),
            "{name}"
        );
        assert!(out.contains(name.as_str()), "{name} missing from the table");
        for ext in ["json", "step", "igs", "obj", "svg"] {
            let f = dir.join(format!("{name}.{ext}"));
            let text =
                std::fs::read_to_string(&f).unwrap_or_else(|_| panic!("{} missing", f.display()));
            assert!(!text.is_empty(), "{} empty", f.display());
        }
        let png = std::fs::read(dir.join(format!("{name}.png"))).expect("png");
        assert!(
            png.starts_with(b"\x89PNG\r\n\x1a\n"),
            "{name}.png is not a PNG"
        );
        let j: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(dir.join(format!("{name}.json"))).expect("json"),
        )
        .expect("object json");
        assert_eq!(j["name"], name.as_str());
        assert!(j["control_points"].is_array(), "{name}");
    }
    // All objects in one STEP and one IGES file, named, read back by rcagd's readers
    // and restored exactly from the sidecar.
    let side: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("gallery-all.exact.json")).expect("sidecar"),
    )
    .expect("sidecar JSON");
    let step = std::fs::read_to_string(dir.join("gallery-all.step")).expect("step");
    let iges = std::fs::read_to_string(dir.join("gallery-all.igs")).expect("iges");
    for mut read in [
        rcagd_io::step_read::read_step(&step).expect("STEP reads"),
        rcagd_io::iges_read::read_iges(&iges).expect("IGES reads"),
    ] {
        let names: Vec<&str> = read.iter().map(|o| o.name.as_str()).collect();
        let built: Vec<&str> = objects
            .iter()
            .map(|o| o["name"].as_str().expect("name"))
            .collect();
        assert_eq!(names, built, "objects of the combined file");
        rcagd_io::step_read::apply_sidecar(&mut read, &side).expect("exact round trip");
    }
    // The report shows every object: a PNG render for surfaces, an inline SVG plot
    // for curves, and links to the files.
    let html = std::fs::read_to_string(dir.join("index.html")).expect("index.html");
    for o in objects {
        let name = o["name"].as_str().expect("name");
        assert!(html.contains(&format!("href=\"{name}.igs\"")), "{name}");
        assert!(
            html.contains(&format!("href=\"{name}.exact.json\"")),
            "{name}"
        );
        if o["kind"] == "patch" || o["kind"] == "patches" {
            assert!(html.contains(&format!("<img src=\"{name}.png\"")), "{name}");
        }
    }
    assert!(html.contains("href=\"gallery-all.step\""));
    closed_objects_arrive_closed(dir);
}

/// The closed gallery objects (examples/closed-objects.txt): one closed solid in STEP,
/// a watertight, consistently and outward wound OBJ mesh (checked on the files).
fn closed_objects_arrive_closed(dir: &std::path::Path) {
    let list = include_str!("../../../../examples/closed-objects.txt");
    let names: Vec<&str> = list
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .collect();
    assert!(names.len() >= 8);
    for name in names {
        let step = std::fs::read_to_string(dir.join(format!("{name}.step"))).expect("step");
        let count = |s: &str| step.matches(s).count();
        assert_eq!(count("MANIFOLD_SOLID_BREP("), 1, "{name}.step: one solid");
        assert_eq!(count("CLOSED_SHELL("), 1, "{name}.step: one closed shell");
        assert_eq!(count("OPEN_SHELL("), 0, "{name}.step: no open shell");
        let obj = std::fs::read_to_string(dir.join(format!("{name}.obj"))).expect("obj");
        let m = crate::common::obj_mesh(&obj);
        let a = rcagd_io::mesh::edge_census(&m);
        assert_eq!(a.boundary, 0, "{name}.obj: cracks");
        assert_eq!(
            a.non_manifold, 0,
            "{name}.obj: an edge in more than two triangles"
        );
        assert_eq!(a.repeated_directed, 0, "{name}.obj: inconsistent winding");
        assert!(
            a.volume > 0.0,
            "{name}.obj: wound inward (volume {})",
            a.volume
        );
    }
}

/// `--quiet` prints nothing; `--only` builds just the named recipes (one small recipe
/// here: the whole gallery is built once, by the test above).
#[test]
fn gallery_quiet_prints_nothing() {
    let dir = temp_dir("cli-gallery-quiet");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&dir)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).is_empty());
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("report.json")).expect("report.json"),
    )
    .expect("report is JSON");
    let (_, text) = rcagd_cli::gallery::RECIPES
        .iter()
        .find(|(f, _)| rcagd_cli::gallery::recipe_name(f) == "analysis")
        .expect("the analysis recipe");
    let recipe = rcagd_cli::recipe::Recipe::parse("analysis.toml", text, None).expect("parses");
    let names: Vec<&str> = report["objects"]
        .as_array()
        .expect("objects")
        .iter()
        .map(|o| o["name"].as_str().expect("name"))
        .collect();
    assert_eq!(
        names,
        recipe
            .objects
            .iter()
            .map(|o| o.name.as_str())
            .collect::<Vec<_>>()
    );
}

/// An unknown `--only` name is a usage error that lists the recipes; nothing is written.
#[test]
fn gallery_only_rejects_unknown_recipes() {
    let dir = temp_dir("cli-gallery-only");
    let out = dir.join("out");
    let o = bin()
        .args(["gallery", "--only", "pn,nosuch", "--out"])
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("\"nosuch\"") && err.contains("canal"), "{err}");
    assert!(!out.exists());
}

#[test]
fn build_toml_prints_exact_json() {
    let dir = temp_dir("cli-build-toml");
    let p = write(&dir, "r.toml", QUARTER_TOML);
    let o = build(&p);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("stdout is JSON");
    assert_eq!(v["all_certificates_hold"], true);
    let q = &v["objects"][0];
    assert_eq!(q["name"], "quarter");
    assert_eq!(q["op"], "circle_arc");
    assert_eq!(q["kind"], "curve");
    assert_eq!(q["degree"], 2);
    assert_eq!(
        q["control_points"],
        serde_json::json!([["1", "1", "0"], ["1", "1", "1"], ["2", "0", "2"]])
    );
    assert_eq!(
        q["params"]["center"],
        serde_json::json!(["0", "0"]),
        "defaults are echoed"
    );
}

#[test]
fn build_json_recipe_and_sniffing() {
    let dir = temp_dir("cli-build-json");
    let text = r#"{"object": [
  {"name": "c", "op": "circle", "center": [0.5, "-1"], "radius": "3/2"},
  {"name": "b", "op": "bezier_curve", "points": [[0, 0], [0.1, 1], [1, 0]]}
]}"#;
    for name in ["r.json", "r.recipe"] {
        let p = write(&dir, name, text);
        let o = build(&p);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
        let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("JSON");
        assert_eq!(v["objects"][0]["kind"], "curves");
        assert_eq!(
            v["objects"][0]["params"]["center"],
            serde_json::json!(["1/2", "-1"])
        );
        assert_eq!(
            v["objects"][1]["control_points"][1],
            serde_json::json!(["1", "1/10", "1"])
        );
    }
}

#[test]
fn decimals_are_exact() {
    let dir = temp_dir("cli-exact");
    let p = write(
        &dir,
        "r.toml",
        "[[object]]\nname = \"line\"\nop = \"bezier_curve\"\npoints = [[0.1, \"0.2\"], [\"1e-3\", -0.125]]\n",
    );
    let o = build(&p);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("JSON");
    let obj = &v["objects"][0];
    assert_eq!(
        obj["control_points"],
        serde_json::json!([["1", "1/10", "1/5"], ["1", "1/1000", "-1/8"]])
    );
    assert_eq!(
        obj["params"]["points"],
        serde_json::json!([["1/10", "1/5"], ["1/1000", "-1/8"]])
    );
    assert!(
        !stdout(&o).contains("0.1000000000000000055"),
        "never through f64"
    );
}

#[test]
fn build_writes_formats_to_out_dir() {
    let dir = temp_dir("cli-build-out");
    let p = write(&dir, "r.toml", QUARTER_TOML);
    let out = dir.join("out");
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(&out)
        .args([
            "--format",
            "json",
            "--format",
            "obj,svg",
            "--format",
            "step,iges",
        ])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for ext in ["json", "obj", "svg", "step", "igs"] {
        assert!(out.join(format!("quarter.{ext}")).exists(), "{ext}");
    }
    let svg = std::fs::read_to_string(out.join("quarter.svg")).expect("svg");
    assert!(svg.contains("<svg"), "{svg}");
    let obj = std::fs::read_to_string(out.join("quarter.obj")).expect("obj");
    assert!(obj.contains("\nv ") && obj.contains("\nl "), "{obj}");
    let step = std::fs::read_to_string(out.join("quarter.step")).expect("step");
    assert!(step.starts_with("ISO-10303-21;"), "{step}");
    assert!(step.contains("B_SPLINE_CURVE_WITH_KNOTS"), "{step}");
    // Mesh formats of a patch.
    let patch = write(
        &dir,
        "patch.toml",
        "[[object]]\nname = \"cyl\"\nop = \"cylinder_patch\"\nradius = 2\nfrom = [2, 0]\nto = [0, 2]\nz0 = 0\nz1 = 3\n",
    );
    let out4 = dir.join("out4");
    let o = bin()
        .arg("build")
        .arg(&patch)
        .arg("--out")
        .arg(&out4)
        .args(["--format", "stl,ply,gltf,obj"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for ext in ["stl", "ply", "glb", "obj"] {
        let bytes = std::fs::read(out4.join(format!("cyl.{ext}"))).expect("mesh file");
        assert!(bytes.len() > 100, "{ext}");
    }
    // A PNG render of a patch and of a curve.
    let o = bin()
        .arg("build")
        .arg(&patch)
        .arg("--out")
        .arg(&out4)
        .args(["--format", "png"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let png = std::fs::read(out4.join("cyl.png")).expect("png");
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    assert!(png.len() > 1000);
    // STL of a curve: the exporter's error, exit code 2.
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(dir.join("out5"))
        .args(["--format", "stl"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("no patches"), "{}", stderr(&o));
    // An object STEP cannot write (a coordinate beyond the f64 range) is an input error.
    let bad = write(
        &dir,
        "bad.toml",
        "[[object]]\nname = \"pole\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 1], [\"1e400\", 0]]\n",
    );
    let o = bin()
        .arg("build")
        .arg(&bad)
        .arg("--out")
        .arg(dir.join("out3"))
        .args(["--format", "step", "--max-magnitude", "500"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("pole.step"), "{}", stderr(&o));
    // All or nothing: JSON could be written but STEP cannot, so neither is, and the
    // output directory is not even created.
    let out6 = dir.join("out6");
    let o = bin()
        .arg("build")
        .arg(&bad)
        .arg("--out")
        .arg(&out6)
        .args(["--format", "json,step", "--max-magnitude", "500"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("nothing was written"), "{}", stderr(&o));
    assert!(!out6.exists(), "a failed build left {}", out6.display());
    // The same into an existing directory: it is left as it was.
    std::fs::create_dir_all(&out6).expect("mkdir");
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(&out6)
        .args(["--format", "json,stl"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let left: Vec<_> = std::fs::read_dir(&out6).expect("read dir").collect();
    assert!(left.is_empty(), "a failed build wrote {left:?}");
    // Default format: JSON only.
    let out2 = dir.join("out2");
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(&out2)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0));
    assert!(out2.join("quarter.json").exists());
    assert!(!out2.join("quarter.obj").exists());
}

/// A write that fails midway leaves the output directory as it was (files of the same
/// names keep their old contents, no partial files); two objects whose files would
/// collide are an error; output that cannot reach standard output is a failure.
#[test]
fn output_is_atomic_and_never_silently_lost() {
    let dir = temp_dir("cli-atomic");
    let p = write(&dir, "q.toml", QUARTER_TOML);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).expect("mkdir");
    std::fs::write(out.join("quarter.json"), "old").expect("old file");
    // the temporary file of the SVG cannot be created (a directory has its name)
    std::fs::create_dir_all(out.join(".quarter.svg.rcagd-partial")).expect("blocker");
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(&out)
        .args(["--format", "json,svg"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("the directory is as it was"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        std::fs::read_to_string(out.join("quarter.json")).expect("kept"),
        "old"
    );
    let mut left: Vec<String> = std::fs::read_dir(&out)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(left, [".quarter.svg.rcagd-partial", "quarter.json"]);
    // colliding outputs: `a` as exact NURBS and `a.exact` as JSON are both a.exact.json
    let coll = write(
        &dir,
        "coll.toml",
        &format!(
            "{QUARTER_TOML}\n{}",
            QUARTER_TOML.replace("\"quarter\"", "\"quarter.exact\"")
        ),
    );
    let o = bin()
        .arg("build")
        .arg(&coll)
        .arg("--out")
        .arg(dir.join("coll"))
        .args(["--format", "json,exact"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("would both be written to"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("coll").exists());
    // a full standard output
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        let o = bin()
            .arg("build")
            .arg(&p)
            .stdout(full)
            .output()
            .expect("run");
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("cannot write to standard output"),
            "{}",
            stderr(&o)
        );
    }
}

#[test]
fn build_from_stdin() {
    let mut child = bin()
        .args(["build", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    {
        use std::io::Write as _;
        let mut stdin = child.stdin.take().expect("stdin");
        stdin
            .write_all(QUARTER_TOML.as_bytes())
            .expect("write stdin");
    }
    let o = child.wait_with_output().expect("wait");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("\"quarter\""));
}

/// Bounded work: a recipe larger than `--max-recipe-bytes` (including an endless input,
/// which is read only up to the limit), with more objects than `--max-objects`, or with a
/// number longer than `--max-digits` digits is an input error (exit 2) that names the
/// limit and the option; the options raise the limits.
#[test]
fn recipe_limits_are_named_and_can_be_raised() {
    let dir = temp_dir("cli-limits");
    let long = write(
        &dir,
        "long.toml",
        &format!(
            "[[object]]\nname = \"c\"\nop = \"circle\"\ncenter = [0, 0]\nradius = \"{}/{}\"\n",
            "7".repeat(6000),
            "3".repeat(6000)
        ),
    );
    let o = build(&long);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("12000 digits") && stderr(&o).contains("--max-digits"),
        "{}",
        stderr(&o)
    );
    let o = bin()
        .arg("build")
        .arg(&long)
        .args(["--max-digits", "20000"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let many: String = (0..12)
        .map(|i| {
            format!("[[object]]\nname = \"c{i}\"\nop = \"circle\"\ncenter = [0, 0]\nradius = 1\n")
        })
        .collect();
    let many = write(&dir, "many.toml", &many);
    let o = bin()
        .arg("build")
        .arg(&many)
        .args(["--max-objects", "10"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("12 objects") && stderr(&o).contains("--max-objects"),
        "{}",
        stderr(&o)
    );
    assert_eq!(build(&many).status.code(), Some(0));
    let o = bin()
        .arg("build")
        .arg(&many)
        .args(["--max-recipe-bytes", "100"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("limit of 100 bytes") && stderr(&o).contains("--max-recipe-bytes"),
        "{}",
        stderr(&o)
    );
    // an endless input stops at the limit
    if Path::new("/dev/zero").exists() {
        let o = bin()
            .args(["build", "/dev/zero", "--max-recipe-bytes", "1000"])
            .output()
            .expect("run");
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("larger than the limit"),
            "{}",
            stderr(&o)
        );
    }
}

/// Weights whose weight function vanishes on [0, 1] (a pole) are an input error (exit
/// 2, located at `weights`, nothing on standard output), not a failing certificate: the
/// same rule for every op that takes weights (`rcagd_geom::weight_sign::curve_pole_free`).
/// Mixed signs without a zero, and all-negative weights, are accepted.
#[test]
fn weights_with_a_pole_are_an_input_error() {
    let dir = temp_dir("cli-pole");
    let curve = |w: &str| {
        format!("[[object]]\nname = \"c\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 1], [2, 0]]\nweights = {w}\n")
    };
    let p = write(&dir, "r.toml", &curve("[1, -1, 1]"));
    let o = build(&p);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.contains(&format!("{}:5:11", p.display())), "{err}");
    assert!(err.contains("vanishes at t = 1/2"), "{err}");
    assert!(stdout(&o).is_empty());
    for (i, w) in ["[1, -1, 2]", "[-1, -1, -2]"].iter().enumerate() {
        let p = write(&dir, &format!("ok{i}.toml"), &curve(w));
        let o = build(&p);
        assert_eq!(o.status.code(), Some(0), "{w}: {}", stderr(&o));
    }
    // subdivide follows the same rule
    let p = write(
        &dir,
        "sub.toml",
        "[[object]]\nname = \"s\"\nop = \"subdivide\"\npoints = [[0, 0], [1, 1], [2, 0]]\nweights = [1, -3, 1]\nat = \"1/2\"\n",
    );
    let o = build(&p);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn usage_errors_exit_2() {
    let o = bin().arg("frobnicate").output().expect("run");
    assert_eq!(o.status.code(), Some(2));
    let o = bin().args(["build"]).output().expect("run");
    assert_eq!(o.status.code(), Some(2));
    let o = bin()
        .args(["build", "no/such/recipe.toml"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("cannot read the recipe"),
        "{}",
        stderr(&o)
    );
    let dir = temp_dir("cli-usage");
    let p = write(&dir, "r.toml", QUARTER_TOML);
    let o = bin()
        .arg("build")
        .arg(&p)
        .args(["--format", "obj"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "obj without --out");
    let o = bin()
        .arg("build")
        .arg(&p)
        .args(["--format", "pdf"])
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2));
    // An output directory that cannot be created.
    let blocker = write(&dir, "blocker", "a file, not a directory");
    let o = bin()
        .arg("gallery")
        .arg("--out")
        .arg(blocker.join("sub"))
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("cannot create directory"),
        "{}",
        stderr(&o)
    );
    let o = bin()
        .arg("build")
        .arg(&p)
        .arg("--out")
        .arg(blocker.join("sub"))
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let o = bin().arg("--help").output().expect("run");
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("gallery"));
}

#[test]
fn ops_lists_every_op() {
    let o = bin().arg("ops").output().expect("run");
    assert_eq!(o.status.code(), Some(0));
    let text = stdout(&o);
    for op in rcagd_cli::ops::all() {
        assert!(text.contains(op.name), "{} missing", op.name);
        for p in op.params {
            assert!(
                text.contains(&format!("{}: {}", p.name, p.kind.type_name())),
                "{}.{}",
                op.name,
                p.name
            );
        }
    }
    let o = bin().args(["ops", "circle_arc"]).output().expect("run");
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("example:"));
    assert!(stdout(&o).contains("op = \"circle_arc\""));
    let o = bin().args(["ops", "circle_ark"]).output().expect("run");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("did you mean \"circle_arc\""),
        "{}",
        stderr(&o)
    );
}

// ---- located errors, one per kind ----------------------------------------------

#[test]
fn toml_syntax_error() {
    expect_error(
        "syntax.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = [1, 2\n",
        4,
        15,
        "TOML syntax error",
    );
}

#[test]
fn json_syntax_error() {
    expect_error(
        "syntax.json",
        "{\"object\": [\n  {\"name\": \"a\", \"op\": \"circle\", \"radius\": 1,}\n]}",
        2,
        45,
        "JSON syntax error: trailing comma",
    );
    expect_error(
        "syntax2.json",
        "{\"object\": [\n  {\"name\": \"a\" \"op\": 1}]}",
        2,
        16,
        "expected ',' or '}' after an object member",
    );
    expect_error(
        "syntax3.json",
        "{\"object\": [\n  {\"name\" 1}]}",
        2,
        11,
        "expected ':' after the key \"name\"",
    );
}

#[test]
fn unknown_op_suggests() {
    let err = expect_error(
        "unknown-op.toml",
        "[[object]]\nname = \"a\"\nop = \"circl_arc\"\nradius = 1\n",
        3,
        6,
        "unknown op \"circl_arc\"",
    );
    assert!(err.contains("did you mean \"circle_arc\"?"), "{err}");
    assert!(err.contains("known ops:"), "{err}");
}

#[test]
fn missing_parameter_lists_expected() {
    let err = expect_error(
        "missing.toml",
        "# comment\n\n[[object]]\nname = \"a\"\nop = \"circle_arc\"\nradius = 1\nfrom = [1, 0]\n",
        3,
        1,
        "needs the parameter `to` (point [x, y])",
    );
    assert!(err.contains("parameters of `circle_arc`:"), "{err}");
    assert!(err.contains("radius: number (required)"), "{err}");
    assert!(
        err.contains("center: point [x, y] (default [0, 0])"),
        "{err}"
    );
    // JSON: at the object's brace.
    expect_error(
        "missing.json",
        "{\"object\": [\n   {\"name\": \"a\", \"op\": \"circle\"}]}",
        2,
        4,
        "needs the parameter `radius`",
    );
}

#[test]
fn unknown_parameter() {
    let err = expect_error(
        "unknown-param.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = 1\n  centre = [0, 0]\n",
        5,
        3,
        "unknown parameter `centre` for op `circle`",
    );
    assert!(err.contains("did you mean `center`?"), "{err}");
    assert!(err.contains("radius: number (required)"), "{err}");
}

#[test]
fn wrong_type() {
    expect_error(
        "type.toml",
        "[[object]]\nname = \"a\"\nop = \"circle_arc\"\nradius = 1\nfrom = [1, 0]\nto = [0, 1]\nclockwise = \"no\"\n",
        7,
        13,
        "parameter `clockwise`: expected a boolean (true or false), found a string \"no\"",
    );
    expect_error(
        "type.json",
        "{\"object\": [{\"name\": \"a\", \"op\": \"circle\",\n \"radius\": [1]}]}",
        2,
        12,
        "expected a number, found an array",
    );
}

#[test]
fn not_a_number_shows_text() {
    expect_error(
        "nan.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = \"1/x\"\n",
        4,
        10,
        "not a number: \"1/x\"",
    );
    expect_error(
        "inf.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = inf\n",
        4,
        10,
        "not a number: `inf`",
    );
    expect_error(
        "nan.json",
        "{\"object\": [{\"name\": \"a\", \"op\": \"circle\", \"center\": [0, \"zero\"], \"radius\": 1}]}",
        1,
        57,
        "not a number: \"zero\"",
    );
}

#[test]
fn wrong_array_length() {
    expect_error(
        "len.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = 1\ncenter = [0, 0, 0]\n",
        5,
        10,
        "expected a point [x, y], found an array of 3 elements",
    );
    expect_error(
        "ragged.toml",
        "[[object]]\nname = \"a\"\nop = \"bezier_curve\"\npoints = [[0, 0], [1, 1, 1]]\n",
        4,
        19,
        "point 1: expected a point [x, y], found an array of 3 elements",
    );
}

#[test]
fn construction_error_points_at_op_key() {
    let err = expect_error(
        "construct.toml",
        "[[object]]\nname = \"a\"\n  op = \"circle_arc\"\nradius = 1\nfrom = [1, 0]\nto = [1, 1]\n",
        3,
        3,
        "cannot build \"a\" (op `circle_arc`)",
    );
    assert!(err.contains("not on the circle"), "{err}");
    expect_error(
        "radius.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = -1\n",
        3,
        1,
        "radius must be positive",
    );
}

#[test]
fn duplicate_names() {
    let err = expect_error(
        "dup.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = 1\n\n[[object]]\nname = \"a\"\nop = \"circle\"\nradius = 2\n",
        7,
        8,
        "duplicate object name \"a\"",
    );
    assert!(err.contains("line 2, column 8"), "{err}");
}

#[test]
fn all_errors_are_reported_at_once() {
    let dir = temp_dir("cli-many");
    let p = write(
        &dir,
        "r.toml",
        "[[object]]\nname = \"a\"\nop = \"circle\"\nradius = \"x\"\n\n[[object]]\nname = \"b\"\nop = \"nope\"\n",
    );
    let o = build(&p);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains(":4:10: error:"), "{err}");
    assert!(err.contains(":8:6: error:"), "{err}");
    assert!(err.contains("2 errors"), "{err}");
}

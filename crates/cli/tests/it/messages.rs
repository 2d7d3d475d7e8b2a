//! The CLI's input and output reliability (issue 19, item 2): `gallery --out` checked
//! before building and written all or nothing, bounded error output, and the smaller
//! messages (zero denominator, a recipe whose extension chose the wrong format, empty
//! lists).

use crate::common::{bin, stderr, temp_dir, write};

/// Every entry of `dir`, sorted (names only).
fn listing(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// An output directory that cannot be written is refused before the build, with exit 2
/// and a message naming it; a path below a regular file cannot be created.
#[test]
fn gallery_refuses_an_unwritable_out_before_building() {
    let dir = temp_dir("messages-gallery-unwritable");
    let file = write(&dir, "plain-file", "x");
    let below = file.join("sub");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&below)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&below.display().to_string()),
        "{}",
        stderr(&o)
    );
    // /proc/self exists but nobody (root included) can create a file in it
    if cfg!(target_os = "linux") {
        let t = std::time::Instant::now();
        let o = bin()
            .args(["gallery", "--quiet", "--out", "/proc/self"])
            .output()
            .expect("run");
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let e = stderr(&o);
        assert!(
            e.contains("cannot write into the output directory /proc/self"),
            "{e}"
        );
        // refused before building the whole gallery (which takes minutes in debug)
        assert!(t.elapsed().as_secs() < 20, "{:?}", t.elapsed());
    }
}

/// A gallery write that fails (here: the temporary of `index.html`, the last file, is a
/// directory in the way) leaves the directory as it was: no new file, no temporary, an
/// old file of a gallery name unchanged; the same run into a clean directory writes
/// everything and leaves no temporary behind.
#[test]
fn gallery_writes_all_or_nothing() {
    let dir = temp_dir("messages-gallery-atomic");
    let out = dir.join("g");
    std::fs::create_dir_all(out.join(".index.html.rcagd-partial")).expect("mkdir");
    std::fs::write(out.join("report.json"), "old").expect("write");
    let before = listing(&out);
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("index.html"), "{}", stderr(&o));
    assert!(stderr(&o).contains("nothing was written"), "{}", stderr(&o));
    assert_eq!(listing(&out), before);
    assert_eq!(
        std::fs::read_to_string(out.join("report.json")).expect("read"),
        "old"
    );
    // the way cleared, the same run writes every file and no temporary
    std::fs::remove_dir(out.join(".index.html.rcagd-partial")).expect("rmdir");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&out)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let after = listing(&out);
    assert!(
        after.iter().all(|f| !f.contains("rcagd-partial")),
        "{after:?}"
    );
    for f in ["index.html", "report.json", "gallery-all.step"] {
        assert!(after.iter().any(|x| x == f), "{f} missing: {after:?}");
    }
    assert_ne!(
        std::fs::read_to_string(out.join("report.json")).expect("read"),
        "old"
    );
    // a fresh directory (created by the run) gets the same files
    let fresh = dir.join("fresh");
    let o = bin()
        .args(["gallery", "--quiet", "--only", "analysis", "--out"])
        .arg(&fresh)
        .output()
        .expect("run");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(listing(&fresh).len(), after.len());
}

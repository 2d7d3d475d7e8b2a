//! The report: `report.json` and a self-contained `index.html`.
//!
//! `index.html` needs no server and no network: styles are inline, pictures are either
//! inlined SVG or relative links to files next to it (PNG renders of surfaces). One
//! card per object shows its picture, op, parameters, degree, control-point count,
//! certificates (with holds / FAILS badges and residuals) and links to its files; the
//! header may link files of the whole report ([`report_html_with`]).
//!
//! `report.json` is
//!
//! ```json
//! { "generator": "rcagd 0.1.0", "all_certificates_hold": true,
//!   "object_count": 3, "certificate_count": 40, "failed_certificate_count": 0,
//!   "objects": [ { …object summary…, "files": [{"label": "STEP", "path": "quarter.step"}] } ] }
//! ```
//!
//! with the object summaries of [`crate::json::object_summary_json`].

use crate::json::object_summary_json;
use crate::model::Object;
use crate::svg::escape_xml;
use crate::IoError;
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

/// A file written for an object, linked from the report.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileLink {
    /// What it is (`"STEP"`, `"OBJ"`, `"SVG"`, `"JSON"`).
    pub label: String,
    /// The path relative to the report directory (use `/` separators).
    pub path: String,
}

/// One object of the report.
#[derive(Debug, Clone, PartialEq)]
pub struct ReportEntry {
    /// The object.
    pub object: Object,
    /// An SVG picture to inline into the card (the text of an `<svg>` element).
    pub svg: Option<String>,
    /// A picture file (PNG) beside the report, relative path; shown instead of the
    /// inline SVG when set.
    pub picture: Option<String>,
    /// The object's files.
    pub files: Vec<FileLink>,
}

impl ReportEntry {
    /// An entry without picture and files.
    pub fn new(object: Object) -> Self {
        ReportEntry {
            object,
            svg: None,
            picture: None,
            files: Vec::new(),
        }
    }

    /// Sets the picture file (a relative path, e.g. `"torus.png"`), shown in the card
    /// in place of the inline SVG.
    pub fn with_picture(mut self, path: impl Into<String>) -> Self {
        self.picture = Some(path.into());
        self
    }

    /// Sets the inline picture.
    pub fn with_svg(mut self, svg: impl Into<String>) -> Self {
        self.svg = Some(svg.into());
        self
    }

    /// Adds a file link.
    pub fn with_file(mut self, label: impl Into<String>, path: impl Into<String>) -> Self {
        self.files.push(FileLink {
            label: label.into(),
            path: path.into(),
        });
        self
    }
}

/// The content of `report.json` (module docs).
pub fn report_json(entries: &[ReportEntry]) -> Value {
    let objects: Vec<Value> = entries
        .iter()
        .map(|e| {
            let mut v = object_summary_json(&e.object);
            if let Value::Object(map) = &mut v {
                let files: Vec<Value> = e
                    .files
                    .iter()
                    .map(|f| json!({"label": f.label, "path": f.path}))
                    .collect();
                map.insert("files".into(), Value::Array(files));
            }
            v
        })
        .collect();
    let certs: usize = entries.iter().map(|e| e.object.certificates.len()).sum();
    let failed: usize = entries
        .iter()
        .map(|e| e.object.failed_certificate_count())
        .sum();
    json!({
        "generator": concat!("rcagd ", env!("CARGO_PKG_VERSION")),
        "all_certificates_hold": failed == 0,
        "object_count": entries.len(),
        "certificate_count": certs,
        "failed_certificate_count": failed,
        "objects": objects,
    })
}

const STYLE: &str = r#"
:root { --ink:#202124; --muted:#5f6368; --line:#dadce0; --ok:#1e8449; --okbg:#e6f4ea; --bad:#b3261e; --badbg:#fce8e6; }
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; color: var(--ink); background: #f6f7f9; }
header { padding: 20px 28px; background: #fff; border-bottom: 1px solid var(--line); }
header h1 { margin: 0 0 4px; font-size: 22px; }
header p { margin: 0; color: var(--muted); }
main { display: grid; grid-template-columns: repeat(auto-fill, minmax(360px, 1fr)); gap: 18px; padding: 22px 28px; }
.card { background: #fff; border: 1px solid var(--line); border-radius: 10px; overflow: hidden; display: flex; flex-direction: column; }
.card.failed { border-color: var(--bad); }
.pic { display: flex; justify-content: center; align-items: center; background: #fff; border-bottom: 1px solid var(--line); padding: 8px; min-height: 120px; }
.pic svg, .pic img { max-width: 100%; height: auto; }
.body { padding: 12px 16px 16px; }
.body h2 { margin: 0 0 6px; font-size: 17px; display: flex; justify-content: space-between; gap: 8px; align-items: baseline; }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 2px 12px; margin: 8px 0; font-size: 14px; }
dt { color: var(--muted); }
dd { margin: 0; }
code { font: 12.5px/1.4 ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; word-break: break-word; }
.badge { display: inline-block; padding: 0 8px; border-radius: 999px; font-size: 12px; font-weight: 600; white-space: nowrap; }
.badge.ok { color: var(--ok); background: var(--okbg); }
.badge.bad { color: var(--bad); background: var(--badbg); }
.badge.kind { color: var(--muted); background: #f1f3f4; font-weight: 500; }
details { margin-top: 6px; }
summary { cursor: pointer; font-size: 14px; }
ul.certs { list-style: none; padding: 0; margin: 6px 0 0; font-size: 13px; }
ul.certs li { padding: 4px 0; border-top: 1px solid #f1f3f4; }
.residual { color: var(--bad); display: block; margin-left: 4px; }
.files a { margin-right: 10px; }
footer { padding: 0 28px 24px; color: var(--muted); font-size: 13px; }
"#;

fn badge(holds: bool, ok: &str, bad: &str) -> String {
    if holds {
        format!(r#"<span class="badge ok">{ok}</span>"#)
    } else {
        format!(r#"<span class="badge bad">{bad}</span>"#)
    }
}

/// Strips an XML declaration / doctype so an SVG document can be inlined into HTML.
fn inline_svg(svg: &str) -> &str {
    svg.find("<svg").map_or(svg, |i| &svg[i..])
}

fn card(e: &ReportEntry) -> String {
    let o = &e.object;
    let ok = o.all_certificates_hold();
    let mut s = String::new();
    let _ = write!(
        s,
        r#"<section class="card{}">"#,
        if ok { "" } else { " failed" }
    );
    let svg_file = e
        .files
        .iter()
        .find(|f| f.path.to_ascii_lowercase().ends_with(".svg"));
    match (&e.picture, &e.svg, svg_file) {
        (Some(path), _, _) | (None, None, Some(FileLink { path, .. })) => {
            let _ = write!(
                s,
                r#"<div class="pic"><img src="{}" alt="{}" loading="lazy"></div>"#,
                escape_xml(path),
                escape_xml(&o.name)
            );
        }
        (None, Some(svg), _) => {
            let _ = write!(s, r#"<div class="pic">{}</div>"#, inline_svg(svg));
        }
        (None, None, None) => {}
    }
    let n = o.certificates.len();
    let failed = o.failed_certificate_count();
    let _ = write!(
        s,
        r#"<div class="body"><h2><span>{}</span>{}</h2>"#,
        escape_xml(&o.name),
        badge(
            ok,
            &format!("{n} certificate{} hold", if n == 1 { "" } else { "s" }),
            &format!("{failed} of {n} FAIL")
        )
    );
    let params = serde_json::to_string(&o.params).unwrap_or_default();
    let _ = write!(
        s,
        "<dl><dt>op</dt><dd><code>{}</code> <span class=\"badge kind\">{}</span></dd>\
         <dt>params</dt><dd><code>{}</code></dd>\
         <dt>degree</dt><dd>{}</dd>\
         <dt>control points</dt><dd>{} (homogeneous, dimension {})</dd></dl>",
        escape_xml(&o.op),
        o.kind(),
        escape_xml(&params),
        escape_xml(&o.degree_summary()),
        o.control_point_count(),
        o.geometry.dim()
    );
    if !o.values.is_empty() {
        s.push_str("<details open><summary>Values</summary><dl class=\"values\">");
        for v in &o.values {
            let _ = write!(
                s,
                "<dt><code>{}</code></dt><dd><code>{}</code>",
                escape_xml(&v.name),
                escape_xml(&v.value.to_string())
            );
            if let Some(x) = v.value.to_f64() {
                let _ = write!(s, " ≈ {x}");
            }
            let _ = write!(s, " <span class=\"doc\">{}</span></dd>", escape_xml(&v.doc));
        }
        s.push_str("</dl></details>");
    }
    if n > 0 {
        let _ = write!(
            s,
            "<details{}><summary>Certificates: {}</summary><ul class=\"certs\">",
            if ok { "" } else { " open" },
            if ok {
                format!("all {n} hold")
            } else {
                format!("{failed} of {n} fail")
            }
        );
        for c in &o.certificates {
            let _ = write!(
                s,
                "<li>{} <span class=\"badge kind\">{}</span> {}",
                badge(c.holds, "holds", "FAILS"),
                if c.exact { "exact" } else { "f64" },
                escape_xml(&c.property)
            );
            if let Some(r) = &c.residual {
                let _ = write!(
                    s,
                    r#"<span class="residual">residual: <code>{}</code></span>"#,
                    escape_xml(r)
                );
            }
            s.push_str("</li>");
        }
        s.push_str("</ul></details>");
    }
    if !e.files.is_empty() {
        s.push_str(r#"<p class="files">"#);
        for f in &e.files {
            let _ = write!(
                s,
                r#"<a href="{}">{}</a>"#,
                escape_xml(&f.path),
                escape_xml(&f.label)
            );
        }
        s.push_str("</p>");
    }
    s.push_str("</div></section>");
    s
}

/// The self-contained `index.html` (module docs).
pub fn report_html(entries: &[ReportEntry]) -> String {
    report_html_with(entries, &[])
}

/// [`report_html`] with links to files of the whole report in its header (e.g. one
/// STEP file holding every object).
pub fn report_html_with(entries: &[ReportEntry], links: &[FileLink]) -> String {
    let certs: usize = entries.iter().map(|e| e.object.certificates.len()).sum();
    let failed: usize = entries
        .iter()
        .map(|e| e.object.failed_certificate_count())
        .sum();
    let mut s = String::new();
    s.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">");
    s.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">");
    s.push_str("<title>rcagd report</title><style>");
    s.push_str(STYLE);
    s.push_str("</style></head><body><header><h1>rcagd report ");
    s.push_str(&badge(
        failed == 0,
        "all certificates hold",
        &format!(
            "{failed} certificate{} FAIL",
            if failed == 1 { "" } else { "s" }
        ),
    ));
    let _ = write!(
        s,
        "</h1><p>{} object{}, {certs} certificate{} ({} exact). Exact rational geometry: \
         homogeneous control points <code>(w, wx, wy[, wz])</code>; exact certificates are \
         decided in exact rational arithmetic (polynomial identities over Q). Data: <a href=\"report.json\">report.json</a>{}.</p></header><main>",
        entries.len(),
        if entries.len() == 1 { "" } else { "s" },
        if certs == 1 { "" } else { "s" },
        entries
            .iter()
            .flat_map(|e| &e.object.certificates)
            .filter(|c| c.exact)
            .count(),
        links.iter().fold(String::new(), |mut acc, f| {
            let _ = write!(
                acc,
                r#", <a href="{}">{}</a>"#,
                escape_xml(&f.path),
                escape_xml(&f.label)
            );
            acc
        })
    );
    for e in entries {
        s.push_str(&card(e));
        s.push('\n');
    }
    s.push_str("</main><footer>Generated by rcagd ");
    s.push_str(env!("CARGO_PKG_VERSION"));
    s.push_str(".</footer></body></html>\n");
    s
}

fn write_file(path: &Path, contents: &str) -> Result<(), IoError> {
    std::fs::write(path, contents).map_err(|source| IoError::Write {
        path: path.to_path_buf(),
        source,
    })
}

/// Writes `report.json` and `index.html` into `dir` (created if missing).
///
/// # Errors
/// [`IoError::CreateDir`] / [`IoError::Write`] on file-system failures,
/// [`IoError::Json`] if serialization fails.
pub fn write_report(dir: &Path, entries: &[ReportEntry]) -> Result<(), IoError> {
    write_report_with(dir, entries, &[])
}

/// [`write_report`] with header links to files of the whole report
/// ([`report_html_with`]; also listed as `"files"` in `report.json`).
///
/// # Errors
/// As [`write_report`].
pub fn write_report_with(
    dir: &Path,
    entries: &[ReportEntry],
    links: &[FileLink],
) -> Result<(), IoError> {
    std::fs::create_dir_all(dir).map_err(|source| IoError::CreateDir {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut json = report_json(entries);
    if let Value::Object(map) = &mut json {
        if !links.is_empty() {
            let files = links
                .iter()
                .map(|f| json!({"label": f.label, "path": f.path}))
                .collect();
            map.insert("files".into(), Value::Array(files));
        }
    }
    let json = serde_json::to_string_pretty(&json)?;
    write_file(&dir.join("report.json"), &(json + "\n"))?;
    write_file(&dir.join("index.html"), &report_html_with(entries, links))
}

//! The rule "library first" (docs/ARCHITECTURE.md): an op reads its parameters, calls one
//! library function and wraps the result; no polynomial arithmetic under
//! `crates/cli/src/ops/`.
//!
//! The test scans every `crates/cli/src/ops/*.rs` except `poly_io.rs` (the one module that
//! reads coefficient lists into polynomials and writes polynomials as values) after
//! removing comments, string and character literals and the `#[cfg(test)]` module at the
//! end of a file. It refuses:
//!
//! 1. the polynomial types by name — `Poly`, `MPoly`, `BiPoly` — and the algebra's
//!    polynomial modules (`rcagd_algebra::{poly, mpoly, bernstein, roots, resultant,
//!    factor, factor_ext, plane_positivity, sum_of_squares}`, `rcagd::canal::bipoly`): an op
//!    cannot construct a polynomial (no `Poly::new`, `MPoly::monomial`, …), annotate one
//!    for arithmetic, or call root finding, resultants, factorization or basis changes;
//! 2. associated functions of `poly_io`'s type aliases (`PolyT::`, `MPolyQ::`,
//!    `PolyMatrix4::`): the aliases name types in signatures only;
//! 3. the polynomial-only methods (`.derivative(`, `.integrate(`, `.compose_poly(`,
//!    `.reverse_u(`, `.map_scalar(`, `.partial_t(`, `.partial_u(`, `.at_t(`, `.div_rem(`,
//!    `.div_exact(`, `.gcd(`, `.pseudo_rem(`, `.substitute(`, `.coeffs()`, `.all_coeffs()`,
//!    `.terms()`, `.bernstein_on(`).
//!
//! What a text scan cannot see: operators (`&a * &b`) and `.eval(` on a polynomial that a
//! library function returned (the names are shared with points, frames and maps). The rule
//! keeps those rare — without the types an op can only hold a polynomial the library gave
//! it — and review does the rest (docs/plans/library-first.md lists what remains).

use std::path::Path;

const ALLOWED_FILE: &str = "poly_io.rs";

const FORBIDDEN_WORDS: &[&str] = &["Poly", "MPoly", "BiPoly"];

const FORBIDDEN_PATHS: &[&str] = &[
    "rcagd_algebra::poly",
    "rcagd_algebra::mpoly",
    "rcagd_algebra::bernstein",
    "rcagd_algebra::roots",
    "rcagd_algebra::resultant",
    "rcagd_algebra::factor",
    "rcagd_algebra::plane_positivity",
    "rcagd_algebra::sum_of_squares",
    "rcagd::canal::bipoly",
    "PolyT::",
    "MPolyQ::",
    "PolyMatrix4::",
];

const FORBIDDEN_METHODS: &[&str] = &[
    ".derivative(",
    ".integrate(",
    ".compose_poly(",
    ".reverse_u(",
    ".map_scalar(",
    ".partial_t(",
    ".partial_u(",
    ".at_t(",
    ".div_rem(",
    ".div_exact(",
    ".gcd(",
    ".pseudo_rem(",
    ".substitute(",
    ".coeffs()",
    ".all_coeffs()",
    ".terms()",
    ".bernstein_on(",
];

/// The code of a Rust source without comments, string/char literals (replaced by a space)
/// and without everything from the first `#[cfg(test)]` on.
fn code_only(src: &str) -> String {
    let src = match src.find("#[cfg(test)]") {
        Some(i) => &src[..i],
        None => src,
    };
    let b: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < b.len() && b[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            i += 2;
            while i + 1 < b.len() && !(b[i] == '*' && b[i + 1] == '/') {
                i += 1;
            }
            i += 2;
            out.push(' ');
        } else if c == 'r' && (next == Some('#') || next == Some('"')) && !prev_is_ident(&b, i) {
            // raw string r#"…"#
            let mut j = i + 1;
            let mut hashes = 0;
            while b.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if b.get(j) != Some(&'"') {
                out.push(c);
                i += 1;
                continue;
            }
            j += 1;
            loop {
                if j >= b.len() {
                    break;
                }
                if b[j] == '"' && (0..hashes).all(|h| b.get(j + 1 + h) == Some(&'#')) {
                    j += 1 + hashes;
                    break;
                }
                j += 1;
            }
            i = j;
            out.push(' ');
        } else if c == '"' {
            i += 1;
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push(' ');
        } else if c == '\'' {
            // a char literal ('x', '\n', '\''), else a lifetime
            if next == Some('\\') {
                let mut j = i + 2;
                while j < b.len() && b[j] != '\'' {
                    j += 1;
                }
                i = j + 1;
                out.push(' ');
            } else if b.get(i + 2) == Some(&'\'') {
                i += 3;
                out.push(' ');
            } else {
                out.push(c);
                i += 1;
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

fn prev_is_ident(b: &[char], i: usize) -> bool {
    i > 0 && (b[i - 1].is_alphanumeric() || b[i - 1] == '_')
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Every violation of the rule in `src` as `line: text (what)`.
fn violations(src: &str) -> Vec<String> {
    let code = code_only(src);
    let mut out = Vec::new();
    for (n, line) in code.lines().enumerate() {
        let mut found: Vec<String> = Vec::new();
        for w in FORBIDDEN_WORDS {
            let mut from = 0;
            while let Some(k) = line[from..].find(w) {
                let s = from + k;
                let e = s + w.len();
                let before = line[..s].chars().next_back();
                let after = line[e..].chars().next();
                if !before.is_some_and(is_ident) && !after.is_some_and(is_ident) {
                    found.push(format!("the type `{w}`"));
                }
                from = e;
            }
        }
        for p in FORBIDDEN_PATHS {
            if line.contains(p) {
                found.push(format!("`{p}`"));
            }
        }
        for m in FORBIDDEN_METHODS {
            if line.contains(m) {
                found.push(format!("`{m}`"));
            }
        }
        for f in found {
            out.push(format!("{}: {} ({f})", n + 1, line.trim()));
        }
    }
    out
}

#[test]
fn no_polynomial_arithmetic_in_ops() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ops");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("ops dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    files.sort();
    assert!(
        files.len() >= 15,
        "found only {} op files in {}",
        files.len(),
        dir.display()
    );
    let mut report = Vec::new();
    for f in &files {
        let name = f.file_name().and_then(|n| n.to_str()).unwrap_or_default();
        if name == ALLOWED_FILE {
            continue;
        }
        let src = std::fs::read_to_string(f).expect("read op file");
        for v in violations(&src) {
            report.push(format!("ops/{name}:{v}"));
        }
    }
    assert!(
        report.is_empty(),
        "polynomial construction or arithmetic in an op (move it to the library crate that owns \
         the concept, or — for reading coefficient lists / writing values — to ops/poly_io.rs):\n{}",
        report.join("\n")
    );
}

#[test]
fn the_scanner_sees_violations_and_ignores_comments_and_strings() {
    let bad = "use rcagd_algebra::Poly;\nfn f(v: Vec<Q>) -> Q {\n    let p = Poly::new(v);\n    p.derivative().eval(&q)\n}\n";
    let v = violations(bad);
    assert_eq!(v.len(), 3, "{v:?}");
    assert!(v[0].starts_with("1:") && v[1].starts_with("3:") && v[2].starts_with("4:"));
    assert_eq!(
        violations("let r = rcagd_algebra::roots::rational_roots(&p);").len(),
        1
    );
    assert_eq!(violations("let x = MPolyQ::zero(2);").len(), 1);
    assert_eq!(violations("let m = b.reverse_u(3);").len(), 1);
    let fine = "// Poly::new in a comment\nlet s = \"Poly::new(v).derivative()\";\nlet r = r#\"MPoly \"# ;\nlet c = '\"'; let d = Poly_ish + PolyT;\nfn g<'a>(x: &'a PolyT) {}\n#[cfg(test)]\nmod tests { use rcagd_algebra::Poly; }\n";
    assert_eq!(violations(fine), Vec::<String>::new());
}

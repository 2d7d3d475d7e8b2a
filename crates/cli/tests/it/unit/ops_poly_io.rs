//! Unit tests of `rcagd_cli::ops::poly_io` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

use rcagd_algebra::mpoly::MPoly;
use rcagd_algebra::Rational as Q;
use rcagd_cli::ops::poly_io::*;

fn q(n: i64) -> Q {
    Q::from(n)
}

#[test]
fn grid_and_list_agree_with_monomial_sums() {
    let g = vec![vec![q(1), q(0), q(2)], vec![q(-3)]];
    let mut sum = MPoly::zero(2);
    for (i, row) in g.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            sum = &sum + &MPoly::monomial(2, &[i as u32, j as u32], c.clone());
        }
    }
    assert_eq!(grid_mpoly(&g).unwrap(), sum);
    let l = list_mpoly(&[q(1), q(0), q(5)], 2).unwrap();
    assert_eq!(
        l,
        grid_mpoly(&[vec![q(1)], vec![q(0)], vec![q(5)]]).unwrap()
    );
    let t = list_mpolys(&[vec![q(2), q(3)]]).unwrap();
    assert_eq!(
        t[0],
        &MPoly::constant(1, q(2)) + &MPoly::monomial(1, &[1], q(3))
    );
}

#[test]
fn terms_are_summed_per_index() {
    let terms = vec![
        (0, vec![q(1), q(1)]),
        (1, vec![q(2), q(0)]),
        (0, vec![q(3), q(1)]),
    ];
    let p = indexed_terms_mpolys(&terms, 2, 1, "a").unwrap();
    assert_eq!(p[0], MPoly::monomial(1, &[1], q(4)));
    assert_eq!(p[1], MPoly::constant(1, q(2)));
    assert!(terms_mpoly(&[vec![q(1)]], 1, "a").is_err());
    assert!(terms_mpoly(&[vec![q(1), q(1) / q(2)]], 1, "a").is_err());
}

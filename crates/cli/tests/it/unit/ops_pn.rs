//! Unit tests of `rcagd_cli::ops::pn` (moved out of the library so that `cargo test`
//! does not compile the library a second time as a test harness; docs/ARCHITECTURE.md, "Tests").

type Q = rcagd_algebra::Rational;

use rcagd_cli::model::{Geometry, Object};
use rcagd_cli::ops::{OpArgs, OpError, OpSpec};
use rcagd_cli::value::Value;

fn q(p: i64, d: i64) -> Q {
    Q::from(p) / Q::from(d)
}
fn nums(xs: &[(i64, i64)]) -> Value {
    Value::Numbers(xs.iter().map(|&(p, d)| q(p, d)).collect())
}
fn grid(rows: &[&[i64]]) -> Value {
    Value::Grid(
        rows.iter()
            .map(|r| r.iter().map(|&x| Q::from(x)).collect())
            .collect(),
    )
}
fn run(op: &'static OpSpec, values: Vec<(&'static str, Value)>) -> Result<Vec<Object>, OpError> {
    (op.build)(&OpArgs::new("t", op, values))
}

/// The developable ops: the cubic's edge with an offset edge; a cylinder has no edge
/// of regression and an interval through D = 0 is blamed on `interval`; a motion
/// whose moved planes stay a one-parameter family is blamed on `translation`.
#[test]
fn developable_edge_and_motion_ops() {
    let cubic = || {
        Value::Grid(vec![
            vec![q(0, 1), q(1, 1), q(0, 1), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(1, 1), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(0, 1), q(1, 3)],
        ])
    };
    let objs = run(
        spec("pn_developable_edge"),
        vec![
            ("curve", cubic()),
            ("interval", nums(&[(1, 1), (3, 2)])),
            ("distances", nums(&[(1, 4)])),
        ],
    )
    .expect("edge");
    assert_eq!(objs.len(), 2);
    assert!(objs.iter().all(|o| o.certificates.iter().all(|c| c.holds)));
    let e = run(
        spec("pn_developable_edge"),
        vec![("curve", cubic()), ("interval", nums(&[(1, 2), (1, 1)]))],
    )
    .expect_err("D = 3t⁴ − 1 vanishes in [1/2, 1]");
    assert_eq!(e.param, Some("interval"));
    let cylinder = grid(&[&[0, 1], &[0, 0], &[0, 0, 1]]);
    let e = run(spec("pn_developable_edge"), vec![("curve", cylinder)]).expect_err("cylinder");
    assert_eq!(e.param, Some("curve"));
    assert!(e.message.contains("cylinder"), "{}", e.message);
    // the foot-point form of pn_developable has the higher degree and is certified too
    let foot = run(
        spec("pn_developable"),
        vec![
            ("curve", cubic()),
            ("domain", nums(&[(1, 2), (1, 1), (1, 4), (2, 1)])),
            ("form", Value::Str("foot".into())),
        ],
    )
    .expect("foot form");
    assert!(foot[0].certificates.iter().all(|c| c.holds));
    // a parabolic cylinder (rulings ∥ z) turned about z: the moved planes are all
    // vertical, a one-parameter family
    let par = Value::Grid(vec![
        vec![q(0, 1), q(0, 1), q(2, 1), q(0, 1), q(0, 1)],
        vec![q(0, 1), q(-1, 1), q(0, 1), q(1, 1), q(0, 1)],
        vec![q(-1, 1), q(0, 1), q(-2, 1), q(0, 1), q(-1, 1)],
    ]);
    let e = run(
        spec("pn_developable_motion"),
        vec![
            ("curve", par.clone()),
            ("denominator", nums(&[(0, 1), (1, 1), (0, 1), (1, 1)])),
            ("axis", Value::Str("z".into())),
            ("translation", grid(&[&[0], &[0], &[0]])),
        ],
    )
    .expect_err("developable envelope");
    assert_eq!(e.param, Some("translation"));
    let objs = run(
        spec("pn_developable_motion"),
        vec![
            ("curve", par),
            ("denominator", nums(&[(0, 1), (1, 1), (0, 1), (1, 1)])),
            ("axis", Value::Str("x".into())),
            (
                "translation",
                Value::Grid(vec![vec![q(0, 1), q(-1, 4)], vec![q(0, 1)], vec![q(0, 1)]]),
            ),
            ("domain", nums(&[(3, 2), (4, 1), (-6, 5), (6, 5)])),
            ("distances", nums(&[(1, 2)])),
        ],
    )
    .expect("§4.6 example");
    assert_eq!(objs.len(), 2);
    assert!(objs.iter().all(|o| o.certificates.iter().all(|c| c.holds)));
}

/// `pn_cone_motion`: touching cycles span no cone (blamed on `cycle2`); translations
/// only give a developable envelope; a bad cycle is blamed on its parameter.
#[test]
fn cone_motion_op_errors() {
    let pt = |xs: &[(i64, i64)]| Value::Point(xs.iter().map(|&(p, d)| q(p, d)).collect());
    let base = |c2: &[(i64, i64)], axis: &str, tr: Value| {
        vec![
            ("cycle1", pt(&[(0, 1), (0, 1), (0, 1), (0, 1)])),
            ("cycle2", pt(c2)),
            ("axis", Value::Str(axis.into())),
            ("translation", tr),
            ("domain", nums(&[(1, 4), (3, 4), (1, 4), (3, 4)])),
        ]
    };
    let par = || grid(&[&[0, 1, 0], &[0, 0, 1], &[0, 0, 0]]);
    let ok = run(
        spec("pn_cone_motion"),
        base(&[(5, 1), (0, 1), (0, 1), (3, 1)], "z", par()),
    )
    .expect("Cor. 4.4");
    assert!(ok[0].certificates.iter().all(|c| c.holds));
    let e = run(
        spec("pn_cone_motion"),
        base(&[(5, 1), (0, 1), (0, 1), (5, 1)], "z", par()),
    )
    .expect_err("touching cycles");
    assert_eq!(e.param, Some("cycle2"));
    assert!(e.message.contains("isotropic"), "{}", e.message);
    // the cone's axis is z, the rotation about z: every cone is a translate
    let e = run(
        spec("pn_cone_motion"),
        base(&[(0, 1), (0, 1), (5, 1), (3, 1)], "z", par()),
    )
    .expect_err("developable");
    assert!(e.message.contains("developable"), "{}", e.message);
    let e = run(
        spec("pn_cone_motion"),
        base(&[(5, 1), (0, 1), (3, 1)], "z", par()),
    )
    .expect_err("three numbers");
    assert_eq!(e.param, Some("cycle2"));
}

/// `pn_ruled_cyclographic`: a developable ruled surface of R⁴ and timelike rulings are
/// named errors on `ruling`; three rows are an error too.
#[test]
fn ruled_cyclographic_op_errors() {
    let l = || grid(&[&[0, 1], &[0, 0], &[0, 0], &[0, 0]]);
    let ok = run(
        spec("pn_ruled_cyclographic"),
        vec![
            (
                "directrix",
                grid(&[&[0, 1, 0], &[0, 0, 0], &[0, 0, 0], &[0, 0, 1]]),
            ),
            ("ruling", grid(&[&[0, 0], &[5, 0], &[0, 1], &[3, 0]])),
            ("domain", nums(&[(1, 4), (3, 4), (1, 4), (3, 4)])),
        ],
    )
    .expect("Cor. 4.1");
    assert!(ok[0].certificates.iter().all(|c| c.holds));
    // g constant and l a line: developable
    let e = run(
        spec("pn_ruled_cyclographic"),
        vec![
            ("directrix", l()),
            ("ruling", grid(&[&[1], &[1], &[0], &[0]])),
        ],
    )
    .expect_err("developable");
    assert_eq!(e.param, Some("ruling"));
    assert!(e.message.contains("developable"), "{}", e.message);
    // timelike rulings ⟨g, g⟩ = 1 + t² − 4 < 0 near t = 0: no real image over Q(t)
    let e = run(
        spec("pn_ruled_cyclographic"),
        vec![
            ("directrix", l()),
            ("ruling", grid(&[&[0, 0], &[1, 0], &[0, 1], &[2, 0]])),
        ],
    )
    .expect_err("timelike");
    assert_eq!(e.param, Some("ruling"));
    let e = run(
        spec("pn_ruled_cyclographic"),
        vec![
            ("directrix", grid(&[&[0, 1], &[0, 0], &[0, 0]])),
            ("ruling", l()),
        ],
    )
    .expect_err("three rows");
    assert_eq!(e.param, Some("directrix"));
}

/// F = u² + v² is the isotropic sphere of the cycle ((0, 0, −1); −1): its offset at
/// d = 1 collapses to a point — reported on `distances` with the parameter point;
/// d = 1/4 is fine and gives a second object.
#[test]
fn degenerate_offset_distance_blames_distances() {
    let base = || {
        vec![
            ("coefficients", grid(&[&[0, 0, 1], &[0, 0, 0], &[1, 0, 0]])),
            ("domain", nums(&[(0, 1), (1, 2), (0, 1), (1, 2)])),
        ]
    };
    let mut ok = base();
    ok.push(("distances", nums(&[(1, 4)])));
    let objs = run(spec("pn_graph"), ok).expect("regular offset");
    assert_eq!(objs.len(), 2);
    assert_eq!(objs[1].name, "t_offset1");
    assert!(objs.iter().all(|o| o.certificates.iter().all(|c| c.holds)));
    let mut bad = base();
    bad.push(("distances", nums(&[(1, 4), (1, 1)])));
    let e = run(spec("pn_graph"), bad).expect_err("d = 1 degenerates");
    assert_eq!(e.param, Some("distances"));
    assert!(e.message.contains("(0, 0)"), "{}", e.message);
}

/// `orientation = "negative"` flips the unit normal: the exported surface is the same,
/// its offset at d is the positive orientation's offset at −d (and not at +d). For
/// the pipe of radius 1/2 around the parabola (t, t², 0), the offsets at d = 1/4 have radius
/// 3/4 (positive) and 1/4 (negative: the family (m; −r)).
#[test]
fn negative_orientation_flips_the_normal() {
    let str_val = |s: &str| Value::Str(s.to_string());
    let ruled = |orient: &str, d: (i64, i64)| {
        run(
            spec("pn_ruled"),
            vec![
                ("directrix", grid(&[&[0, 1], &[0, 0], &[0, 0]])),
                ("ruling", grid(&[&[0, 0], &[1, 0], &[0, 1]])),
                ("domain", nums(&[(1, 4), (1, 1), (1, 4), (1, 1)])),
                ("distances", nums(&[d])),
                ("orientation", str_val(orient)),
            ],
        )
        .expect("ruled")
    };
    let pos = ruled("positive", (1, 4));
    let neg = ruled("negative", (-1, 4));
    assert!(pos
        .iter()
        .chain(&neg)
        .all(|o| o.certificates.iter().all(|c| c.holds)));
    assert_eq!(pos[0].geometry, neg[0].geometry);
    assert_eq!(pos[1].geometry, neg[1].geometry);
    assert_ne!(pos[1].geometry, ruled("negative", (1, 4))[1].geometry);
    // the isotropic graph: same for pn_graph
    let graph = |orient: &str, d: (i64, i64)| {
        run(
            spec("pn_graph"),
            vec![
                ("coefficients", grid(&[&[1, 0, 1], &[0, -1, 0], &[2, 0, 0]])),
                ("domain", nums(&[(0, 1), (1, 2), (0, 1), (1, 2)])),
                ("distances", nums(&[d])),
                ("orientation", str_val(orient)),
            ],
        )
        .expect("graph")
    };
    assert_eq!(
        graph("negative", (1, 3))[1].geometry,
        graph("positive", (-1, 3))[1].geometry
    );
    assert_ne!(
        graph("negative", (1, 3))[1].geometry,
        graph("positive", (1, 3))[1].geometry
    );
    // the pipe: the offset radius is |r ± d|
    let pipe = |orient: &str| {
        let objs = run(
            spec("pn_canal"),
            vec![
                ("spine", grid(&[&[0, 1, 0], &[0, 0, 1], &[0, 0, 0]])),
                ("radius", nums(&[(1, 2)])),
                ("domain", nums(&[(1, 4), (1, 1), (1, 4), (3, 4)])),
                ("distances", nums(&[(1, 4)])),
                ("orientation", str_val(orient)),
            ],
        )
        .expect("pipe");
        assert!(objs.iter().all(|o| o.certificates.iter().all(|c| c.holds)));
        let Geometry::Patch(p) = &objs[1].geometry else {
            panic!("a patch")
        };
        let x = p.eval(&q(1, 9), &q(2, 7)).expect("point");
        // local 1/9 is the family parameter t = 1/4 + (3/4)/9 = 1/3:
        // spine point m = (1/3, 1/9, 0)
        let m = [q(1, 3), q(1, 9), q(0, 1)];
        (0..3)
            .map(|k| (x[k].clone() - m[k].clone()) * (x[k].clone() - m[k].clone()))
            .fold(q(0, 1), |a, b| a + b)
    };
    assert_eq!(pipe("positive"), q(9, 16));
    assert_eq!(pipe("negative"), q(1, 16));
}

/// The planar analogue: F = t² is the circle of radius −1; the offset at d = 1 has a
/// cusp (here: collapses), reported on `distances` with the parameter.
#[test]
fn planar_cusp_blames_distances() {
    let vals = |d: (i64, i64)| {
        vec![
            ("function", nums(&[(0, 1), (0, 1), (1, 1)])),
            ("interval", nums(&[(-1, 1), (1, 1)])),
            ("distances", nums(&[d])),
        ]
    };
    assert_eq!(run(spec("pn_planar"), vals((1, 2))).expect("fine").len(), 2);
    let e = run(spec("pn_planar"), vals((1, 1))).expect_err("cusp");
    assert_eq!(e.param, Some("distances"));
    assert!(e.message.contains("t = "), "{}", e.message);
}

/// Data the §4.4 scheme cannot match, a developable ruled surface and a non-regular
/// domain are errors located at the right parameter.
#[test]
fn construction_errors_are_located() {
    let pt = |x: [(i64, i64); 3]| x.iter().map(|&(p, d)| q(p, d)).collect::<Vec<Q>>();
    let model = |n0: [(i64, i64); 3]| {
        vec![
            (
                "points",
                Value::Points(vec![
                    pt([(0, 1), (0, 1), (0, 1)]),
                    pt([(-4, 5), (0, 1), (-2, 5)]),
                    pt([(0, 1), (-2, 5), (-1, 5)]),
                ]),
            ),
            (
                "normals",
                Value::Points(vec![
                    pt(n0),
                    pt([(4, 5), (0, 1), (-3, 5)]),
                    pt([(0, 1), (4, 5), (-3, 5)]),
                ]),
            ),
            (
                "triangles",
                Value::Points(vec![pt([(0, 1), (1, 1), (2, 1)])]),
            ),
        ]
    };
    assert!(run(spec("pn_model"), model([(0, 1), (0, 1), (-1, 1)])).is_ok());
    let e = run(spec("pn_model"), model([(0, 1), (0, 1), (1, 1)])).expect_err("n = (0,0,1)");
    assert_eq!(e.param, Some("normals"));
    let e = run(spec("pn_model"), model([(1, 1), (1, 1), (0, 1)])).expect_err("not unit");
    assert_eq!(e.param, Some("normals"));
    // a circular cone l = 0, g = (2t, 1 − t², 1 + t²) is developable
    let e = run(
        spec("pn_ruled"),
        vec![
            ("directrix", grid(&[&[0], &[0], &[0]])),
            ("ruling", grid(&[&[0, 2, 0], &[1, 0, -1], &[1, 0, 1]])),
            ("domain", nums(&[(0, 1), (1, 1), (0, 1), (1, 1)])),
        ],
    )
    .expect_err("developable");
    assert_eq!(e.param, Some("ruling"));
    // the cubic graph F = 1 + v²/2 − uv + u³/3 has parabolic (singular) points in
    // [−1/2, 1/2]²: reported on `coefficients`
    let e = run(
        spec("pn_graph"),
        vec![
            (
                "coefficients",
                Value::Grid(vec![
                    vec![q(1, 1), q(0, 1), q(1, 2)],
                    vec![q(0, 1), q(-1, 1), q(0, 1)],
                    vec![q(0, 1); 3],
                    vec![q(1, 3), q(0, 1), q(0, 1)],
                ]),
            ),
            ("domain", nums(&[(-1, 2), (1, 2), (-1, 2), (1, 2)])),
        ],
    )
    .expect_err("singular");
    assert_eq!(e.param, Some("coefficients"));
    let e = run(
        spec("pn_ellipsoid"),
        vec![
            ("a", Value::Number(q(3, 1))),
            ("b", Value::Number(q(2, 1))),
            ("c", Value::Number(q(1, 1))),
            ("domain", nums(&[(1, 4), (3, 4), (-1, 1), (1, 1)])),
        ],
    )
    .expect_err("irrational μ");
    assert_eq!(e.param, Some("c"));
    // a loft with too few samples, and a normal field that is not a unit field
    let row = |xs: &[i64]| xs.iter().map(|&x| Q::from(x)).collect::<Vec<Q>>();
    let loft = |samples: i64, n3: i64| {
        vec![
            (
                "curve0",
                Value::Grid(vec![row(&[1]), row(&[0]), row(&[1, 1]), row(&[0])]),
            ),
            (
                "normal0",
                Value::Grid(vec![row(&[1]), row(&[0]), row(&[0]), row(&[n3])]),
            ),
            (
                "curve1",
                Value::Grid(vec![row(&[1]), row(&[1]), row(&[1, 1]), row(&[0])]),
            ),
            (
                "normal1",
                Value::Grid(vec![row(&[1]), row(&[0]), row(&[0]), row(&[-1])]),
            ),
            ("samples", Value::Int(samples)),
        ]
    };
    assert_eq!(
        run(spec("pn_loft"), loft(1, -1))
            .expect_err("samples")
            .param,
        Some("samples")
    );
    assert_eq!(
        run(spec("pn_loft"), loft(3, 2))
            .expect_err("not unit")
            .param,
        Some("normal0")
    );
}

/// The registry's op of this name (the op statics are private to the library).
fn spec(name: &str) -> &'static OpSpec {
    rcagd_cli::ops::find(name).expect("a registered op")
}

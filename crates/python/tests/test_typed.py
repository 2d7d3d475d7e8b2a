"""The typed constructions: exact and float input, compared with the CLI (same exact
control points, same certificates) and with each other (f64 agreement)."""

import json
from fractions import Fraction as F

import numpy as np
import pytest

import rcagd

# (function, op, exact keyword arguments, float keyword arguments or None: the exact
# ones with every number turned into a float; EXACT_ONLY: no float data fit)
EXACT_ONLY = "exact only"
CASES = [
    (rcagd.circle_arc, "circle_arc", dict(radius=5, from_=(5, 0), to=(3, 4)), None),
    (rcagd.quadric_interpolate, "quadric_interpolate",
     dict(points=[[1, 0, 0], [0, 1, 0], [0, 0, 1], [F(3, 5), 0, F(-4, 5)]]), None),
    (rcagd.quadric_curve_image, "quadric_curve_image",
     dict(points=[[0, 0, 0], [1, 2, 0], [2, -1, 1], [3, 1, 2]]), None),
    (rcagd.sphere_cover, "sphere_cover", dict(center=(0, 0, 1), radii=(1, 2, 3)), None),
    (rcagd.ph_curve, "ph_curve", dict(quaternions=[[1, 0, 1, 0], [0, 1, 0, 1]]), None),
    (rcagd.ph_planar_curve, "ph_planar_curve", dict(preimage=[[1, 0], [1, 1]]), None),
    (rcagd.ph_planar_offset, "ph_planar_offset",
     dict(preimage=[[1, 0], [1, 1]], distance=F(-1, 4)), None),
    (rcagd.ph_planar_hermite, "ph_planar_hermite",
     dict(p0=(0, 0), d0=(1, 0), p1=(F(2, 15), F(2, 3)), d1=(0, 2)),
     dict(p0=(0.0, 0.0), d0=(1.0, 0.0), p1=(0.125, 0.75), d1=(0.0, 2.0))),
    (rcagd.ph_spatial_hermite, "ph_spatial_hermite",
     dict(p0=(0, 0, 0), d0=(1, 0, 0), p1=(F(-1, 15), F(9, 5), F(-1, 15)), d1=(-1, 2, 2),
          tau0=0, tau2=0),
     dict(p0=(0.0, 0.0, 0.0), d0=(1.0, 0.0, 0.0), p1=(-0.0625, 1.75, -0.0625),
          d1=(-1.0, 2.0, 2.0), tau0=0.0, tau2=0.0)),
    (rcagd.ph_hermite, "ph_hermite",
     dict(p_s=(0, 0, 0), d_s=(1, 0, 1), p_f=(1, 1, 1), d_f=(0, 1, 1)), None),
    (rcagd.ph_planar_spline, "ph_planar_spline",
     dict(points=[[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]]), None),
    (rcagd.ph_helix, "ph_helix",
     dict(a0=[1, 0], a1=[1, 1], b0=[1, -1], b1=[0, 1], f=[1, 2, 2, 1], g=[1, 2, 3, 3]), None),
    (rcagd.ph_dph_septic, "ph_dph_septic",
     dict(h=[1], w=[[1, 0], [1, 1], [0, 1]], alpha0=[1, 0], alpha1=[0, 2], beta0=[0, 1]),
     None),
    (rcagd.canal_blend_spheres, "canal_blend_spheres",
     dict(center0=[0, 0, 0], radius0=1, normal0=[F(29, 10), F(14, 5), 0], offset0=F(1, 2),
          center1=[F(21, 10), F(11, 5), 0], radius1=F(1, 2),
          normal1=[F(29, 10), F(14, 5), 0], offset1=F(1, 4), lambda0=1, lambda1=1), None),
    (rcagd.cyclide_blend, "cyclide_blend",
     dict(sphere1=[2, 0, 0, 1], direction1=[1, 0, 0, 0], sphere2=[0, 2, 0, 1],
          direction2=[0, 1, 0, 0]), None),
    (rcagd.canal_surface, "canal_surface",
     dict(points=[[0, 0, 0], [0, 2, 0], [4, 4, 0]], radius=[F(1, 2), F(81, 50)]), None),
    (rcagd.pipe, "pipe",
     dict(radius=F(1, 5), points=[[1, 0, 0], [1, 1, 0], [0, 1, 0]], weights=[1, 1, 2]), None),
    (rcagd.pipe_ph, "pipe_ph",
     dict(coefficients=[[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]], radius=F(1, 8)), None),
    (rcagd.torus, "torus", dict(major_radius=2, minor_radius=F(1, 2)), None),
    (rcagd.dupin_cyclide, "dupin_cyclide",
     dict(center=[0, 0, 0, 4], u=[1, 0, 0, 0], v=[0, F(5, 4), 0, F(3, 4)], rho=4), None),
    (rcagd.pn_graph, "pn_graph",
     dict(coefficients=[[1, 0, F(1, 2)], [0, -1, 0], [0, 0, 0], [F(1, 3), 0, 0]],
          domain=[0, F(1, 2), 0, F(1, 2)], distances=[F(1, 4)]), None),
    (rcagd.pn_support, "pn_support",
     dict(support=[[2, 0], [0, 0], [0, 1]], domain=[0, F(1, 2), 0, F(1, 2)],
          distances=[F(1, 2)]), None),
    (rcagd.pn_model, "pn_model",
     dict(points=[[0, 0, 0], [F(-4, 5), 0, F(-2, 5)], [0, F(-2, 5), F(-1, 5)],
                  [F(-3, 4), F(-1, 4), F(-1, 2)]],
          normals=[[0, 0, -1], [F(4, 5), 0, F(-3, 5)], [0, F(4, 5), F(-3, 5)],
                   [F(2, 3), F(2, 3), F(-1, 3)]],
          triangles=[[0, 1, 3], [0, 3, 2]]),
     # the data are samples of one PN surface with exact unit normals such as
     # (2/3, 2/3, −1/3), which no float represents
     EXACT_ONLY),
    (rcagd.pn_ellipsoid, "pn_ellipsoid",
     dict(a=F(25, 3), b=5, c=3, domain=[F(1, 4), F(1, 2), 0, F(1, 2)], distances=[1]),
     # floats: an ellipsoid whose semi-axes are binary fractions and meet the conditions
     dict(a=1.0, b=0.5, c=0.25, domain=[0.25, 0.5, 0.0, 0.5], distances=[0.125])),
    (rcagd.pn_revolution, "pn_revolution",
     dict(u=[1, 2], v=[1, 0], start=[2, 0], distances=[F(1, 2)]), None),
    (rcagd.pn_canal, "pn_canal",
     dict(spine=[[0, 1, 0], [0, 0, 1], [0, 0, 0]], radius=[F(1, 2)], domain=[0, 1, 0, 1],
          distances=[F(1, 4)]), None),
    (rcagd.quadric_patch_image, "quadric_patch_image",
     dict(net=[[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, F(1, 2)]]], quadric="ellipsoid",
          coefficients=[3, 2, 1]), None),
]
IDS = [c[1] for c in CASES]


def _floats(v):
    if isinstance(v, (list, tuple)):
        return [_floats(x) for x in v]
    if isinstance(v, (int, F)) and not isinstance(v, bool):
        return float(v)
    return v


def _float_kwargs(exact, given):
    return given if given is not None else {k: _floats(v) for k, v in exact.items()}


def _recipe_entry(op, name, kwargs):
    entry = {"name": name, "op": op}
    for k, v in kwargs.items():
        entry[k.rstrip("_")] = v
    return rcagd._param(entry)


@pytest.mark.parametrize("fn,op,exact,_f", CASES, ids=IDS)
def test_exact_input_matches_cli(fn, op, exact, _f, tmp_path, cli_build):
    o = fn(**exact, name="x")
    assert o.name == "x" and o.op == op
    assert o.all_certificates_hold, o.certificates
    path = tmp_path / "r.json"
    path.write_text(json.dumps({"object": [_recipe_entry(op, "x", exact)]}))
    expected = cli_build(path)
    for obj in [o, *o.extras.values()]:
        e = expected[obj.name]
        j = obj.to_json()
        assert j["control_points"] == e["control_points"], obj.name
        assert j["certificates"] == e["certificates"], obj.name
    assert set(expected) == {o.name, *o.extras}


@pytest.mark.parametrize("fn,op,exact,floats", CASES, ids=IDS)
def test_float_input_agrees(fn, op, exact, floats):
    if floats is EXACT_ONLY:
        pytest.skip(f"{op}: the example data have no float representation")
    o = fn(**_float_kwargs(exact, floats))
    assert o.all_certificates_hold, o.certificates
    if floats is not None:
        return  # other data: only the certificates compare
    e = fn(**exact)
    a, b = o.control_points_f64, e.control_points_f64
    if not isinstance(a, list):
        a, b = [a], [b]
    assert len(a) == len(b)
    for x, y in zip(a, b):
        # the same Euclidean control points (the homogeneous ones may differ by a factor)
        np.testing.assert_allclose(x[..., 1:] / x[..., :1], y[..., 1:] / y[..., :1],
                                   rtol=1e-9, atol=1e-12)


def test_float_input_is_its_decimal():
    # 0.5 is 1/2 exactly: the same exact object as Fraction(1, 2) and "1/2"
    a = rcagd.torus(2.0, 0.5)
    b = rcagd.torus(2, F(1, 2))
    c = rcagd.torus("2", "1/2")
    d = rcagd.torus(np.float64(2.0), np.int64(1) / 2)
    assert a.control_points == b.control_points == c.control_points == d.control_points


def test_values_are_exact():
    o = rcagd.ph_planar_hermite(p0=(0, 0), d0=(1, 0), p1=(F(2, 15), F(2, 3)), d1=(0, 2))
    vals = o.values
    # Farouki–Neff's example: every interpolant has arc length 4/5
    assert vals["arc_length_0"] == F(4, 5) and isinstance(vals["arc_length_0"], F)
    assert vals["solutions"] == 4


def test_pipe_around_an_imported_bspline():
    """A spine with no exact rational pipe (the OpenCascade B-spline of examples/spines):
    the pipe is exact around a certified PH spline within the tolerance; ``approximate =
    "never"`` refuses it with the field it needs."""
    import pathlib

    root = pathlib.Path(__file__).resolve().parents[3]
    spine = root / "examples" / "spines" / "bspline_spine.step"
    p = rcagd.pipe(F(1, 5), spine_file=spine, tolerance=F(1, 100))
    assert p.all_certificates_hold
    assert any("spine deviation" in c.property for c in p.certificates)
    with pytest.raises(ValueError, match="extension|Q\\(√"):
        rcagd.pipe(F(1, 5), spine_file=spine, approximate="never")

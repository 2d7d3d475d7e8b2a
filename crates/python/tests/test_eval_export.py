"""Grid evaluation, meshes, exports and reading STEP/IGES back."""

from fractions import Fraction as F
from math import comb

import numpy as np
import pytest

import rcagd


def _bernstein(n, t):
    return [comb(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]


def _exact_patch_point(net, u, v):
    """x(u, v) of a homogeneous exact net (test oracle, in Fractions)."""
    bu, bv = _bernstein(len(net) - 1, u), _bernstein(len(net[0]) - 1, v)
    h = [sum(bu[i] * bv[j] * net[i][j][k] for i in range(len(net)) for j in range(len(net[0])))
         for k in range(len(net[0][0]))]
    return [c / h[0] for c in h[1:]]


def _exact_curve_point(points, t):
    b = _bernstein(len(points) - 1, t)
    h = [sum(b[i] * p[k] for i, p in enumerate(points)) for k in range(len(points[0]))]
    return [c / h[0] for c in h[1:]]


def test_grid_matches_exact_evaluation():
    torus = rcagd.torus(2, F(1, 2))
    us = np.linspace(0, 1, 7)
    vs = np.linspace(0, 1, 5)
    for piece in (0, 5, 15):
        g = torus.evaluate_grid(us, vs, piece=piece)
        assert g.shape == (7, 5, 3) and g.dtype == np.float64
        net = torus.control_points[piece]
        for i, u in enumerate(us):
            for j, v in enumerate(vs):
                x = _exact_patch_point(net, F(u), F(v))
                np.testing.assert_allclose(g[i, j], [float(c) for c in x], rtol=0, atol=1e-13)
        # every grid point is on the torus: (|x|² + R² − ρ²)² = 4R²(x² + y²)
        r2 = (g**2).sum(axis=2)
        lhs = (r2 + 4 - 0.25) ** 2
        rhs = 16 * (g[..., 0] ** 2 + g[..., 1] ** 2)
        np.testing.assert_allclose(lhs, rhs, rtol=1e-12)


def test_large_grid_has_no_python_loop():
    s = rcagd.sphere_cover()
    t = np.linspace(0, 1, 1000)
    g = s.evaluate_grid(t, t)
    assert g.shape == (1000, 1000, 3)
    g[0, 0, 0] += 0.0  # a writable array (no copy was needed to hand it over)
    np.testing.assert_allclose((g**2).sum(axis=2), 1.0, rtol=1e-13)


def test_curve_evaluation():
    arc = rcagd.circle_arc(5, (5, 0), (3, 4))
    ts = np.linspace(0, 1, 11)
    x = arc.evaluate(ts)
    assert x.shape == (11, 2)
    np.testing.assert_allclose(np.hypot(x[:, 0], x[:, 1]), 5.0, rtol=1e-14)
    np.testing.assert_allclose(x[0], [5, 0])
    np.testing.assert_allclose(x[-1], [3, 4])
    pts = arc.control_points
    for t, xt in zip(ts, x):
        np.testing.assert_allclose(xt, [float(c) for c in _exact_curve_point(pts, F(t))],
                                   atol=1e-14)
    assert arc.evaluate(0.5).shape == (2,)
    assert arc.evaluate(np.zeros((2, 3))).shape == (2, 3, 2)


def test_mesh_is_closed_and_on_the_surface():
    pos, nor, tri = rcagd.torus(2, F(1, 2)).mesh()
    assert pos.shape[1] == 3 and nor.shape == pos.shape and tri.dtype == np.uint32
    assert tri.max() < len(pos)
    r2 = (pos**2).sum(axis=1)
    np.testing.assert_allclose((r2 + 3.75) ** 2, 16 * (pos[:, 0] ** 2 + pos[:, 1] ** 2),
                               rtol=1e-9)


MAGIC = {
    "json": b"{",
    "step": b"ISO-10303-21;",
    "obj": b"#",
    "svg": b"<svg",
    "png": b"\x89PNG",
    "glb": b"glTF",
    "exact": b"{",
}


@pytest.mark.parametrize("fmt", ["json", "step", "iges", "obj", "stl", "ply", "glb", "svg",
                                 "png", "exact"])
def test_exports(fmt, tmp_path):
    o = rcagd.torus(2, F(1, 2))
    data = o.export(fmt)
    assert isinstance(data, bytes) and len(data) > 100
    if fmt in MAGIC:
        assert data.startswith(MAGIC[fmt]) or MAGIC[fmt] in data[:200], data[:40]
    ext = {"iges": "igs", "exact": "exact.json"}.get(fmt, fmt)
    path = o.save(tmp_path / f"ring.{ext}")
    if fmt in ("step", "iges"):
        # the header carries the time of writing
        assert len(path.read_bytes()) == len(data)
    else:
        assert path.read_bytes() == data


def test_step_and_iges_round_trip(tmp_path):
    o = rcagd.torus(2, F(1, 2), name="ring")
    _, surfaces = o.exact_nurbs()
    for reader, fmt in ((rcagd.read_step, "step"), (rcagd.read_iges, "iges")):
        path = tmp_path / f"ring.{fmt}"
        o.save(path, format=fmt)
        (imp,) = reader(path)
        assert len(imp.surfaces) == len(surfaces) == 16
        for a, b in zip(imp.surfaces, surfaces):
            assert a.degree == b.degree
            # the files carry the exact values rounded once to f64
            fa = np.array(a.control_points, dtype=float)
            fb = np.array(b.control_points, dtype=float)
            np.testing.assert_allclose(fa[..., 1:] / fa[..., :1], fb[..., 1:] / fb[..., :1],
                                       rtol=1e-15, atol=1e-15)
        # reading text instead of a path
        assert len(reader(path.read_text())[0].surfaces) == 16


def test_export_many(tmp_path):
    a = rcagd.torus(2, F(1, 2), name="a")
    b = rcagd.sphere_cover(name="b")
    step = rcagd.export([a, b], tmp_path / "both.step")
    names = sorted(o.name for o in rcagd.read_step(step.decode()))
    assert names == ["a", "b"]
    assert rcagd.export([a, b], format="glb").startswith(b"glTF")
    with pytest.raises(ValueError, match="one object per file"):
        rcagd.export([a, b], format="png")

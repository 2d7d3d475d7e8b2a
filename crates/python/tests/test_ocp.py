"""The OpenCascade bridge: rcagd's exact surfaces as OCP geometry, sewn into a solid and
cut (what CadQuery and build123d users do with them). Skipped, with the reason, when
`cadquery-ocp` is not installed in the Python running the tests."""

import math
from fractions import Fraction as F

import pytest

import rcagd

OCP = pytest.importorskip(
    "OCP",
    reason="cadquery-ocp is not installed in this Python: the OpenCascade bridge tests are "
    "skipped (pip install cadquery-ocp, or run them with the Python of scripts/occ_venv.sh)",
)

from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut  # noqa: E402
from OCP.BRepBuilderAPI import (  # noqa: E402
    BRepBuilderAPI_MakeFace,
    BRepBuilderAPI_MakeSolid,
    BRepBuilderAPI_Sewing,
)
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox  # noqa: E402
from OCP.Geom import Geom_BSplineCurve, Geom_BSplineSurface  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.TopAbs import TopAbs_SHELL, TopAbs_SOLID  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402
from OCP.TopoDS import TopoDS  # noqa: E402
from OCP.gp import gp_Pnt  # noqa: E402


def static(owner, name):
    """A static method across OCP versions: `Name_s` (OCCT 7) or `Name` (OCCT 8)."""
    f = getattr(owner, name + "_s", None)
    return f if f is not None else getattr(owner, name)


def volume(shape):
    props = GProp_GProps()
    static(BRepGProp, "VolumeProperties")(shape, props)
    return props.Mass()


def count(shape, kind):
    n, exp = 0, TopExp_Explorer(shape, kind)
    while exp.More():
        n += 1
        exp.Next()
    return n


R, RHO = 2, F(1, 2)
TORUS_VOLUME = 2 * math.pi**2 * R * float(RHO) ** 2


def test_surfaces_are_bspline_surfaces_on_the_torus():
    surfs = rcagd.torus(R, RHO).to_ocp()
    assert len(surfs) == 16
    for s in surfs:
        assert isinstance(s, Geom_BSplineSurface)
        assert s.IsURational() or s.IsVRational()
        for u in (0.0, 0.3, 1.0):
            for v in (0.0, 0.6, 1.0):
                p = s.Value(u, v)
                x, y, z = p.X(), p.Y(), p.Z()
                lhs = (x * x + y * y + z * z + R * R - float(RHO) ** 2) ** 2
                assert lhs == pytest.approx(4 * R * R * (x * x + y * y), rel=1e-12)


def test_curves_are_bspline_curves():
    (c,) = rcagd.circle_arc(5, (5, 0), (3, 4)).to_ocp()
    assert isinstance(c, Geom_BSplineCurve)
    for t in (0.0, 0.25, 0.5, 1.0):
        p = c.Value(t)
        assert math.hypot(p.X(), p.Y()) == pytest.approx(5.0, rel=1e-14)


def test_faces_sew_into_a_valid_solid():
    sewing = BRepBuilderAPI_Sewing(1e-7)
    for s in rcagd.torus(R, RHO).to_ocp():
        sewing.Add(BRepBuilderAPI_MakeFace(s, 1e-7).Face())
    sewing.Perform()
    sewn = sewing.SewedShape()
    assert count(sewn, TopAbs_SHELL) == 1
    exp = TopExp_Explorer(sewn, TopAbs_SHELL)
    solid = BRepBuilderAPI_MakeSolid(static(TopoDS, "Shell")(exp.Current())).Solid()
    assert BRepCheck_Analyzer(solid).IsValid()
    assert abs(volume(solid)) == pytest.approx(TORUS_VOLUME, rel=1e-6)


def test_shape_is_a_solid_that_cuts():
    shape = rcagd.torus(R, RHO).to_ocp_shape()
    assert count(shape, TopAbs_SOLID) == 1
    assert volume(shape) == pytest.approx(TORUS_VOLUME, rel=1e-6)
    # cut away the half x < 0: half the torus is left
    box = BRepPrimAPI_MakeBox(gp_Pnt(-5, -5, -5), gp_Pnt(0, 5, 5)).Shape()
    cut = BRepAlgoAPI_Cut(shape, box)
    assert cut.IsDone()
    half = cut.Shape()
    assert BRepCheck_Analyzer(half).IsValid()
    assert volume(half) == pytest.approx(TORUS_VOLUME / 2, rel=1e-5)


def test_without_ocp_the_error_is_an_import_error(monkeypatch):
    import builtins

    real = builtins.__import__

    def no_ocp(name, *a, **k):
        if name == "OCP" or name.startswith("OCP."):
            raise ImportError("no OCP here")
        return real(name, *a, **k)

    monkeypatch.setattr(builtins, "__import__", no_ocp)
    with pytest.raises(ImportError, match="pip install cadquery-ocp"):
        rcagd.torus(R, RHO).to_ocp()

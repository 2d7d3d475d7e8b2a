#!/usr/bin/env python3
"""OpenCascade's half of the pipe-around-an-imported-B-spline comparison (docs/BENCHMARKS.md).

The spine is a non-rational cubic B-spline with three spans (poles ``POLES``, clamped
uniform knots), joined into one curve and written by OpenCascade (``write-spine``): the file
``examples/spines/bspline_spine.step`` is what a CAD user would export. Its ``|m'|²`` is no sum of two rational squares, so rcagd builds the pipe
exactly around a certified PH quintic spline within a tolerance of it (``pipe`` op,
``approximate = "auto"``).

``bench RCAGD_STEP`` measures, for OpenCascade's pipe of the same radius
(``BRepOffsetAPI_MakePipe`` of a circle in the normal plane at the start, the CAD user's
sweep) and for rcagd's STEP file read back by OpenCascade, through the same code:

* the time to build it (OpenCascade: median of repeated builds; rcagd: given on the
  command line, measured by the caller);
* the number of control points after ``BRepBuilderAPI_NurbsConvert``;
* the radial error: on a 40 × 40 grid per face, ``| dist(p, spine) − r |`` with the
  distance to the B-spline spine by ``GeomAPI_ProjectPointOnCurve`` (the exact pipe's
  distance is ``r`` up to the certified spine deviation).

Usage (through the OpenCascade venv: ``py="$(scripts/occ_venv.sh)"``):
    python benches/occ/bspline_pipe.py write-spine examples/spines/bspline_spine.step PIECE.step...
    python benches/occ/bspline_pipe.py bench RADIUS SPINE_STEP RCAGD_STEP [RCAGD_SECONDS]
(benches/occ/pipe_compare.sh does all of it, for this spine and for a PH quintic).
"""

from __future__ import annotations

import statistics
import sys
import time

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepBuilderAPI import (
    BRepBuilderAPI_MakeEdge,
    BRepBuilderAPI_MakeWire,
    BRepBuilderAPI_NurbsConvert,
)
from OCP.BRepOffsetAPI import BRepOffsetAPI_MakePipe
from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
from OCP.GeomConvert import GeomConvert_CompCurveToBSplineCurve
from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt, gp_Vec
from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPControl import STEPControl_AsIs, STEPControl_Reader, STEPControl_Writer
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

SPINE = "examples/spines/bspline_spine.step"

# poles of the cubic spine (three spans, clamped uniform knots 0, 1, 2, 3)
POLES = [
    (0.0, 0.0, 0.0),
    (1.0, 0.0, 0.5),
    (2.0, 1.0, 0.0),
    (3.0, 1.0, 1.0),
    (3.0, 2.5, 2.0),
    (2.0, 3.0, 2.5),
]


def spine_curve(path: str | None = None):
    """The first edge's curve of a STEP file (default: the B-spline spine ``SPINE``)."""
    path = path or SPINE
    exp = TopExp_Explorer(read_step(path), TopAbs_EDGE)
    if not exp.More():
        raise SystemExit(f"{path}: no edge")
    edge = TopoDS.Edge(exp.Current())
    return BRep_Tool.Curve_s(edge, 0.0, 1.0)


def write_spine(path: str, pieces: list[str]) -> None:
    """Joins the Bézier pieces of the B-spline (STEP files written by ``rcagd build`` from
    exact control points, ``benches/occ/bspline_spine_pieces.toml``) into one B-spline curve
    with OpenCascade (``GeomConvert_CompCurveToBSplineCurve``) and writes it as a STEP edge:
    the file a CAD user would export."""
    joined = None
    for f in pieces:
        exp = TopExp_Explorer(read_step(f), TopAbs_EDGE)
        if not exp.More():
            raise SystemExit(f"{f}: no edge")
        edge = TopoDS.Edge(exp.Current())
        curve = BRep_Tool.Curve_s(edge, 0.0, 1.0)
        if joined is None:
            joined = GeomConvert_CompCurveToBSplineCurve(curve)
        elif not joined.Add(curve, 1e-9):
            raise SystemExit(f"{f} does not continue the spine")
    if joined is None:
        raise SystemExit("no spine pieces")
    bspline = joined.BSplineCurve()
    print(
        f"B-spline: degree {bspline.Degree()}, {bspline.NbPoles()} poles, {bspline.NbKnots()} knots,"
        f" rational {bspline.IsRational()}"
    )
    edge = BRepBuilderAPI_MakeEdge(bspline).Edge()
    Interface_Static.SetCVal_s("write.step.schema", "AP214")
    w = STEPControl_Writer()
    w.Transfer(edge, STEPControl_AsIs)
    if w.Write(path) != IFSelect_RetDone:
        raise SystemExit(f"cannot write {path}")
    print(f"wrote {path}")


def pipe_along(curve, radius: float):
    """OpenCascade's pipe: the circle of ``radius`` in the normal plane at the start of
    ``curve``, swept along it by ``BRepOffsetAPI_MakePipe``."""
    wire = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve).Edge()).Wire()
    p, v = gp_Pnt(), gp_Vec()
    curve.D1(curve.FirstParameter(), p, v)
    circ = gp_Circ(gp_Ax2(p, gp_Dir(v)), radius)
    profile = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circ).Edge()).Wire()
    mk = BRepOffsetAPI_MakePipe(wire, profile)
    mk.Build()
    if not mk.IsDone():
        raise SystemExit("OpenCascade's pipe failed")
    return mk.Shape()


def occ_pipe(radius: float):
    """The pipe around the spine read from its STEP file (the read is part of the timing)."""
    return pipe_along(spine_curve(), radius)


def faces(shape):
    exp = TopExp_Explorer(shape, TopAbs_FACE)
    while exp.More():
        yield TopoDS.Face(exp.Current())
        exp.Next()


def control_points(shape) -> int:
    nurbs = BRepBuilderAPI_NurbsConvert(shape, True).Shape()
    total = 0
    for f in faces(nurbs):
        s = BRep_Tool.Surface_s(f)
        total += s.NbUPoles() * s.NbVPoles()
    return total


def radial_error(shape, radius: float, n: int = 40) -> float:
    curve = spine_curve()
    worst = 0.0
    for f in faces(shape):
        a = BRepAdaptor_Surface(f)
        u0, u1 = a.FirstUParameter(), a.LastUParameter()
        v0, v1 = a.FirstVParameter(), a.LastVParameter()
        for i in range(n + 1):
            for j in range(n + 1):
                p = a.Value(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n)
                proj = GeomAPI_ProjectPointOnCurve(p, curve)
                if proj.NbPoints() == 0:
                    continue
                worst = max(worst, abs(proj.LowerDistance() - radius))
    return worst


def read_step(path: str):
    r = STEPControl_Reader()
    if r.ReadFile(path) != IFSelect_RetDone:
        raise SystemExit(f"cannot read {path}")
    r.TransferRoots()
    return r.OneShape()


def bench(radius: float, spine: str, rcagd_step: str, rcagd_seconds: str | None) -> None:
    global SPINE
    SPINE = spine
    times = []
    for _ in range(7):
        t = time.perf_counter()
        shape = occ_pipe(radius)
        times.append(time.perf_counter() - t)
    occ_time = statistics.median(times)
    rows = [
        ("OpenCascade BRepOffsetAPI_MakePipe", shape, f"{occ_time * 1e3:.2f} ms"),
        (
            "rcagd exact pipe (STEP read back)",
            read_step(rcagd_step),
            f"{float(rcagd_seconds) * 1e3:.0f} ms" if rcagd_seconds else "-",
        ),
    ]
    print("| pipe | faces | control points | max radial error | build time |")
    print("| --- | --- | --- | --- | --- |")
    for name, s, t in rows:
        nf = sum(1 for _ in faces(s))
        print(f"| {name} | {nf} | {control_points(s)} | {radial_error(s, radius):.2e} | {t} |")


def main() -> None:
    if len(sys.argv) >= 4 and sys.argv[1] == "write-spine":
        write_spine(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) >= 5 and sys.argv[1] == "bench":
        bench(float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5] if len(sys.argv) > 5 else None)
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()

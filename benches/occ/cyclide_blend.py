#!/usr/bin/env python3
"""OpenCascade's half of the cyclide-blend comparison (docs/BENCHMARKS.md).

The two blends of ``benches/cyclide_blend.rs`` (and examples/recipes/cyclide.toml):

* ``elbow``: cylinders of radius 1 with axes x and y; the blend is the quarter torus with
  major radius 2 (sphere centres on the circle of radius 2 about (2, 2, 0), radius 1);
* ``parallel``: parallel cylinders (axes along z) of radii 1 and 2 through (0, 0) and
  (4, 1); the blend is half of a ring Dupin cyclide, the envelope of the spheres
  ``m(θ) = (2 + 2 cos θ, 1/2 + cos θ / 2, 2 sin θ)``, ``r(θ) = 3/2 + cos θ / 2``,
  ``θ ∈ [0, π]`` (the pe circle through the contact spheres ``(0, 0, 0; 1)`` and
  ``(4, 1, 0; 2)``, tangent to both cylinders' lines of R^{3,1}; docs/math/cyclides.md).

OpenCascade has no cyclide. What a CAD user does to join the two cylinders:

* ``elbow``: ``BRepOffsetAPI_MakePipe`` of the unit circle along the arc of radius 2
  (OpenCascade recognises a torus: an analytic, exact surface);
* ``parallel``: ``BRepOffsetAPI_MakePipeShell`` along the spine ellipse ``m(θ)`` with the
  two contact circles as sections (CadQuery's ``sweep(multisection=True)``): circles in
  the spine's normal planes with a radius interpolated between 1 and 2.

Measured for each surface (OpenCascade's and rcagd's exported STEP, read back by
OpenCascade, through the same code): the time to build it (median of repeated builds),
the number of control points after ``BRepBuilderAPI_NurbsConvert``, the largest distance of
its points (a 60 × 60 grid per face) from the exact blend, i.e. ``min_θ |p − m(θ)| − r(θ)``
(the signed distance to the boundary of the union of the enveloped balls, which is the
blend near it), and the largest angle between its normal and the cylinder's normal along
the two contact circles (0 for a G¹ blend).

Usage (run through the OpenCascade venv of scripts/occ_check.sh):
    python benches/occ/cyclide_blend.py RCAGD_OUT_DIR
where RCAGD_OUT_DIR holds ``elbow_blend.step`` and ``parallel_cylinders_blend.step``
written by ``rcagd build`` (benches/occ/cyclide_blend.sh does all of it).
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepBuilderAPI import (
    BRepBuilderAPI_MakeEdge,
    BRepBuilderAPI_MakeWire,
    BRepBuilderAPI_NurbsConvert,
)
from OCP.BRepOffsetAPI import BRepOffsetAPI_MakePipe, BRepOffsetAPI_MakePipeShell
from OCP.GC import GC_MakeArcOfCircle, GC_MakeArcOfEllipse
from OCP.GeomAbs import GeomAbs_SurfaceType
from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Elips, gp_Pnt
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

GRID = 60
REPEAT = 200


# ------------------------------------------------------------------------------------
# The exact blends as sphere families
# ------------------------------------------------------------------------------------


def elbow_spheres(theta):
    """Centres and radii of the elbow's spheres, θ ∈ [0, π/2]: the arc of the circle of
    radius 2 about (2, 2, 0) tangent to the x axis at (2, 0, 0) and to the y axis at (0, 2, 0)."""
    m = np.stack([2 - 2 * np.sin(theta), 2 - 2 * np.cos(theta), 0 * theta], axis=-1)
    return m, np.ones_like(theta)


def parallel_spheres(theta):
    """Centres and radii of the parallel-cylinder cyclide's spheres, θ ∈ [0, π]."""
    c = np.cos(theta)
    m = np.stack([2 + 2 * c, 0.5 + 0.5 * c, 2 * np.sin(theta)], axis=-1)
    return m, 1.5 + 0.5 * c


def distance_to_envelope(points, spheres, lo, hi):
    """max over points of |min_θ (|p − m(θ)| − r(θ))|: dense θ grid, then golden search."""
    theta = np.linspace(lo, hi, 4001)
    m, r = spheres(theta)
    worst = 0.0
    for chunk in np.array_split(points, max(1, len(points) // 500)):
        d = np.linalg.norm(chunk[:, None, :] - m[None, :, :], axis=2) - r[None, :]
        k = np.argmin(d, axis=1)
        for p, kk in zip(chunk, k):
            a = theta[max(kk - 1, 0)]
            b = theta[min(kk + 1, len(theta) - 1)]

            def f(t):
                mm, rr = spheres(np.array([t]))
                return float(np.linalg.norm(p - mm[0]) - rr[0])

            g = (math.sqrt(5) - 1) / 2
            x1, x2 = b - g * (b - a), a + g * (b - a)
            f1, f2 = f(x1), f(x2)
            for _ in range(60):
                if f1 < f2:
                    b, x2, f2 = x2, x1, f1
                    x1 = b - g * (b - a)
                    f1 = f(x1)
                else:
                    a, x1, f1 = x1, x2, f2
                    x2 = a + g * (b - a)
                    f2 = f(x2)
            best = min(f1, f2)
            if kk in (0, len(theta) - 1):  # the minimum may sit at an end of [lo, hi]
                best = min(best, f(lo), f(hi))
            worst = max(worst, abs(best))
    return worst


# ------------------------------------------------------------------------------------
# Shapes
# ------------------------------------------------------------------------------------


def wire(*edges):
    w = BRepBuilderAPI_MakeWire()
    for e in edges:
        w.Add(BRepBuilderAPI_MakeEdge(e).Edge())
    return w.Wire()


def circle(centre, normal, radius):
    return wire(gp_Circ(gp_Ax2(gp_Pnt(*centre), gp_Dir(*normal)), radius))


def occ_elbow():
    s2 = 2 - math.sqrt(2)
    arc = GC_MakeArcOfCircle(gp_Pnt(2, 0, 0), gp_Pnt(s2, s2, 0), gp_Pnt(0, 2, 0)).Value()
    pipe = BRepOffsetAPI_MakePipe(wire(arc), circle((2, 0, 0), (1, 0, 0), 1.0))
    pipe.Build()
    return pipe.Shape()


def occ_parallel():
    xdir = np.array([1.0, 0.25, 0.0])
    major = 2 * float(np.linalg.norm(xdir))
    xdir /= np.linalg.norm(xdir)
    # the ellipse m(θ): centre (2, 1/2, 0), major radius along xdir, minor radius 2 along
    # z; the arc from (0, 0, 0) to (4, 1, 0) through (2, 1/2, 2), where the rcagd blend goes
    for normal in (np.cross([0.0, 0.0, 1.0], xdir), np.cross(xdir, [0.0, 0.0, 1.0])):
        el = gp_Elips(gp_Ax2(gp_Pnt(2, 0.5, 0), gp_Dir(*normal), gp_Dir(*xdir)), major, 2.0)
        arc = GC_MakeArcOfEllipse(el, gp_Pnt(0, 0, 0), gp_Pnt(4, 1, 0), True).Value()
        if arc.Value(0.5 * (arc.FirstParameter() + arc.LastParameter())).Z() > 0:
            break
    shell = BRepOffsetAPI_MakePipeShell(wire(arc))
    shell.Add(circle((0, 0, 0), (0, 0, 1), 1.0))
    shell.Add(circle((4, 1, 0), (0, 0, 1), 2.0))
    shell.Build()
    return shell.Shape()


def read_step(path):
    reader = STEPControl_Reader()
    if reader.ReadFile(str(path)) != IFSelect_RetDone:
        raise SystemExit(f"cannot read {path}")
    reader.TransferRoots()
    return reader.OneShape()


def faces(shape):
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        yield TopoDS.Face(e.Current())
        e.Next()


def control_points(shape):
    conv = BRepBuilderAPI_NurbsConvert(shape, True)
    n = 0
    for f in faces(conv.Shape()):
        s = BRep_Tool.Surface_s(f)
        n += s.NbUPoles() * s.NbVPoles()
    return n


def surface_types(shape):
    names = []
    for f in faces(shape):
        t = BRepAdaptor_Surface(f).GetType()
        names.append(str(t).split(".")[-1].replace("GeomAbs_", ""))
    return sorted(set(names))


def samples(shape):
    """Points and unit normals on a GRID × GRID grid of every face. The normals are
    cross products of one-sided differences (step 1e-6 of the parameter range), so that
    they are defined at the face boundaries (where the contact circles lie) even when a
    partial derivative degenerates there; their error is about 1e-6 rad."""
    pts, nrm = [], []
    for f in faces(shape):
        ad = BRepAdaptor_Surface(f)
        u0, u1, v0, v1 = ad.FirstUParameter(), ad.LastUParameter(), ad.FirstVParameter(), ad.LastVParameter()
        hu, hv = 1e-6 * (u1 - u0), 1e-6 * (v1 - v0)

        def val(u, v):
            p = ad.Value(u, v)
            return np.array([p.X(), p.Y(), p.Z()])

        for u in np.linspace(u0, u1, GRID):
            for v in np.linspace(v0, v1, GRID):
                p = val(u, v)
                pts.append(p)
                su = hu if u + hu <= u1 else -hu
                sv = hv if v + hv <= v1 else -hv
                n = np.cross((val(u + su, v) - p) / su, (val(u, v + sv) - p) / sv)
                if np.linalg.norm(n) > 0:
                    nrm.append((*p, *(n / np.linalg.norm(n))))
    return np.array(pts), np.array(nrm)


def contact_angles(normals, cylinders, tol=1e-7):
    """Per cylinder: the largest angle (degrees) between the surface normal and the
    cylinder's normal at the sample points on its contact circle (in the plane through the
    axis point perpendicular to the axis, at the cylinder's radius), and the number of such
    samples."""
    out = []
    for (ax, ay, az), (cx, cy, cz), rad in cylinders:
        worst, hit = 0.0, 0
        a = np.array([ax, ay, az], dtype=float)
        for x, y, z, nx, ny, nz in normals:
            p = np.array([x - cx, y - cy, z - cz])
            radial = p - p.dot(a) * a
            if abs(p.dot(a)) < tol and abs(np.linalg.norm(radial) - rad) < 1e-6:
                hit += 1
                c = abs(np.dot(radial / np.linalg.norm(radial), (nx, ny, nz)))
                worst = max(worst, math.degrees(math.acos(min(1.0, c))))
        out.append((worst, hit))
    return out


def timed(build):
    ts = []
    for _ in range(REPEAT):
        t = time.perf_counter()
        build()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts)


def report(label, shape, spheres, lo, hi, cylinders, build_time=None):
    pts, nrm = samples(shape)
    dev = distance_to_envelope(pts, spheres, lo, hi)
    angles = "; ".join(
        f"cylinder {i + 1}: {a:.3g}° ({n} samples)" for i, (a, n) in enumerate(contact_angles(nrm, cylinders))
    )
    t = f"{build_time * 1e3:.3f} ms" if build_time is not None else "-"
    print(
        f"{label}: surfaces {','.join(surface_types(shape))}; control points {control_points(shape)}; "
        f"max deviation from the exact blend {dev:.2e}; max normal angle at the contact circles: "
        f"{angles}; build {t}"
    )


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else None
    elbow_cyl = [((1, 0, 0), (2, 0, 0), 1.0), ((0, 1, 0), (0, 2, 0), 1.0)]
    par_cyl = [((0, 0, 1), (0, 0, 0), 1.0), ((0, 0, 1), (4, 1, 0), 2.0)]
    report("elbow / OpenCascade MakePipe", occ_elbow(), elbow_spheres, 0, math.pi / 2, elbow_cyl, timed(occ_elbow))
    report("parallel / OpenCascade MakePipeShell", occ_parallel(), parallel_spheres, 0, math.pi, par_cyl, timed(occ_parallel))
    if out is not None:
        report("elbow / rcagd STEP read by OpenCascade", read_step(out / "elbow_blend.step"), elbow_spheres, 0, math.pi / 2, elbow_cyl)
        report(
            "parallel / rcagd STEP read by OpenCascade",
            read_step(out / "parallel_cylinders_blend.step"),
            parallel_spheres,
            0,
            math.pi,
            par_cyl,
        )


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""OpenCascade's half of the twist comparison (docs/BENCHMARKS.md).

The spine is the RRMF quintic of ``benches/occ/rrmf_twist.toml`` (preimage
``A_0 = 2 + j``, ``A_1 = 1 + 2i − k``, ``A_2`` from the quintic RRMF condition; read from
rcagd's STEP file ``spine.step``), the profile an ellipse with semi-axes 1 and 1/2 whose
major axis starts along the first vector ``f1(0)`` of the exact rational
rotation-minimizing frame (RMF) of rcagd (``spine_frame.json``: the curve's point, ``t``,
``f1``, ``f2`` at ``t = k/32``).

OpenCascade sweeps the ellipse along the spine with ``BRepOffsetAPI_MakePipeShell`` in
its three trihedron modes: corrected Frenet (``SetMode(False)``, the default for
CadQuery/FreeCAD sweeps), Frenet (``SetMode(True)``) and discrete
(``SetDiscreteMode()``). For each swept shape (and for rcagd's ``sweep.step``, read back by
OpenCascade through the same code) the twist is measured at every sample ``t = k/32``:
the shape is cut by the normal plane of the spine at ``r(t)``, points of the section near
``r(t)`` are expressed in the exact RMF coordinates ``(f1, f2)``, the conic
``A x² + B xy + C y² = 1`` is fitted by least squares, and the angle of its major axis
from ``f1`` is ``φ = ½ atan2(−B, C − A)`` (mod 180°; exact for points on an ellipse). A
twist-free sweep has ``φ ≡ 0``.

Usage (run through the OpenCascade venv of scripts/occ_check.sh):
    python benches/occ/rrmf_twist.py RCAGD_OUT_DIR
(benches/occ/rrmf_twist.sh does all of it).
"""

from __future__ import annotations

import json
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
from OCP.BRepBuilderAPI import (
    BRepBuilderAPI_MakeEdge,
    BRepBuilderAPI_MakeWire,
    BRepBuilderAPI_NurbsConvert,
)
from OCP.BRepOffsetAPI import BRepOffsetAPI_MakePipeShell
from OCP.gp import gp_Ax2, gp_Dir, gp_Elips, gp_Pln, gp_Pnt
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

A, B = 1.0, 0.5  # semi-axes of the ellipse


def read_step(path):
    reader = STEPControl_Reader()
    if reader.ReadFile(str(path)) != IFSelect_RetDone:
        raise SystemExit(f"cannot read {path}")
    reader.TransferRoots()
    return reader.OneShape()


def explore(shape, kind, cast):
    e = TopExp_Explorer(shape, kind)
    while e.More():
        yield cast(e.Current())
        e.Next()


def control_points(shape):
    conv = BRepBuilderAPI_NurbsConvert(shape, True)
    n = 0
    for f in explore(conv.Shape(), TopAbs_FACE, TopoDS.Face):
        s = BRep_Tool.Surface_s(f)
        n += s.NbUPoles() * s.NbVPoles()
    return n


def frame_samples(path):
    """(p, t, f1, f2) per sample from the `<name>_frame` JSON: piece 0 is the curve, then
    three segments p → p + v per sample (frame_length = 1)."""
    pieces = json.loads(Path(path).read_text())["control_points_f64"][1:]
    out = []
    for k in range(0, len(pieces), 3):
        seg = [np.array(pc[1][1:]) / pc[1][0] - np.array(pc[0][1:]) / pc[0][0] for pc in pieces[k : k + 3]]
        p = np.array(pieces[k][0][1:]) / pieces[k][0][0]
        out.append((p, *[v / np.linalg.norm(v) for v in seg]))
    return out


def spine_wire(path):
    edges = list(explore(read_step(path), TopAbs_EDGE, TopoDS.Edge))
    mk = BRepBuilderAPI_MakeWire()
    for e in edges:
        mk.Add(e)
    return mk.Wire()


def occ_sweep(spine, frame0, mode):
    p, t, f1, _ = frame0
    ax = gp_Ax2(gp_Pnt(*p), gp_Dir(*t), gp_Dir(*f1))
    prof = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Elips(ax, A, B)).Edge()).Wire()
    mk = BRepOffsetAPI_MakePipeShell(spine)
    if mode == "corrected_frenet":
        mk.SetMode(False)
    elif mode == "frenet":
        mk.SetMode(True)
    else:
        mk.SetDiscreteMode()
    mk.Add(prof)
    mk.Build()
    if not mk.IsDone():
        raise SystemExit(f"MakePipeShell ({mode}) failed")
    return mk.Shape()


def twist_at(shape, sample):
    """Angle (degrees, in (−90, 90]) of the section ellipse's major axis from f1."""
    p, t, f1, f2 = sample
    sec = BRepAlgoAPI_Section(shape, gp_Pln(gp_Pnt(*p), gp_Dir(*t)))
    sec.Build()
    xs, ys = [], []
    for e in explore(sec.Shape(), TopAbs_EDGE, TopoDS.Edge):
        c = BRepAdaptor_Curve(e)
        a, b = c.FirstParameter(), c.LastParameter()
        for i in range(201):
            q = c.Value(a + (b - a) * i / 200)
            d = np.array([q.X(), q.Y(), q.Z()]) - p
            if np.linalg.norm(d) < 1.5 * A:
                xs.append(d @ f1)
                ys.append(d @ f2)
    if len(xs) < 5:
        return None
    x, y = np.array(xs), np.array(ys)
    m = np.stack([x * x, x * y, y * y], axis=1)
    (ca, cb, cc), *_ = np.linalg.lstsq(m, np.ones_like(x), rcond=None)
    # the major axis is the eigenvector of the smaller eigenvalue of [[A, B/2], [B/2, C]]
    phi = 0.5 * math.degrees(math.atan2(-cb, cc - ca))
    return phi


def median_time(f, n=5):
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        r = f()
        ts.append(time.perf_counter() - t0)
    return r, statistics.median(ts)


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    frames = frame_samples(out / "spine_frame.json")
    spine = spine_wire(out / "spine.step")
    rows = []
    for mode in ["corrected_frenet", "frenet", "discrete"]:
        shape, dt = median_time(lambda: occ_sweep(spine, frames[0], mode))
        rows.append((f"OpenCascade MakePipeShell {mode}", shape, dt))
    rcagd, dt = median_time(lambda: read_step(out / "sweep.step"))
    rows.append(("rcagd sweep_rrmf (STEP read back)", rcagd, None))
    print(f"spine: {len(frames)} samples t = k/{len(frames) - 1}; profile: ellipse {A} × {B}")
    print(f"{'sweep':42} {'build ms':>9} {'ctrl pts':>8} {'max |twist| °':>14} {'twist at t=1 °':>15}")
    profiles = []
    for name, shape, dt in rows:
        tw = [twist_at(shape, s) for s in frames]
        profiles.append((name, tw))
        tw = [v for v in tw if v is not None]
        mx = max(abs(v) for v in tw) if tw else float("nan")
        end = tw[-1] if tw else float("nan")
        ms = f"{dt * 1e3:9.2f}" if dt is not None else f"{'—':>9}"
        print(f"{name:42} {ms} {control_points(shape):8d} {mx:14.3e} {end:15.3e}  ({len(tw)} sections)")
    step = max(1, (len(frames) - 1) // 8)
    print("twist (degrees) at t = " + ", ".join(f"{k}/{len(frames) - 1}" for k in range(0, len(frames), step)))
    for name, tw in profiles:
        vals = ", ".join("—" if v is None else f"{v:.3g}" for v in tw[::step])
        print(f"  {name}: {vals}")


if __name__ == "__main__":
    main()

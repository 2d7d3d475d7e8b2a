"""An exact rational pipe handed to CadQuery (or to OpenCascade directly).

rcagd builds the pipe surface of radius 1/8 around a spatial PH quintic exactly over Q
(every certificate an exact polynomial identity), then hands it to OpenCascade as
B-spline faces (`Object.to_ocp`) and as a shape (`Object.to_ocp_shape`); a ring torus
arrives as one closed solid that CadQuery can cut like any other.

    pip install ./crates/python cadquery-ocp     # (cadquery optional)
    python examples/python/exact_pipe_cadquery.py [OUT_DIR]
"""

import math
import os
import sys
from fractions import Fraction

import rcagd

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)

pipe = rcagd.pipe_ph(coefficients=[[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]],
                     radius=Fraction(1, 8), name="pipe")
print(pipe)
for c in pipe.certificates:
    print("  ", "holds" if c.holds else "FAILS", c.property)

torus = rcagd.torus(2, Fraction(1, 2), name="ring")
faces = pipe.to_ocp()  # Geom_BSplineSurface per patch
print(f"{len(faces)} exact B-spline faces in OpenCascade")

try:
    import cadquery as cq
except ImportError:
    cq = None

if cq is not None:
    tube = cq.Shape.cast(pipe.to_ocp_shape())
    ring = cq.Shape.cast(torus.to_ocp_shape())
    half = cq.Workplane().add(ring).cut(cq.Workplane().box(10, 10, 10, centered=(False, True, True)))
    print(f"CadQuery: tube area {tube.Area():.6f}, half torus volume {half.val().Volume():.6f}")
    cq.exporters.export(half, os.path.join(out, "half_ring.step"))
else:
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
    from OCP.BRepGProp import BRepGProp
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeBox
    from OCP.GProp import GProp_GProps
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
    from OCP.gp import gp_Pnt

    def static(owner, name):
        return getattr(owner, name + "_s", None) or getattr(owner, name)

    def props(shape, kind):
        p = GProp_GProps()
        static(BRepGProp, kind)(shape, p)
        return p.Mass()

    tube = pipe.to_ocp_shape()
    ring = torus.to_ocp_shape()
    half = BRepAlgoAPI_Cut(ring, BRepPrimAPI_MakeBox(gp_Pnt(0, -5, -5), gp_Pnt(10, 5, 5)).Shape())
    vol = props(half.Shape(), "VolumeProperties")
    print(f"OpenCascade (cadquery not installed): tube area {props(tube, 'SurfaceProperties'):.6f}, "
          f"half torus volume {vol:.6f} (exact π²/2 = {math.pi**2 / 2:.6f})")
    w = STEPControl_Writer()
    w.Transfer(half.Shape(), STEPControl_AsIs)
    assert w.Write(os.path.join(out, "half_ring.step")) == IFSelect_RetDone
print("wrote", os.path.join(out, "half_ring.step"))

"""A PN surface's exact rational offset compared with OpenCascade's offset surface.

rcagd builds the PN surface of F(u, v) = 1 + v²/2 − u v + u³/3 (Peternell's isotropic
model) and its offset at distance 1/4 exactly: a rational patch, certified an offset.
OpenCascade offsets the same B-spline surface numerically (`Geom_OffsetSurface`, a
non-rational evaluator). The script measures how far the exact offset's points are from
OpenCascade's offset surface (point projection), for d and −d (the two normal senses).

    pip install ./crates/python cadquery-ocp
    python examples/python/pn_offset_vs_occ.py
"""

from fractions import Fraction

import numpy as np

import rcagd
from OCP.Geom import Geom_OffsetSurface
from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
from OCP.gp import gp_Pnt

d = Fraction(1, 4)
base = rcagd.pn_graph(coefficients=[[1, 0, "1/2"], [0, -1, 0], [0, 0, 0], ["1/3", 0, 0]],
                      domain=[0, "1/2", 0, "1/2"], distances=[d], name="pn")
offset = base.extras["pn_offset1"]
print(base)
print(offset)
assert offset.all_certificates_hold

(surface,) = base.to_ocp()
t = np.linspace(0, 1, 21)
points = offset.evaluate_grid(t, t).reshape(-1, 3)
for sense in (+1, -1):
    occ = Geom_OffsetSurface(surface, sense * float(d))
    dist = []
    for x, y, z in points:
        proj = GeomAPI_ProjectPointOnSurf(gp_Pnt(x, y, z), occ)
        dist.append(proj.LowerDistance() if proj.NbPoints() else np.inf)
    dist = np.array(dist)
    print(f"OpenCascade offset at {sense * float(d):+.2f}: distance of the exact offset's "
          f"{len(points)} points: max {dist.max():.3e}, mean {dist.mean():.3e}")

#!/usr/bin/env python3
"""Check rcagd's STEP and IGES files in OpenCascade (the `cadquery-ocp` wheel).

For every ``*.step``, ``*.stp``, ``*.igs`` and ``*.iges`` file of a directory:

1. read it with OpenCascade's STEP or IGES reader and collect every message of the
   load and of the transfer (a file that CAD systems open "without warnings" has
   none);
2. run ``BRepCheck_Analyzer`` on every transferred shape, and report each solid's
   volume (a correctly oriented closed shell has a positive one);
3. sample every face at 1000 parameters (a 40 x 25 grid over its surface's domain)
   and every edge at 1000 parameters, evaluated by OpenCascade, and compare with the
   exact NURBS that rcagd wrote beside the file: ``NAME.exact.json`` (see
   ``rcagd_io::step::exact_sidecar``), evaluated here with Python fractions (the
   Bernstein basis for a single Bézier piece, de Boor otherwise, on homogeneous
   control points; rational parameters equal to OpenCascade's
   binary64 parameters). Each OpenCascade surface or curve is matched to the exact
   one whose rounded control points and weights it carries. The largest deviation,
   relative to the object's size (diagonal of its control points' bounding box),
   must be at most ``--tol`` (default 1e-12).

Exit status 0 if every file passes, 1 otherwise. Run it through ``occ_check.sh``,
which makes the virtual environment.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from decimal import Decimal, localcontext, getcontext
from fractions import Fraction
from pathlib import Path

# --------------------------------------------------------------------------------
# Exact NURBS evaluation
# --------------------------------------------------------------------------------


# The number type of the exact evaluation. Inputs are exact rationals ("p/q") and the
# binary64 parameters of OpenCascade (exact as Fraction or Decimal). With Fraction the
# evaluation is exact; with Decimal at 60 significant digits (the default, about 50
# times faster) every de Boor step, and the Bernstein sum, is a convex combination of
# the control points (the Bernstein form is about twice as fast), so the evaluation
# error is below 1e-55 relative: exact for a comparison at 1e-12.
DECIMAL_DIGITS = 60
EXACT = {"kind": "decimal"}


def frac(s: str):
    if EXACT["kind"] == "fraction":
        return Fraction(s)
    num, _, den = s.partition("/")
    with localcontext() as ctx:
        ctx.prec = DECIMAL_DIGITS
        return Decimal(num) / Decimal(den or "1")


def param(x: float):
    """An OpenCascade parameter as an exact number of the evaluation type."""
    return Fraction(x) if EXACT["kind"] == "fraction" else Decimal(x)


def find_span(knots, p, n_ctrl, t):
    """Index k with knots[k] <= t < knots[k+1], clamped to the last span."""
    if t >= knots[n_ctrl]:
        return n_ctrl - 1
    lo, hi = p, n_ctrl
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if knots[mid] <= t:
            lo = mid
        else:
            hi = mid
    return lo


def de_boor(knots, p, k, pts, t):
    """de Boor on the p + 1 homogeneous points of span k (NURBS Book A5.2 form)."""
    d = [list(x) for x in pts]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = j + k - p
            den = knots[i + 1 + p - r] - knots[i]
            a = (t - knots[i]) / den if den != 0 else t - t
            d[j] = [(1 - a) * x + a * y for x, y in zip(d[j - 1], d[j])]
    return d[p]


def single_bezier(knots, p, n_ctrl):
    """(a, b) if the knots are a⁽ᵖ⁺¹⁾ b⁽ᵖ⁺¹⁾ (one Bézier piece), else None."""
    if n_ctrl != p + 1 or len(knots) != 2 * p + 2:
        return None
    a, b = knots[0], knots[-1]
    if a == b or any(k != a for k in knots[: p + 1]) or any(k != b for k in knots[p + 1 :]):
        return None
    return a, b


def bernstein(p, a, b, t):
    """The Bernstein basis of degree p on [a, b] at t: nonnegative weights summing to 1
    for t in [a, b] (the evaluation is a convex combination, as de Boor's)."""
    s = (t - a) / (b - a)
    r = 1 - s
    left = [s - s + 1]
    for _ in range(p):
        left.append(left[-1] * s)
    right = [s - s + 1]
    for _ in range(p):
        right.append(right[-1] * r)
    return [BINOM[p][i] * left[i] * right[p - i] for i in range(p + 1)]


# binomial coefficients C(n, i), n ≤ 64
BINOM = [[math.comb(n, i) for i in range(n + 1)] for n in range(65)]


def combine(basis, pts):
    """Σ basis[i] · pts[i] (homogeneous points)."""
    out = [x * basis[0] for x in pts[0]]
    for bi, pt in zip(basis[1:], pts[1:]):
        out = [o + bi * x for o, x in zip(out, pt)]
    return out


class ExactCurve:
    def __init__(self, js):
        self.p = js["degree"]
        self.knots = [frac(x) for x in js["knots"]]
        self.pts = [[frac(x) for x in h] for h in js["control_points"]]

    @classmethod
    def from_parts(cls, p, knots, pts):
        c = cls.__new__(cls)
        c.p, c.knots, c.pts = p, knots, pts
        return c

    def domain(self):
        return self.knots[self.p], self.knots[len(self.pts)]

    def eval(self, t: Fraction):
        bez = single_bezier(self.knots, self.p, len(self.pts))
        if bez is not None and self.p <= 64:
            h = combine(bernstein(self.p, bez[0], bez[1], t), self.pts)
            return [x / h[0] for x in h[1:]]
        k = find_span(self.knots, self.p, len(self.pts), t)
        h = de_boor(self.knots, self.p, k, self.pts[k - self.p : k + 1], t)
        return [x / h[0] for x in h[1:]]

    def bezier_pieces(self):
        """The Bézier pieces (on their knot intervals) when every interior knot has
        multiplicity p: consecutive slices of p + 1 control points."""
        p, n = self.p, len(self.pts)
        inner = self.knots[p + 1 : n]
        if not inner or (n - 1) % p != 0:
            return []
        out = []
        for k in range((n - 1) // p):
            a, b = self.knots[p + k * p], self.knots[p + k * p + 1]
            if a == b:
                return []
            out.append(
                ExactCurve.from_parts(p, [a] * (p + 1) + [b] * (p + 1), self.pts[k * p : k * p + p + 1])
            )
        return out

    def euclid_f64(self):
        return [[float(x / h[0]) for x in h[1:]] for h in self.pts]

    def weights_f64(self):
        return [float(h[0]) for h in self.pts]


class ExactSurface:
    def __init__(self, js):
        self.p, self.q = js["degree"]
        self.ku = [frac(x) for x in js["knots_u"]]
        self.kv = [frac(x) for x in js["knots_v"]]
        self.net = [[[frac(x) for x in h] for h in row] for row in js["control_points"]]

    def eval(self, u: Fraction, v: Fraction):
        nu, nv = len(self.net), len(self.net[0])
        bu = single_bezier(self.ku, self.p, nu)
        bv = single_bezier(self.kv, self.q, nv)
        if bu is not None and bv is not None and max(self.p, self.q) <= 64:
            basis_v = bernstein(self.q, bv[0], bv[1], v)
            rows = [combine(basis_v, row) for row in self.net]
            h = combine(bernstein(self.p, bu[0], bu[1], u), rows)
            return [x / h[0] for x in h[1:]]
        ku = find_span(self.ku, self.p, nu, u)
        kv = find_span(self.kv, self.q, nv, v)
        rows = [
            de_boor(self.kv, self.q, kv, self.net[i][kv - self.q : kv + 1], v)
            for i in range(ku - self.p, ku + 1)
        ]
        h = de_boor(self.ku, self.p, ku, rows, u)
        return [x / h[0] for x in h[1:]]

    def boundary_curves(self):
        """The four boundary curves (rows and columns of the net) as exact curves."""
        nu, nv = len(self.net), len(self.net[0])
        out = [
            ExactCurve.from_parts(self.q, self.kv, self.net[0]),
            ExactCurve.from_parts(self.q, self.kv, self.net[nu - 1]),
            ExactCurve.from_parts(self.p, self.ku, [self.net[i][0] for i in range(nu)]),
            ExactCurve.from_parts(self.p, self.ku, [self.net[i][nv - 1] for i in range(nu)]),
        ]
        return out

    def domain_u(self):
        return self.ku[self.p], self.ku[len(self.net)]

    def domain_v(self):
        return self.kv[self.q], self.kv[len(self.net[0])]

    def euclid_f64(self):
        return [[[float(x / h[0]) for x in h[1:]] for h in row] for row in self.net]

    def weights_f64(self):
        return [[float(h[0]) for h in row] for row in self.net]


def size_of(points):
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    return math.sqrt(sum((b - a) ** 2 for a, b in zip(lo, hi))) or 1.0


def dist_exact(occ_xyz, exact):
    return math.sqrt(sum(float(param(a) - b) ** 2 for a, b in zip(occ_xyz, exact)))


# --------------------------------------------------------------------------------
# OpenCascade side
# --------------------------------------------------------------------------------


def occ_imports():
    from OCP.BRep import BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Surface
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.BRepGProp import BRepGProp
    from OCP.GeomAbs import GeomAbs_BSplineCurve, GeomAbs_BSplineSurface
    from OCP.GProp import GProp_GProps
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.IGESControl import IGESControl_Reader
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID, TopAbs_VERTEX
    from OCP.TopAbs import TopAbs_SHELL
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    from OCP.ShapeAnalysis import ShapeAnalysis_FreeBounds

    return locals()


def static(owner, name):
    """A static method across OCP versions: `Name_s` (OCCT 7) or `Name` (OCCT 8)."""
    f = getattr(owner, name + "_s", None)
    return f if f is not None else getattr(owner, name)


def messages(check_iterator):
    """(warnings, fails) of an Interface_CheckIterator, as lists of strings."""
    warns, fails = [], []
    check_iterator.Start()
    while check_iterator.More():
        c = check_iterator.Value()
        num = check_iterator.Number()
        for i in range(1, c.NbWarnings() + 1):
            warns.append(f"entity {num}: {c.CWarning(i)}")
        for i in range(1, c.NbFails() + 1):
            fails.append(f"entity {num}: {c.CFail(i)}")
        check_iterator.Next()
    return warns, fails


class quiet_stdout:
    """Silences OpenCascade's messages on the process's standard output."""

    def __enter__(self):
        import os

        sys.stdout.flush()
        self.saved = os.dup(1)
        self.null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(self.null, 1)

    def __exit__(self, *exc):
        import os

        sys.stdout.flush()
        os.dup2(self.saved, 1)
        os.close(self.saved)
        os.close(self.null)


def read_file(occ, path: Path):
    """(shapes, warnings, fails) of a STEP or IGES file."""
    with quiet_stdout():
        return read_file_loud(occ, path)


def read_file_loud(occ, path: Path):
    if path.suffix.lower() in (".step", ".stp"):
        reader = occ["STEPControl_Reader"]()
    else:
        reader = occ["IGESControl_Reader"]()
    status = reader.ReadFile(str(path))
    if status != occ["IFSelect_RetDone"]:
        return [], [], [f"the reader failed to load the file (status {status})"]
    ws = reader.WS()
    w1, f1 = messages(ws.ModelCheckList())
    reader.TransferRoots()
    w2, f2 = messages(ws.TransferReader().TransientProcess().CheckList(False))
    shapes = [reader.Shape(i) for i in range(1, reader.NbShapes() + 1)]
    return shapes, w1 + w2, f1 + f2


def poles_match(occ_poles, occ_weights, ex_poles, ex_weights, tol):
    if len(occ_poles) != len(ex_poles) or not occ_poles:
        return False
    for a, b in zip(occ_poles, ex_poles):
        if max(abs(x - y) for x, y in zip(a, b)) > tol:
            return False
    # weights up to a common factor
    f = occ_weights[0] / ex_weights[0]
    return all(abs(a - f * b) <= 1e-12 * abs(a) for a, b in zip(occ_weights, ex_weights))


def same_domain(occ_range, exact_range):
    a, b = (float(x) for x in exact_range)
    return abs(occ_range[0] - a) <= 1e-12 * (1 + abs(a)) and abs(occ_range[1] - b) <= 1e-12 * (
        1 + abs(b)
    )


def transform(loc, pnt):
    if loc is None:
        return pnt
    return pnt.Transformed(loc)


def check_faces(occ, shape, ex_f64, size, n_samples, report):
    """ex_f64: (exact surface, rounded poles, rounded weights) of every sidecar surface."""
    worst, matched, total = 0.0, 0, 0
    exp = occ["TopExp_Explorer"](shape, occ["TopAbs_FACE"])
    while exp.More():
        face = static(occ["TopoDS"], "Face")(exp.Current())
        exp.Next()
        total += 1
        ad = occ["BRepAdaptor_Surface"](face, False)
        if ad.GetType() != occ["GeomAbs_BSplineSurface"]:
            report.append(f"face {total}: not a B-spline surface ({ad.GetType()})")
            continue
        bs = ad.BSpline()
        trsf = ad.Trsf()
        nu, nv = bs.NbUPoles(), bs.NbVPoles()
        poles = [
            [
                [c for c in (lambda p: (p.X(), p.Y(), p.Z()))(bs.Pole(i, j).Transformed(trsf))]
                for j in range(1, nv + 1)
            ]
            for i in range(1, nu + 1)
        ]
        weights = [[bs.Weight(i, j) for j in range(1, nv + 1)] for i in range(1, nu + 1)]
        flat_p = [x for row in poles for x in row]
        flat_w = [x for row in weights for x in row]
        match = None
        u0, u1, v0, v1 = bs.Bounds()
        for s, ep, ew, fp, fw in ex_f64:
            if len(ep) != nu or len(ep[0]) != nv:
                continue
            if not same_domain((u0, u1), s.domain_u()) or not same_domain((v0, v1), s.domain_v()):
                continue
            if poles_match(flat_p, flat_w, fp, fw, 1e-9 * size):
                match = s
                break
        if match is None:
            report.append(f"face {total}: no exact surface of the sidecar has its control points")
            continue
        matched += 1
        nu_s = 40
        nv_s = max(1, n_samples // nu_s)
        for a in range(nu_s):
            u = u0 + (u1 - u0) * a / (nu_s - 1)
            for b in range(nv_s):
                v = v0 + (v1 - v0) * b / (nv_s - 1)
                p = bs.Value(u, v).Transformed(trsf)
                e = match.eval(param(u), param(v))
                worst = max(worst, dist_exact((p.X(), p.Y(), p.Z()), e))
    return total, matched, worst


def check_edges(occ, shape, cands, size, n_samples, report):
    """cands: (exact curve, rounded poles, rounded weights) of every sidecar curve."""
    worst, matched, total, degenerate = 0.0, 0, 0, 0
    seen = {}
    exp = occ["TopExp_Explorer"](shape, occ["TopAbs_EDGE"])
    while exp.More():
        edge = static(occ["TopoDS"], "Edge")(exp.Current())
        exp.Next()
        bucket = seen.setdefault(hash(edge), [])
        if any(edge.IsSame(other) for other in bucket):
            continue
        bucket.append(edge)
        if static(occ["BRep_Tool"], "Degenerated")(edge):
            degenerate += 1
            continue
        total += 1
        ad = occ["BRepAdaptor_Curve"](edge)
        if ad.GetType() != occ["GeomAbs_BSplineCurve"]:
            report.append(f"edge {total}: not a B-spline curve ({ad.GetType()})")
            continue
        bc = ad.BSpline()
        trsf = ad.Trsf()
        poles = []
        for i in range(1, bc.NbPoles() + 1):
            p = bc.Pole(i).Transformed(trsf)
            poles.append((p.X(), p.Y(), p.Z()))
        weights = [bc.Weight(i) for i in range(1, bc.NbPoles() + 1)]
        match, reverse = None, False
        t0, t1 = bc.FirstParameter(), bc.LastParameter()
        for c, ep, ew in cands:
            if not same_domain((t0, t1), c.domain()):
                continue
            if poles_match(poles, weights, ep, ew, 1e-9 * size):
                match = c
                break
            if poles_match(poles, weights, ep[::-1], ew[::-1], 1e-9 * size):
                match, reverse = c, True
                break
        if match is None:
            report.append(f"edge {total}: no exact curve of the sidecar has its control points")
            continue
        matched += 1
        a, b = match.domain()
        for k in range(n_samples):
            t = t0 + (t1 - t0) * k / (n_samples - 1)
            p = bc.Value(t).Transformed(trsf)
            te = param(t)
            if reverse:
                # OpenCascade reversed the curve: t ↦ a + b − t on the same knots
                te = a + b - te
            e = match.eval(min(max(te, a), b))
            worst = max(worst, dist_exact((p.X(), p.Y(), p.Z()), e))
    return total, matched, worst, degenerate


def max_tolerance(occ, shape):
    """The largest vertex, edge and face tolerance: the reader enlarges them where it
    has to close gaps between exact geometry and topology (rcagd's are 1e-7)."""
    worst = 0.0
    for kind, cast in (("TopAbs_VERTEX", "Vertex"), ("TopAbs_EDGE", "Edge"), ("TopAbs_FACE", "Face")):
        exp = occ["TopExp_Explorer"](shape, occ[kind])
        while exp.More():
            sub = static(occ["TopoDS"], cast)(exp.Current())
            worst = max(worst, static(occ["BRep_Tool"], "Tolerance")(sub))
            exp.Next()
    return worst


def solids_volumes(occ, shape):
    vols = []
    exp = occ["TopExp_Explorer"](shape, occ["TopAbs_SOLID"])
    while exp.More():
        props = occ["GProp_GProps"]()
        static(occ["BRepGProp"], "VolumeProperties")(exp.Current(), props)
        vols.append(props.Mass())
        exp.Next()
    return vols


def count(occ, shape, kind):
    n = 0
    exp = occ["TopExp_Explorer"](shape, occ[kind])
    while exp.More():
        n += 1
        exp.Next()
    return n


def free_edges(occ, shape):
    """Edges of the free boundary (ShapeAnalysis_FreeBounds: edges of one face only)."""
    fb = occ["ShapeAnalysis_FreeBounds"](shape)
    return count(occ, fb.GetClosedWires(), "TopAbs_EDGE") + count(
        occ, fb.GetOpenWires(), "TopAbs_EDGE"
    )


def sidecar_for(path: Path):
    for cand in (
        path.with_suffix(".exact.json"),
        path.parent / (path.name + ".exact.json"),
    ):
        if cand.exists():
            return cand
    return None


def check_file(occ, path: Path, args):
    lines, ok = [], True
    side_path = sidecar_for(path)
    if side_path is None:
        return False, [f"{path.name}: no sidecar {path.stem}.exact.json with the exact NURBS"]
    side = json.loads(side_path.read_text())
    objects = side.get("objects", [])
    surfaces = [ExactSurface(s) for o in objects for s in o.get("surfaces", [])]
    curves = [ExactCurve(c) for o in objects for c in o.get("curves", []) + o.get("edges", [])]
    for s in surfaces:
        curves.extend(s.boundary_curves())
    curves.extend([piece for c in list(curves) for piece in c.bezier_pieces()])
    pts = [p for s in surfaces for row in s.euclid_f64() for p in row]
    pts += [p for c in curves for p in c.euclid_f64()]
    size = size_of(pts) if pts else 1.0

    shapes, warns, fails = read_file(occ, path)
    kind = "STEP" if path.suffix.lower() in (".step", ".stp") else "IGES"
    head = f"{path.name}: {kind}, {len(shapes)} shape(s) for {len(objects)} object(s)"
    if warns or fails:
        head += f", {len(warns)} warning(s), {len(fails)} fail(s)"
        lines.append(head)
        for m in (fails + warns)[:20]:
            lines.append(f"    reader: {m}")
        if fails or args.strict_warnings:
            ok = False
    else:
        lines.append(head + ", no reader messages")
    if not shapes:
        return False, lines + ["    no shape was transferred"]
    report = []
    # the rounded control points of the candidates, once per file (not per shape)
    ex_f64 = []
    for s in surfaces:
        ep, ew = s.euclid_f64(), s.weights_f64()
        ex_f64.append((s, ep, ew, [x for r in ep for x in r], [x for r in ew for x in r]))
    cands = [(c, c.euclid_f64(), c.weights_f64()) for c in curves]
    tf = tm = te = tem = tdeg = 0
    wf = we = 0.0
    for i, sh in enumerate(shapes, 1):
        an = occ["BRepCheck_Analyzer"](sh)
        valid = an.IsValid()
        vols = solids_volumes(occ, sh)
        tol = max_tolerance(occ, sh)
        desc = (
            f"    shape {i}: {str(sh.ShapeType()).split('_')[-1].lower()}, "
            f"BRepCheck {'valid' if valid else 'INVALID'}, max tolerance {tol:.1e}"
        )
        if tol > args.max_tolerance:
            ok = False
            desc += f" (ABOVE {args.max_tolerance:g}: the reader had to close gaps)"
        if vols:
            desc += ", solid volume " + ", ".join(f"{v:.9g}" for v in vols)
            if any(v <= 0 for v in vols):
                ok = False
                desc += " (NOT POSITIVE: inward orientation)"
        if path.stem in args.solids:
            # a closed object: one solid of one closed shell (STEP: MANIFOLD_SOLID_BREP;
            # IGES: the manifold solid B-rep entity 186), no free edge, positive volume
            nsol, nsh, nfree = (
                count(occ, sh, "TopAbs_SOLID"),
                count(occ, sh, "TopAbs_SHELL"),
                free_edges(occ, sh),
            )
            desc += f"; {nsol} solid(s), {nsh} shell(s), {nfree} free edge(s)"
            if len(shapes) != 1 or nsol != 1 or nsh != 1 or nfree != 0 or not vols:
                ok = False
                desc += " (MUST BE ONE CLOSED SOLID)"
        lines.append(desc)
        ok &= valid
        nf, mf, df = check_faces(occ, sh, ex_f64, size, args.samples, report)
        ne, me, de, ndeg = check_edges(occ, sh, cands, size, args.samples, report)
        tf, tm, te, tem, tdeg = tf + nf, tm + mf, te + ne, tem + me, tdeg + ndeg
        wf, we = max(wf, df), max(we, de)
    rel_f, rel_e = wf / size, we / size
    lines.append(
        f"    faces: {tm}/{tf} matched, max deviation {wf:.3e} ({rel_f:.3e} of size {size:.6g}); "
        f"edges: {tem}/{te} matched, max deviation {we:.3e} ({rel_e:.3e})"
        + (f"; {tdeg} degenerated edge(s) (collapsed sides: poles)" if tdeg else "")
    )
    for r in report[:20]:
        lines.append(f"    {r}")
    if tm != tf or tem != te or report:
        ok = False
    if rel_f > args.tol or rel_e > args.tol:
        ok = False
        lines.append(f"    deviation above the tolerance {args.tol:g}")
    return ok, lines


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", type=Path, help="directory with STEP/IGES files and their .exact.json")
    ap.add_argument("--tol", type=float, default=1e-12, help="largest relative deviation")
    ap.add_argument("--samples", type=int, default=1000, help="samples per face and per edge")
    ap.add_argument(
        "--strict-warnings", action="store_true", help="fail on reader warnings, not only fails"
    )
    ap.add_argument(
        "--max-tolerance",
        type=float,
        default=1e-6,
        help="largest vertex/edge/face tolerance after import",
    )
    ap.add_argument(
        "--fractions",
        action="store_true",
        help="evaluate with exact fractions (slow) instead of 60-digit decimals",
    )
    ap.add_argument(
        "--solids",
        nargs="*",
        default=[],
        metavar="STEM",
        help="files (by stem) of closed objects: they must arrive as one solid of one closed "
        "shell with no free edge and a positive volume",
    )
    args = ap.parse_args(argv)
    if args.fractions:
        EXACT["kind"] = "fraction"
    getcontext().prec = DECIMAL_DIGITS
    files = sorted(
        p for p in args.dir.iterdir() if p.suffix.lower() in (".step", ".stp", ".igs", ".iges")
    )
    if not files:
        print(f"no STEP or IGES files in {args.dir}")
        return 1
    occ = occ_imports()
    passed = failed = 0
    for f in files:
        try:
            ok, lines = check_file(occ, f, args)
        except Exception as e:  # a crash on one file is a failure of that file
            ok, lines = False, [f"{f.name}: checker error {type(e).__name__}: {e}"]
        print("\n".join(lines))
        print(f"    {'PASS' if ok else 'FAIL'}")
        passed += ok
        failed += not ok
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

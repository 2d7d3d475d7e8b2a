"""rcagd from Python: exact rational CAGD with certificates.

Every function builds its result with the rcagd library (the Rust crates of this
repository) through the compiled module ``rcagd._rcagd``; nothing geometric is computed
in Python. Exact numbers come back as :class:`fractions.Fraction`, float arrays as
:mod:`numpy` arrays, and every error the library reports is raised as ``ValueError``
carrying the library's message (the same text ``rcagd build`` prints).

Numbers given to rcagd may be ``int``, ``fractions.Fraction``, ``decimal.Decimal``,
``"p/q"`` strings or ``float``. A ``float`` is read as its shortest decimal ``repr``
(``0.1`` is 1/10, as in a recipe file); pass ``Fraction(x)`` for the exact binary value.
"""

from __future__ import annotations

import json as _json
import os as _os
from decimal import Decimal as _Decimal
from fractions import Fraction
from numbers import Integral as _Integral

import numpy as _np

from . import _rcagd

__version__ = _rcagd.__version__

__all__ = [
    "Certificate",
    "Object",
    "NurbsCurve",
    "NurbsSurface",
    "Imported",
    "build",
    "op",
    "ops",
    "export",
    "read_step",
    "read_iges",
    "circle_arc",
    "quadric_interpolate",
    "quadric_curve_image",
    "sphere_cover",
    "ph_curve",
    "ph_planar_curve",
    "ph_planar_offset",
    "ph_planar_hermite",
    "ph_spatial_hermite",
    "ph_hermite",
    "ph_planar_spline",
    "ph_helix",
    "ph_dph_septic",
    "canal_surface",
    "pipe",
    "pipe_ph",
    "canal_blend_spheres",
    "cyclide_blend",
    "torus",
    "dupin_cyclide",
    "pn_graph",
    "pn_support",
    "pn_model",
    "pn_ellipsoid",
    "pn_revolution",
    "pn_canal",
    "quadric_patch_image",
]


# --------------------------------------------------------------------------------------
# Values: Python → recipe JSON, recipe JSON → Python
# --------------------------------------------------------------------------------------


def _param(x):
    """A parameter value as recipe JSON: exact numbers as "p/q" strings."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, _np.ndarray):
        return _param(x.tolist())
    if isinstance(x, _np.generic):
        return _param(x.item())
    if isinstance(x, _Integral):
        return int(x)
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, float):
        # the shortest decimal that reads back as x (the library rejects "nan", "inf")
        return repr(x)
    if isinstance(x, _Decimal):
        return str(x)
    if isinstance(x, dict):
        return {str(k): _param(v) for k, v in x.items() if v is not None}
    if isinstance(x, (list, tuple)):
        return [_param(v) for v in x]
    raise ValueError(f"cannot pass a value of type {type(x).__name__} to rcagd: {x!r}")


def _frac(s):
    """An exact number of the library's JSON ("p/q" or "p") as a Fraction."""
    return Fraction(s)


def _exact(v):
    """Nested lists of "p/q" strings as nested lists of Fractions."""
    if isinstance(v, list):
        return [_exact(x) for x in v]
    return _frac(v)


class Certificate:
    """A certificate: a property decided by an exact polynomial identity.

    ``property`` is the formula, ``holds`` the verdict, ``residual`` a description of
    the residual when it fails (``None`` when it holds), ``exact`` whether the verdict
    is an exact proof.
    """

    __slots__ = ("property", "holds", "residual", "exact")

    def __init__(self, property, holds, residual, exact):
        self.property = property
        self.holds = holds
        self.residual = residual
        self.exact = exact

    def __bool__(self):
        return bool(self.holds)

    def __repr__(self):
        verdict = "holds" if self.holds else f"FAILS ({self.residual})"
        return f"<Certificate {self.property!r}: {verdict}>"


def _ocp():
    try:
        import OCP  # noqa: F401
    except ImportError as e:
        raise ImportError(
            "to_ocp needs OpenCascade's Python bindings: pip install cadquery-ocp"
        ) from e
    from OCP import Geom, gp

    class _A:
        """OCCT's arrays: ``OCP.collections`` (OCP 8) or ``TColgp``/``TColStd`` (OCP 7)."""

    try:
        from OCP import collections as c

        _A.pnt1, _A.real1, _A.int1 = c.Array1_gp_Pnt, c.Array1_double, c.Array1_int
        _A.pnt2, _A.real2 = c.Array2_gp_Pnt, c.Array2_double
    except (ImportError, AttributeError):
        from OCP import TColgp, TColStd

        _A.pnt1, _A.real1 = TColgp.TColgp_Array1OfPnt, TColStd.TColStd_Array1OfReal
        _A.int1 = TColStd.TColStd_Array1OfInteger
        _A.pnt2, _A.real2 = TColgp.TColgp_Array2OfPnt, TColStd.TColStd_Array2OfReal
    return Geom, _A, gp


def _knots_mults(knots):
    """Distinct knots and multiplicities (OpenCascade's form) of a knot vector."""
    ks, ms = [], []
    for k in knots:
        if ks and ks[-1] == k:
            ms[-1] += 1
        else:
            ks.append(k)
            ms.append(1)
    return ks, ms


def _knot_arrays(A, knot_vector):
    ks, ms = _knots_mults(knot_vector)
    knots, mults = A.real1(1, len(ks)), A.int1(1, len(ks))
    for i, (k, m) in enumerate(zip(ks, ms), start=1):
        knots.SetValue(i, float(k))
        mults.SetValue(i, m)
    return knots, mults


class NurbsCurve:
    """An exact NURBS curve: ``degree``, ``knots`` (Fractions) and homogeneous
    ``control_points`` (weight first, Fractions), as in a STEP/IGES file."""

    def __init__(self, d):
        self.degree = int(d["degree"])
        self.knots = [_frac(k) for k in d["knots"]]
        self.control_points = _exact(d["control_points"])

    def to_ocp(self):
        """This curve as an OCP ``Geom_BSplineCurve`` (rounded to float once)."""
        Geom, A, gp = _ocp()
        pts = self.control_points
        n = len(pts)
        poles = A.pnt1(1, n)
        weights = A.real1(1, n)
        for i, h in enumerate(pts, start=1):
            w = h[0]
            xyz = [float(c / w) for c in h[1:4]] + [0.0] * (4 - len(h))
            poles.SetValue(i, gp.gp_Pnt(*xyz))
            weights.SetValue(i, float(w))
        knots, mults = _knot_arrays(A, self.knots)
        return Geom.Geom_BSplineCurve(poles, weights, knots, mults, self.degree)


class NurbsSurface:
    """An exact NURBS surface: ``degree`` ``(p, q)``, ``knots_u``, ``knots_v`` and the
    homogeneous control net ``control_points[i][j]`` (``i`` along ``u``)."""

    def __init__(self, d):
        self.degree = tuple(int(x) for x in d["degree"])
        self.knots_u = [_frac(k) for k in d["knots_u"]]
        self.knots_v = [_frac(k) for k in d["knots_v"]]
        self.control_points = _exact(d["control_points"])

    def to_ocp(self):
        """This surface as an OCP ``Geom_BSplineSurface`` (rounded to float once)."""
        Geom, A, gp = _ocp()
        net = self.control_points
        nu, nv = len(net), len(net[0])
        poles = A.pnt2(1, nu, 1, nv)
        weights = A.real2(1, nu, 1, nv)
        for i, row in enumerate(net, start=1):
            for j, h in enumerate(row, start=1):
                w = h[0]
                poles.SetValue(i, j, gp.gp_Pnt(*(float(c / w) for c in h[1:4])))
                weights.SetValue(i, j, float(w))
        ku, mu = _knot_arrays(A, self.knots_u)
        kv, mv = _knot_arrays(A, self.knots_v)
        p, q = self.degree
        return Geom.Geom_BSplineSurface(poles, weights, ku, kv, mu, mv, p, q)


class Imported:
    """An object read from a STEP or IGES file: ``name``, exact ``curves`` and
    ``surfaces`` (:class:`NurbsCurve`, :class:`NurbsSurface`)."""

    def __init__(self, d):
        self.name = d["name"]
        self.curves = [NurbsCurve(c) for c in d["curves"]]
        self.surfaces = [NurbsSurface(s) for s in d["surfaces"]]

    def __repr__(self):
        return (
            f"<rcagd imported {self.name!r}: {len(self.curves)} curves, "
            f"{len(self.surfaces)} surfaces>"
        )


_FORMATS = {
    ".json": "json",
    ".step": "step",
    ".stp": "step",
    ".igs": "iges",
    ".iges": "iges",
    ".obj": "obj",
    ".stl": "stl",
    ".ply": "ply",
    ".glb": "glb",
    ".svg": "svg",
    ".png": "png",
}


def _format_of(path, format):
    if format is not None:
        return format
    p = str(path)
    if p.endswith(".exact.json"):
        return "exact"
    ext = _os.path.splitext(p)[1].lower()
    if ext not in _FORMATS:
        raise ValueError(
            f"cannot tell the format of {p!r} from its extension; pass format= "
            f"(one of {', '.join(sorted(set(_FORMATS.values())))}, exact)"
        )
    return _FORMATS[ext]


class Object:
    """One built, certified object.

    Attributes: ``name``, ``op``, ``kind`` (``"curve"``, ``"curves"``, ``"patch"``,
    ``"patches"``), ``dim``, ``degree``, ``params``, ``control_points`` (exact,
    homogeneous, weight first, Fractions), ``control_points_f64`` (numpy),
    ``certificates``, ``values`` and, for the typed functions, ``extras``: the other
    objects the op built (offsets, frames, the other interpolants), by name.
    """

    def __init__(self, raw):
        self._raw = raw
        self._json = None
        self.extras = {}

    # -- identity ------------------------------------------------------------------
    @property
    def name(self):
        return self._raw.name

    @property
    def op(self):
        return self._raw.op

    @property
    def kind(self):
        return self._raw.kind

    @property
    def dim(self):
        return self._raw.dim

    @property
    def piece_count(self):
        return self._raw.piece_count

    def __repr__(self):
        return repr(self._raw)

    # -- exact data ----------------------------------------------------------------
    def to_json(self):
        """The object's JSON (as ``rcagd build`` prints it), parsed."""
        if self._json is None:
            self._json = _json.loads(self._raw.to_json())
        return self._json

    @property
    def degree(self):
        d = self.to_json()["degree"]
        if self.kind == "patch":
            return tuple(d)
        if self.kind == "patches":
            return [tuple(x) for x in d]
        return d

    @property
    def params(self):
        return self.to_json().get("params", {})

    @property
    def control_points(self):
        """Exact homogeneous control points ``[w, w·x, w·y, …]`` as Fractions: a list
        of points (curve), of point lists (curves), a net (patch) or of nets
        (patches)."""
        return _exact(self.to_json()["control_points"])

    @property
    def control_points_f64(self):
        """The control points correctly rounded, as a numpy array (one per piece for
        ``curves`` and ``patches``)."""
        f = self.to_json()["control_points_f64"]
        if self.kind in ("curve", "patch"):
            return _np.asarray(f, dtype=float)
        return [_np.asarray(x, dtype=float) for x in f]

    @property
    def certificates(self):
        return [Certificate(*c) for c in self._raw.certificates()]

    @property
    def all_certificates_hold(self):
        return all(c.holds for c in self.certificates)

    @property
    def values(self):
        """The named values the op computed (arc length, angles, …): a dict from name to
        the exact value (a Fraction for rationals, else the JSON record)."""
        out = {}
        for v in self.to_json().get("values", []):
            if v.get("type") == "rational":
                out[v["name"]] = _frac(v["exact"])
            elif v.get("type") in ("integer", "bool", "text"):
                out[v["name"]] = v.get("exact")
            else:
                out[v["name"]] = v
        return out

    # -- evaluation ----------------------------------------------------------------
    def evaluate(self, t, piece=0):
        """Points of curve ``piece`` at the parameters ``t`` (array-like): an array of
        shape ``t.shape + (dim,)``."""
        t = _np.asarray(t, dtype=_np.float64)
        flat = _np.ascontiguousarray(t.ravel())
        out = _np.frombuffer(self._raw.eval_curve(piece, flat.tobytes()), dtype=_np.float64)
        return out.reshape(t.shape + (self.dim,))

    def evaluate_grid(self, us, vs, piece=0):
        """Points of patch ``piece`` on the grid ``us × vs``: an array of shape
        ``(len(us), len(vs), dim)``, ``[i, j] = x(us[i], vs[j])``."""
        us = _np.ascontiguousarray(us, dtype=_np.float64).ravel()
        vs = _np.ascontiguousarray(vs, dtype=_np.float64).ravel()
        out = _np.frombuffer(
            self._raw.eval_grid(piece, us.tobytes(), vs.tobytes()), dtype=_np.float64
        )
        return out.reshape(len(us), len(vs), self.dim)

    def mesh(self):
        """The triangle mesh of the patches (as the STL/OBJ exports): ``(positions
        (N, 3), normals (N, 3), triangles (M, 3) uint32)``."""
        p, n, t = self._raw.mesh()
        return (
            _np.frombuffer(p, dtype=_np.float64).reshape(-1, 3),
            _np.frombuffer(n, dtype=_np.float64).reshape(-1, 3),
            _np.frombuffer(t, dtype=_np.uint32).reshape(-1, 3),
        )

    # -- export --------------------------------------------------------------------
    def export(self, format):
        """The file contents in ``format``: json, step, iges, obj, stl, ply, glb, svg,
        png or exact (the exact NURBS sidecar)."""
        return self._raw.export(format)

    def save(self, path, format=None):
        """Writes the object to ``path`` (format from the extension unless given)."""
        data = self.export(_format_of(path, format))
        with open(path, "wb") as f:
            f.write(data)
        return path

    def exact_nurbs(self):
        """The exact NURBS of the exchange form (what STEP/IGES carry, before rounding):
        ``(curves, surfaces)`` as lists of :class:`NurbsCurve` and :class:`NurbsSurface`
        (E3, positive weights)."""
        d = _json.loads(self._raw.exact_nurbs())["objects"][0]
        return [NurbsCurve(c) for c in d["curves"]], [NurbsSurface(s) for s in d["surfaces"]]

    def to_ocp(self):
        """OpenCascade geometry: a list of ``Geom_BSplineSurface`` (patches) or
        ``Geom_BSplineCurve`` (curves), one per piece of the exchange form. Needs
        ``cadquery-ocp``; raises ImportError without it."""
        _ocp()
        curves, surfaces = self.exact_nurbs()
        return [s.to_ocp() for s in surfaces] + [c.to_ocp() for c in curves]

    def to_ocp_shape(self):
        """The object as an OpenCascade ``TopoDS_Shape``, read from rcagd's STEP export
        with OpenCascade's STEP reader: closed objects arrive as one solid (faces sewn
        along their shared exact edges). Needs ``cadquery-ocp``."""
        _ocp()
        return _step_to_ocp_shape(self.export("step"))


def _step_to_ocp_shape(data):
    import tempfile

    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPControl import STEPControl_Reader

    with tempfile.TemporaryDirectory() as d:
        path = _os.path.join(d, "object.step")
        with open(path, "wb") as f:
            f.write(data)
        reader = STEPControl_Reader()
        if reader.ReadFile(path) != IFSelect_RetDone:
            raise ValueError("OpenCascade could not read rcagd's STEP file")
        reader.TransferRoots()
        return reader.OneShape()


# --------------------------------------------------------------------------------------
# Building
# --------------------------------------------------------------------------------------


def build(recipe, float=False):
    """Builds a recipe with the same machinery as ``rcagd build`` and returns its
    objects (:class:`Object`), in the recipe's order.

    ``float=True`` builds as ``rcagd build --float``: the ops' ``f64`` instantiation
    (control points are the exact binary values of ``f64`` results, certificates are
    tolerance checks with ``exact = False``, every object has the value
    ``arithmetic = "f64"``); an op without a float path raises ``ValueError`` (``rcagd
    ops NAME`` says which ops have one).

    ``recipe``: a TOML or JSON text, a path (``str`` or ``os.PathLike``) of a ``.toml``
    or ``.json`` file, or a dict ``{"object": [{"name": …, "op": …, …}, …]}`` (a single
    object dict, or a list of them, is accepted too). Raises ``ValueError`` with the
    CLI's located diagnostics on any problem.
    """
    if isinstance(recipe, dict) and "object" not in recipe:
        recipe = {"object": [recipe]}
    elif isinstance(recipe, (list, tuple)):
        recipe = {"object": list(recipe)}
    if isinstance(recipe, dict):
        text = _json.dumps(_param(recipe))
        raws = _rcagd.build(text, "<recipe>.json", float)
    elif isinstance(recipe, _os.PathLike) or (
        isinstance(recipe, str) and "\n" not in recipe and _os.path.isfile(recipe)
    ):
        path = _os.fspath(recipe)
        with open(path, "rb") as f:
            text = f.read().decode("utf-8", errors="strict")
        raws = _rcagd.build(text, path, float)
    elif isinstance(recipe, str):
        if "\n" not in recipe and recipe.strip().lower().endswith((".toml", ".json")):
            raise ValueError(
                f"no recipe file {recipe!r} (a recipe text has at least one line break)"
            )
        raws = _rcagd.build(recipe, "<recipe>", float)
    else:
        raise ValueError(
            f"a recipe is a TOML/JSON string, a path or a dict, not {type(recipe).__name__}"
        )
    return [Object(r) for r in raws]


def op(op_name, name=None, float=False, **params):
    """Builds one object with the op ``op_name`` (any op of ``rcagd ops``); parameters
    as keyword arguments (``from_`` for ``from``; ``None`` leaves a parameter out).
    Returns the object called ``name`` (default: the op name), the op's other results
    in its ``extras``. ``float=True``: built in ``f64`` (see :func:`build`)."""
    name = name or op_name
    entry = {"name": name, "op": op_name}
    for k, v in params.items():
        if v is not None:
            entry[k[:-1] if k.endswith("_") else k] = v
    objs = build({"object": [entry]}, float=float)
    main = next((o for o in objs if o.name == name), objs[0])
    main.extras = {o.name: o for o in objs if o is not main}
    return main


def ops():
    """Every op: a dict from name to ``{"summary": …, "params": [(name, type,
    requirement, doc), …]}``."""
    return {n: {"summary": s, "params": p} for n, s, p in _rcagd.ops()}


def export(objects, path=None, format=None):
    """Several objects in one STEP, IGES, glb, JSON or exact-sidecar file. Returns the
    bytes; with ``path``, writes them there too (format from the extension unless
    given)."""
    fmt = format or (_format_of(path, None) if path is not None else None)
    if fmt is None:
        raise ValueError("export needs a path or a format")
    data = _rcagd.export_many([o._raw for o in objects], fmt)
    if path is not None:
        with open(path, "wb") as f:
            f.write(data)
    return data


def _read_text(source):
    if isinstance(source, bytes):
        return source.decode("utf-8", errors="replace")
    if isinstance(source, _os.PathLike) or (
        isinstance(source, str) and "\n" not in source and _os.path.isfile(source)
    ):
        with open(_os.fspath(source), "rb") as f:
            return f.read().decode("utf-8", errors="replace")
    return source


def read_step(source):
    """The objects of a STEP file (path or text) with exact NURBS geometry
    (:class:`Imported`), as ``rcagd_io::step_read::read_step`` reads them."""
    return [Imported(d) for d in _json.loads(_rcagd.read_step(_read_text(source)))]


def read_iges(source):
    """The objects of an IGES file (path or text), as :func:`read_step`."""
    return [Imported(d) for d in _json.loads(_rcagd.read_iges(_read_text(source)))]


# --------------------------------------------------------------------------------------
# Typed constructions (each one op of the library; see docs/recipes.md)
# --------------------------------------------------------------------------------------


def circle_arc(radius, from_, to, center=(0, 0), clockwise=False, name="circle_arc"):
    """An exact rational arc of a circle between two rational points on it (one
    quadratic rational Bézier piece per < 180°; conics as rational quadratics: G. Farin,
    *NURBS*, §5)."""
    return op("circle_arc", name, center=center, radius=radius, from_=from_, to=to,
              clockwise=clockwise)


def quadric_interpolate(points, params=None, tangents=None, degree=None,
                        quadric="unit_sphere", coefficients=None, matrix=None,
                        rational_point=None, name="quadric_interpolate"):
    """A rational curve exactly on a quadric (default the unit sphere) through the
    points (optionally with tangents), of the lowest possible degree, by the
    generalized stereographic projection (B. Jüttler, *Zur Konstruktion rationaler
    Kurven und Flächen auf Quadriken*, §2: a linear problem)."""
    return op("quadric_interpolate", name, points=points, params=params,
              tangents=tangents, degree=degree, quadric=quadric,
              coefficients=coefficients, matrix=matrix, rational_point=rational_point)


def quadric_curve_image(points, weights=None, homogeneous=False, quadric="unit_sphere",
                        coefficients=None, matrix=None, rational_point=None,
                        name="quadric_curve_image"):
    """The image of a rational Bézier curve of degree n under the generalized
    stereographic projection: a curve of degree 2n exactly on the quadric (Jüttler,
    *Zur Konstruktion rationaler Kurven und Flächen auf Quadriken*, §2)."""
    return op("quadric_curve_image", name, points=points, weights=weights,
              homogeneous=homogeneous, quadric=quadric, coefficients=coefficients,
              matrix=matrix, rational_point=rational_point)


def sphere_cover(center=(0, 0, 0), radii=(1, 1, 1), name="sphere_cover"):
    """An exact cover of the whole sphere or ellipsoid by four rational biquadratic
    patches (the generalized stereographic image of the four sign quadrants of the plane; B.
    Jüttler, *Zur Konstruktion rationaler Kurven und Flächen auf Quadriken*)."""
    return op("sphere_cover", name, center=center, radii=radii)


def ph_curve(quaternions=None, alpha=None, beta=None, start=(0, 0, 0), name="ph_curve",
             **options):
    """A spatial PH curve r' = A i A* of degree 2m+1 from the quaternion (or Hopf)
    Bernstein coefficients of A (R. T. Farouki, *Pythagorean-hodograph curves*,
    Springer 2008; S. Besednjak, *DPH-krivulje in polinomske vijačnice*, §2).
    ``options``: frame, samples, frame_length, comb, comb_scale, feed."""
    return op("ph_curve", name, quaternions=quaternions, alpha=alpha, beta=beta,
              start=start, **options)


def ph_planar_curve(preimage, start=(0, 0), name="ph_planar_curve"):
    """A planar PH curve r' = w² from the Bernstein coefficients ``[re, im]`` of the
    complex preimage w(t) (the complex representation of R. T. Farouki,
    *Pythagorean-hodograph curves*, Springer 2008)."""
    return op("ph_planar_curve", name, preimage=preimage, start=start)


def ph_planar_offset(preimage, distance, start=(0, 0), name="ph_planar_offset"):
    """The exact rational offset r + d·n (degree 2n − 1) of the planar PH curve of
    preimage w (rational offsets of PH curves: R. T. Farouki,
    *Pythagorean-hodograph curves*, Springer 2008)."""
    return op("ph_planar_offset", name, preimage=preimage, distance=distance, start=start)


def ph_planar_hermite(p0, d0, p1, d1, select="best", name="ph_planar_hermite"):
    """Planar PH quintic C¹ Hermite interpolants (R. T. Farouki, C. A. Neff, *Hermite
    interpolation by Pythagorean hodograph quintics*, Math. Comp. 64 (1995)): the best
    (least absolute rotation index) or, with ``select="all"``, all four (the others in
    ``extras``)."""
    return op("ph_planar_hermite", name, p0=p0, d0=d0, p1=p1, d1=d1, select=select)


def ph_spatial_hermite(p0, d0, p1, d1, tau0=None, tau2=None, name="ph_spatial_hermite"):
    """A spatial PH quintic C¹ Hermite interpolant with free angles φ0, φ2 given by
    ``tau0 = tan(φ0/2)``, ``tau2 = tan(φ2/2)`` (R. T. Farouki, M. al-Kandari, T.
    Sakkalis, *Hermite interpolation by rotation-invariant spatial Pythagorean-hodograph
    curves*, Adv. Comput. Math. 17 (2002)); default: the least bending energy."""
    return op("ph_spatial_hermite", name, p0=p0, d0=d0, p1=p1, d1=d1, tau0=tau0, tau2=tau2)


def ph_planar_spline(points, ends="natural", d0=None, d1=None, name="ph_planar_spline"):
    """A C² planar PH quintic spline through ``points`` (open with natural or given end
    derivatives, or closed), exact PH segments and exact C² junctions (G. Albrecht, R. T.
    Farouki, *Construction of C² Pythagorean-hodograph interpolating splines by the
    homotopy method*, Adv. Comput. Math. 5 (1996); Farouki, Kuspa, Manni, Sestini,
    *Efficient solution of the complex quadratic tridiagonal system for C² PH quintic
    splines*, Numer. Algorithms 27 (2001))."""
    return op("ph_planar_spline", name, points=points, ends=ends, d0=d0, d1=d1)


def ph_helix(a0, a1, b0, b1, f=None, g=None, w=None, start=(0, 0, 0), name="ph_helix",
             **options):
    """A polynomial helix from the line/circle seed z = (a0(1−t) + a1 t)/(b0(1−t) + b1 t)
    (complex numbers ``[re, im]``), reparametrized by f/g and/or multiplied by w
    (S. Besednjak, *DPH-krivulje in polinomske vijačnice*, §6); the axis a·r' ≡ σ is
    certified. ``options``: frame, samples, frame_length, comb, comb_scale, feed."""
    return op("ph_helix", name, a0=a0, a1=a1, b0=b0, b1=b1, f=f, g=g, w=w, start=start,
              **options)


def ph_dph_septic(h, w, alpha0, alpha1, beta0, root=0, start=(0, 0, 0),
                  name="ph_dph_septic", **options):
    """A double-PH septic with αβ' − α'β = h w² from free α0, α1, β0 and a root of the
    quadratic (5.12) (S. Besednjak, *DPH-krivulje in polinomske vijačnice*, §5.2).
    ``options``: frame, samples, frame_length, comb, comb_scale, feed."""
    return op("ph_dph_septic", name, h=h, w=w, alpha0=alpha0, alpha1=alpha1, beta0=beta0,
              root=root, start=start, **options)


def ph_hermite(p_s, d_s, p_f, d_f, name="ph_hermite"):
    """Every helical PH quintic with r(0) = p_s, r'(0) = d_s, r(1) = p_f, r'(1) = d_f
    (S. Besednjak, *DPH-krivulje in polinomske vijačnice*, ch. 9), least bending energy
    first; the others in ``extras``."""
    return op("ph_hermite", name, p_s=p_s, d_s=d_s, p_f=p_f, d_f=d_f)


def canal_surface(points, radius, weights=None, orientation="positive", method="lowest",
                  cyclographic_domain=None, name="canal_surface"):
    """The rational canal surface (envelope of spheres) of a rational spine with
    control ``points`` and a polynomial radius (Bernstein values ``radius``), exact
    over Q (D. Gruber, *Rationale Parametrisierungen von Kugelhüllflächen*, TU Wien
    2008, §2.1 Peternell–Pottmann, §2.4 Krasauskas)."""
    return op("canal_surface", name, points=points, radius=radius, weights=weights,
              orientation=orientation, method=method,
              cyclographic_domain=cyclographic_domain)


def pipe(radius, points=None, weights=None, spine_file=None, orientation="positive",
         approximate="auto", tolerance=None, name="pipe"):
    """The pipe surface of constant ``radius`` around a rational spine (control
    ``points`` or the curves of ``spine_file``), exact over Q when |m'|² is a sum of two
    rational squares; otherwise (``approximate="auto"``) exact around a G¹ spline of PH
    quintics within a certified distance ``tolerance`` of the spine (default 1e-6 of its
    size; Farouki 2008, §25.2; docs/math/pipes.md, "Pipes around any spine"); r·κ < 1
    certified (Gruber 2008, §2.1–2.4; docs/math/pipes.md)."""
    if spine_file is not None:
        spine_file = _os.path.abspath(_os.fspath(spine_file))
    return op("pipe", name, radius=radius, points=points, weights=weights,
              spine_file=spine_file, orientation=orientation, approximate=approximate,
              tolerance=tolerance)


def pipe_ph(coefficients, radius, start=(0, 0, 0), orientation="positive", name="pipe_ph"):
    """The exact rational pipe surface of constant radius around the spatial PH curve of
    quaternion preimage ``coefficients`` (R. T. Farouki, *Pythagorean-hodograph
    curves*, Springer 2008; Gruber 2008, §2; docs/math/pipes.md)."""
    return op("pipe_ph", name, coefficients=coefficients, radius=radius, start=start,
              orientation=orientation)


def canal_blend_spheres(center0, radius0, normal0, center1, radius1, normal1, offset0=0,
                        offset1=0, lambda0=None, lambda1=None, name="canal_blend_spheres"):
    """A canal-surface blend between two spheres, touching each along the circle cut by
    the plane (y − cᵢ)·nᵢ = hᵢ (``offset``), from a cubic Hermite spine/radius in R^{3,1},
    exact over Q (D. Gruber, *Rationale Parametrisierungen von Kugelhüllflächen*, ch. 2;
    M. Peternell, *Rational Parametrizations for Envelopes of Quadric Families*,
    §2.4–2.5)."""
    return op("canal_blend_spheres", name, center0=center0, radius0=radius0,
              normal0=normal0, offset0=offset0, center1=center1, radius1=radius1,
              normal1=normal1, offset1=offset1, lambda0=lambda0, lambda1=lambda1)


def cyclide_blend(sphere1, direction1, direction2, sphere2=None, point2=None, side2=1,
                  arc="blend", name="cyclide_blend"):
    """A Dupin cyclide blend between two cones or cylinders of revolution with
    intersecting or parallel axes, tangent to both along the circles where the spheres
    P₁ = ``sphere1``, P₂ touch them (M. Peternell, *Rational Parametrizations for
    Envelopes of Quadric Families*, §3.8). Spheres and directions are ``[x, y, z, r]``.
    ``arc="complement"`` gives the rest of the same cyclide instead of the blend."""
    return op("cyclide_blend", name, sphere1=sphere1, direction1=direction1,
              sphere2=sphere2, direction2=direction2, point2=point2, side2=side2, arc=arc)


def torus(major_radius, minor_radius, center=(0, 0, 0), name="torus"):
    """A ring torus (axis ∥ z) as 16 biquadratic patches with positive weights, one
    closed shell (M. Peternell, *Rational Parametrizations for Envelopes of Quadric
    Families*, §3.8, Dupin cyclides)."""
    return op("torus", name, major_radius=major_radius, minor_radius=minor_radius,
              center=center)


def dupin_cyclide(name="dupin_cyclide", **params):
    """A Dupin cyclide (Peternell, *Rational Parametrizations for Envelopes of Quadric
    Families*, §3.8); parameters as the op ``dupin_cyclide`` (``rcagd.ops()``)."""
    return op("dupin_cyclide", name, **params)


def pn_graph(coefficients, denominator=None, domain=(-1, 1, -1, 1), offset=None,
             orientation="positive", distances=None, name="pn_graph"):
    """The PN surface Λ⁻¹ of the graph y₃ = F(u, v) of the isotropic model, with exact
    offsets (M. Peternell, *Rational Parametrizations for Envelopes of Quadric
    Families*, Thm 4.3/4.4). ``coefficients[i][j]`` multiplies uⁱvʲ; each of
    ``distances`` adds an offset object to ``extras``."""
    return op("pn_graph", name, coefficients=coefficients, denominator=denominator,
              domain=domain, offset=offset, orientation=orientation, distances=distances)


def pn_support(support, support_denominator=None, a=None, b=None, c=None,
               domain=(-1, 1, -1, 1), offset=None, orientation="positive", distances=None,
               name="pn_support"):
    """The PN surface with tangent planes h + n·x = 0 and rational support function h
    (Peternell, *Rational Parametrizations for Envelopes of Quadric Families*, (4.2)),
    with exact offsets h ↦ h − d."""
    return op("pn_support", name, support=support, support_denominator=support_denominator,
              a=a, b=b, c=c, domain=domain, offset=offset, orientation=orientation,
              distances=distances)


def pn_model(points, normals, triangles, offset=None, distances=None, name="pn_model"):
    """A G¹ PN surface of parabolic Dupin cyclide pieces interpolating ``points`` with
    exact rational unit ``normals`` over a triangulation (M. Peternell, *Rational
    Parametrizations for Envelopes of Quadric Families*, §4.4: Hermite data → gradient
    data in I³ → C¹ Powell–Sabin quadratic spline → Λ⁻¹), with exact offsets."""
    return op("pn_model", name, points=points, normals=normals, triangles=triangles,
              offset=offset, distances=distances)


def pn_ellipsoid(a, b, c, domain=None, offset=None, orientation="positive", distances=None,
                 name="pn_ellipsoid"):
    """The ellipsoid x²/a² + y²/b² + z²/c² = 1 as a PN surface in the umbilic frame
    (Peternell, *Rational Parametrizations for Envelopes of Quadric Families*, §4.7),
    with exact rational offsets; √(b²−c²)·√(a²−b²) and √(ac) must be rational."""
    return op("pn_ellipsoid", name, a=a, b=b, c=c, domain=domain, offset=offset,
              orientation=orientation, distances=distances)


def pn_revolution(u, v, start=(1, 0), domain=None, offset=None, orientation="positive",
                  distances=None, name="pn_revolution"):
    """The surface of revolution (about z) of the polynomial PH profile with preimage
    (u(t), v(t)) (Bernstein coefficients): a PN surface whose offsets are the surfaces of
    revolution of the profile's offsets (Peternell, *Rational Parametrizations for
    Envelopes of Quadric Families*, ch. 4; Farouki, *Pythagorean-hodograph curves*)."""
    return op("pn_revolution", name, u=u, v=v, start=start, domain=domain, offset=offset,
              orientation=orientation, distances=distances)


def pn_canal(spine, radius, domain=None, offset=None, orientation="positive",
             distances=None, name="pn_canal"):
    """A canal surface with polynomial spine m(t) (three rows of power coefficients) and
    radius r(t) (power coefficients) as a PN surface (Peternell, *Rational
    Parametrizations for Envelopes of Quadric Families*, Cor. 4.3), with exact offsets
    (radius r + d)."""
    return op("pn_canal", name, spine=spine, radius=radius, domain=domain, offset=offset,
              orientation=orientation, distances=distances)


def quadric_patch_image(net, weights=None, homogeneous=False, quadric="unit_sphere",
                        coefficients=None, matrix=None, rational_point=None,
                        name="quadric_patch_image"):
    """The image of a rational tensor-product patch of bidegree (m, n) under the
    generalized stereographic projection: a patch of bidegree (2m, 2n) exactly on the
    quadric (B. Jüttler, *Zur Konstruktion rationaler Kurven und Flächen auf
    Quadriken*)."""
    return op("quadric_patch_image", name, net=net, weights=weights, homogeneous=homogeneous,
              quadric=quadric, coefficients=coefficients, matrix=matrix,
              rational_point=rational_point)


# --------------------------------------------------------------------------------------
# Every other op of the registry as a function with its signature and documentation
# --------------------------------------------------------------------------------------

_KEYWORDS = frozenset(__import__("keyword").kwlist)


def _op_function(op_name, summary, params):
    """A function for the op ``op_name``: required parameters first (positional or
    keyword), then the optional ones (default ``None``: the op's own default), then
    ``name``; a parameter spelled like a Python keyword takes a trailing underscore."""
    import inspect

    P = inspect.Parameter
    ordered = [p for p in params if p[2] == "required"] + [
        p for p in params if p[2] != "required"
    ]
    py = [(n + "_" if n in _KEYWORDS else n) for n, _, _, _ in ordered]
    sig = inspect.Signature(
        [
            P(pn, P.POSITIONAL_OR_KEYWORD,
              default=P.empty if req == "required" else None)
            for pn, (_, _, req, _) in zip(py, ordered)
        ]
        + [P("name", P.KEYWORD_ONLY, default=op_name),
           P("float", P.KEYWORD_ONLY, default=False)]
    )

    def function(*args, **kwargs):
        bound = sig.bind(*args, **kwargs)
        bound.apply_defaults()
        values = dict(bound.arguments)
        name = values.pop("name")
        in_f64 = values.pop("float")
        return op(op_name, name, in_f64, **values)

    lines = [summary, "", "Parameters (as in ``rcagd ops " + op_name + "``):"]
    for pn, (_, kind, req, doc) in zip(py, ordered):
        lines.append(f"    {pn}: {kind}, {req}. {doc}")
    lines.append("    name: the object's name (default: the op name).")
    lines.append("    float: build in f64 as ``rcagd build --float`` (ops with a float path only).")
    lines.append("")
    lines.append("Returns the object called ``name``; the op's other results are in its "
                 "``extras``. Errors are ``ValueError`` with the op's message.")
    function.__name__ = op_name
    function.__qualname__ = op_name
    function.__signature__ = sig
    function.__doc__ = "\n".join(lines)
    function.__module__ = __name__
    return function


for _name, _summary, _params in _rcagd.ops():
    if _name not in globals():
        globals()[_name] = _op_function(_name, _summary, _params)
        __all__.append(_name)
del _name, _summary, _params

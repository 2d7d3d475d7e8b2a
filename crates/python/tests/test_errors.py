"""Bad input raises ValueError with the library's message; no input crashes."""

import math
import random
from fractions import Fraction as F

import pytest

import rcagd


def test_library_message_for_a_violated_precondition():
    with pytest.raises(ValueError, match=r"a ring torus needs 0 < ρ < R = 1, got ρ = 2"):
        rcagd.torus(1, 2)


def test_unknown_op_and_parameter():
    with pytest.raises(ValueError, match=r'(?s)unknown op "tors".*did you mean "torus"'):
        rcagd.op("tors", major_radius=2, minor_radius=1)
    with pytest.raises(ValueError, match=r"unknown parameter `radius` for op `torus`"):
        rcagd.op("torus", major_radius=2, minor_radius=1, radius=3)


def test_missing_and_ill_typed_parameters():
    with pytest.raises(ValueError, match=r"needs the parameter `minor_radius`"):
        rcagd.op("torus", major_radius=2)
    with pytest.raises(ValueError, match=r"not a number"):
        rcagd.torus("two", 1)


@pytest.mark.parametrize("x", [math.nan, math.inf, -math.inf])
def test_non_finite_floats(x):
    with pytest.raises(ValueError):
        rcagd.torus(x, 1)


def test_unsupported_python_values():
    with pytest.raises(ValueError, match=r"cannot pass a value of type object"):
        rcagd.torus(object(), 1)
    with pytest.raises(ValueError, match=r"a recipe is a TOML/JSON string"):
        rcagd.build(42)
    with pytest.raises(ValueError, match=r"no recipe file 'missing.toml'"):
        rcagd.build("missing.toml")
    with pytest.raises(FileNotFoundError):
        import pathlib

        rcagd.build(pathlib.Path("missing.toml"))


def test_syntax_errors_are_located():
    with pytest.raises(ValueError, match=r"TOML syntax error"):
        rcagd.build("[[object]\nname = 'a'\n")
    with pytest.raises(ValueError, match=r"JSON syntax error"):
        rcagd.build('{"object": [')


def test_bad_exports_and_reads():
    c = rcagd.circle_arc(5, (5, 0), (3, 4))
    with pytest.raises(ValueError, match=r"unknown format"):
        c.export("dwg")
    with pytest.raises(ValueError):
        c.export("stl")  # a curve has no mesh
    with pytest.raises(ValueError):
        c.evaluate_grid([0.5], [0.5])  # no patch
    with pytest.raises(ValueError):
        rcagd.read_step("not a step file\n")
    with pytest.raises(ValueError):
        rcagd.read_iges("not an iges file\n")
    with pytest.raises(ValueError, match=r"cannot tell the format"):
        c.save("x.dwg")


_VALUES = [0, 1, -1, 2, F(1, 2), F(-3, 7), 0.25, "1/3", "x", True, None, [], [0], [1, 2],
           [0, 0, 0], [1, 2, 3], [[0, 0, 0], [1, 1, 1]], [[1, 0], [0, 1]],
           [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]], 10**40, F(1, 10**30)]


def test_no_input_crashes():
    """Random small parameter values for every op: each call returns objects or raises
    ValueError (never another exception, never a crash)."""
    rng = random.Random(20261203)
    for name, spec in sorted(rcagd.ops().items()):
        params = [p[0] for p in spec["params"]]
        for _ in range(3):
            kwargs = {p: rng.choice(_VALUES) for p in params if rng.random() < 0.7}
            try:
                rcagd.op(name, "fuzz", **{k + "_" if k == "from" else k: v
                                          for k, v in kwargs.items()})
            except ValueError:
                pass

"""rcagd.build(recipe, float=True): the float path (`rcagd build --float`) from Python."""

import pytest

import rcagd

CYCLIDE_TOML = """
[[object]]
name = "cyclide"
op = "dupin_canal"
rho = 2
r0 = 3
s = "1/3"
"""


def _flat(x):
    if isinstance(x, (list, tuple)):
        for y in x:
            yield from _flat(y)
    else:
        yield x


def test_build_float_agrees_with_exact_and_is_marked():
    exact = rcagd.build(CYCLIDE_TOML)
    f64 = rcagd.build(CYCLIDE_TOML, float=True)
    assert [o.name for o in f64] == [o.name for o in exact]
    e, f = exact[0], f64[0]
    assert f.kind == e.kind and f.degree == e.degree
    assert f.values["arithmetic"] == "f64"
    assert "arithmetic" not in e.values
    assert f.certificates and all(c.holds and not c.exact for c in f.certificates)
    assert all(c.exact for c in e.certificates)
    a, b = list(_flat(e.control_points)), list(_flat(f.control_points))
    scale = max(abs(x) for x in a)
    assert len(a) == len(b)
    assert all(abs(x - y) <= 1e-12 * scale for x, y in zip(a, b))


def test_op_functions_take_float():
    assert rcagd.op("circle", radius=2, float=True).values["arithmetic"] == "f64"
    assert "arithmetic" not in rcagd.op("circle", radius=2).values
    # a function generated from the registry (rcagd.circle) passes it on
    assert rcagd.circle(radius=2, float=True).values["arithmetic"] == "f64"
    assert "arithmetic" not in rcagd.circle(radius=2).values


def test_float_refuses_an_op_without_a_float_path():
    with pytest.raises(ValueError, match="has no float path"):
        rcagd.op("pn_ellipsoid", a=5, b=4, c=3, float=True)

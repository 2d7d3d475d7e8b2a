"""rcagd.build: recipes as text, paths and dicts, compared with the CLI's output."""

import json
from fractions import Fraction

import pytest

import rcagd

TORUS_TOML = """
[[object]]
name = "ring"
op = "torus"
major_radius = 2
minor_radius = "1/2"
"""


def test_build_toml_json_dict_and_path_agree(tmp_path):
    from_toml = rcagd.build(TORUS_TOML)
    as_json = json.dumps(
        {"object": [{"name": "ring", "op": "torus", "major_radius": 2, "minor_radius": "1/2"}]}
    )
    from_json = rcagd.build(as_json)
    from_dict = rcagd.build(
        {"object": [{"name": "ring", "op": "torus", "major_radius": 2,
                     "minor_radius": Fraction(1, 2)}]}
    )
    path = tmp_path / "r.toml"
    path.write_text(TORUS_TOML)
    from_path = rcagd.build(path)
    from_str_path = rcagd.build(str(path))
    objs = [from_toml, from_json, from_dict, from_path, from_str_path]
    for o in objs:
        assert len(o) == 1 and o[0].name == "ring" and o[0].kind == "patches"
        assert o[0].control_points == from_toml[0].control_points
        assert o[0].all_certificates_hold


# small recipes of the gallery, built by the CLI and by Python: same exact control
# points, same certificates, same values
@pytest.mark.parametrize("recipe", ["kernel", "ph_planar", "quadric", "ph", "canal"])
def test_build_matches_cli(recipe, root, cli_build):
    path = root / "examples" / "recipes" / f"{recipe}.toml"
    expected = cli_build(path)
    got = rcagd.build(path)
    assert [o.name for o in got] == list(expected)
    for o in got:
        e = expected[o.name]
        j = o.to_json()
        assert j["control_points"] == e["control_points"], o.name
        assert j["certificates"] == e["certificates"], o.name
        assert j.get("values") == e.get("values"), o.name
        # the Fractions are the exact strings of the CLI
        flat_cli = _flatten(e["control_points"])
        assert [Fraction(s) for s in flat_cli] == _flatten(o.control_points)


def _flatten(v):
    if isinstance(v, list):
        return [x for y in v for x in _flatten(y)]
    return [v]


def test_certificates_are_objects():
    (o,) = rcagd.build(TORUS_TOML)
    cs = o.certificates
    assert cs and all(isinstance(c, rcagd.Certificate) for c in cs)
    for c in cs:
        assert c.holds is True and c.residual is None and c.exact is True
        assert isinstance(c.property, str) and c.property


def test_ops_lists_every_op():
    ops = rcagd.ops()
    for name in ["torus", "pipe", "canal_surface", "ph_planar_hermite", "pn_graph"]:
        assert name in ops and ops[name]["summary"]
    assert any(p[0] == "radius" for p in ops["pipe"]["params"])


def test_generic_op_with_extras():
    o = rcagd.op("pn_graph", "g", coefficients=[[1, 0, "1/2"], [0, -1, 0], [0, 0, 0], ["1/3", 0, 0]],
                 domain=[0, "1/2", 0, "1/2"], distances=["1/4"])
    assert o.name == "g"
    assert list(o.extras) == ["g_offset1"]
    assert o.extras["g_offset1"].all_certificates_hold

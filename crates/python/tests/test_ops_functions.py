"""Every op of the registry is a function of the package: with the op's parameters in
its signature, its documentation and the same object as `rcagd.op`. (That the static
stubs are current is checked by `cargo test`: crates/cli/tests/it/python_stubs.rs.)"""

import inspect
import keyword

import pytest

import rcagd


def test_every_op_is_a_function_with_its_parameters():
    for name, spec in rcagd.ops().items():
        f = getattr(rcagd, name)
        assert callable(f), name
        assert name in rcagd.__all__, name
        sig = inspect.signature(f).parameters
        wanted = [n + "_" if keyword.iskeyword(n) else n
                  for n, _, _, _ in spec["params"]]
        if getattr(f, "__signature__", None) is not None:
            # generated: exactly the op's parameters, the object's name and `float`
            # (build in f64, `rcagd build --float`)
            assert sorted(sig) == sorted(wanted + ["name", "float"]), (name, list(sig), wanted)
        else:
            # hand-written: every parameter reachable, by name or through **options
            extra = any(p.kind == p.VAR_KEYWORD for p in sig.values())
            missing = [w for w in wanted if w not in sig]
            assert extra or not missing, (name, missing)
        assert f.__doc__, name


def test_generated_function_builds_the_op():
    # a generated function (not one of the 27 hand-written) against rcagd.op
    f = rcagd.sphere_family_envelope
    assert getattr(f, "__signature__", None) is not None
    args = dict(net="hyperbolic",
                points=[[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]],
                a=[[0], [0], [1]], b=[[0, 0, 1]], domain=[1, 2, "1/4", 1])
    o = f(**args)
    p = rcagd.op("sphere_family_envelope", **args)
    assert o.name == "sphere_family_envelope"
    assert o.all_certificates_hold
    assert o.control_points == p.control_points
    # positional required parameters, a custom name, an op default left out (None)
    o2 = f("hyperbolic", args["points"], args["a"], b=args["b"], domain=args["domain"],
           name="env")
    assert o2.name == "env" and o2.control_points == o.control_points
    with pytest.raises(TypeError):
        f(net="hyperbolic")  # required parameters missing
    with pytest.raises(ValueError, match="support function"):
        f(**{**args, "a": [[0, 1], [0, 0]]})  # a depends on v

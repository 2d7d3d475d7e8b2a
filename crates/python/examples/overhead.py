"""The Python side of the overhead measurement (docs/plans/python.md, "Measurements"):
a small construction per call, and the 10⁶-point grid against the Rust call
(`cargo run --profile pywheel -p rcagd-python --features timing --example grid_timing`)."""

import time
from fractions import Fraction

import numpy as np

import rcagd
from rcagd import _rcagd


def best(f, n):
    b = float("inf")
    for _ in range(n):
        s = time.perf_counter()
        f()
        b = min(b, time.perf_counter() - s)
    return b


text = '[[object]]\nname = "torus"\nop = "torus"\nmajor_radius = 2\nminor_radius = "1/2"\n'
print(f"torus via rcagd.torus: {best(lambda: rcagd.torus(2, Fraction(1, 2)), 50) * 1e3:.3f} ms")
print(f"torus via _rcagd.build (recipe text): {best(lambda: _rcagd.build(text, 'r.toml'), 50) * 1e3:.3f} ms")
s = rcagd.sphere_cover()
t = np.linspace(0, 1, 1000)
print(f"evaluate_grid 1000x1000: {best(lambda: s.evaluate_grid(t, t), 20) * 1e3:.2f} ms")
tb = t.tobytes()
print(f"_rcagd eval_grid (bytes out): {best(lambda: s._raw.eval_grid(0, tb, tb), 20) * 1e3:.2f} ms")

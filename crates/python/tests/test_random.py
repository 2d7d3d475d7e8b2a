"""Property tests with random exact inputs (seeded, 16–24 cases each): certificates hold,
and the float evaluation agrees with the defining property."""

import random
from fractions import Fraction as F

import numpy as np
import pytest

import rcagd

SEED = 20261203


def rat(rng, num=9, den=8):
    return F(rng.randint(-num, num), rng.randint(1, den))


def test_pn_graph_offsets_are_at_distance_d():
    rng = random.Random(SEED)
    built = 0
    t = np.linspace(0, 1, 9)
    for _ in range(16):
        coeffs = [[rat(rng) for _ in range(3)] for _ in range(3)]
        u0, v0 = rat(rng, 4, 4), rat(rng, 4, 4)
        domain = [u0, u0 + F(rng.randint(1, 4), 4), v0, v0 + F(rng.randint(1, 4), 4)]
        d = rat(rng, 3, 4) or F(1, 3)
        try:
            base = rcagd.pn_graph(coefficients=coeffs, domain=domain, distances=[d])
        except ValueError:
            continue  # e.g. a weight with a zero in the domain: refused with a message
        built += 1
        (off,) = base.extras.values()
        assert base.all_certificates_hold and off.all_certificates_hold
        gap = np.linalg.norm(off.evaluate_grid(t, t) - base.evaluate_grid(t, t), axis=2)
        scale = 1 + np.abs(base.evaluate_grid(t, t)).max()
        np.testing.assert_allclose(gap, float(abs(d)), rtol=0, atol=1e-9 * scale)
    assert built >= 12


def _exact_point(points, t):
    n = len(points) - 1
    from math import comb

    b = [comb(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]
    h = [sum(b[i] * p[k] for i, p in enumerate(points)) for k in range(len(points[0]))]
    return [float(c / h[0]) for c in h[1:]]


@pytest.mark.parametrize("k", [2, 3])
def test_planar_ph_curves_and_offsets(k):
    rng = random.Random(SEED + k)
    ts = np.linspace(0, 1, 7)
    curves = offsets = 0
    for _ in range(16):
        w = [[rat(rng), rat(rng)] for _ in range(k)]
        if all(a == 0 and b == 0 for a, b in w):
            continue
        start = [rat(rng), rat(rng)]
        try:
            curve = rcagd.ph_planar_curve(preimage=w, start=start)
        except ValueError:
            continue  # w ≡ 0 or a degenerate hodograph: refused with a message
        curves += 1
        assert curve.all_certificates_hold
        x = curve.evaluate(ts)
        for t, xt in zip(ts, x):
            np.testing.assert_allclose(xt, _exact_point(curve.control_points, F(t)), atol=1e-12)
        d = rat(rng, 3, 4) or F(1, 2)
        try:
            off = rcagd.ph_planar_offset(preimage=w, start=start, distance=d)
        except ValueError:
            continue  # w has a zero in [0, 1]: the unit normal is undefined there
        offsets += 1
        assert off.all_certificates_hold
        gap = np.linalg.norm(off.evaluate(ts) - x, axis=1)
        np.testing.assert_allclose(gap, float(abs(d)), rtol=1e-9, atol=1e-12)
    assert curves >= 12 and offsets >= 8, (curves, offsets)


def test_random_tori_lie_on_their_quartic():
    rng = random.Random(SEED)
    t = np.linspace(0, 1, 6)
    for _ in range(16):
        rho = F(rng.randint(1, 20), rng.randint(1, 9))
        big = rho + F(rng.randint(1, 20), rng.randint(1, 9))
        c = [rat(rng), rat(rng), rat(rng)]
        o = rcagd.torus(big, rho, center=c)
        assert o.all_certificates_hold and o.piece_count == 16
        for piece in range(16):
            g = o.evaluate_grid(t, t, piece=piece) - np.array([float(x) for x in c])
            r2 = (g**2).sum(axis=2)
            lhs = (r2 + float(big) ** 2 - float(rho) ** 2) ** 2
            rhs = 4 * float(big) ** 2 * (g[..., 0] ** 2 + g[..., 1] ** 2)
            np.testing.assert_allclose(lhs, rhs, rtol=1e-10, atol=1e-10 * float(big) ** 4)

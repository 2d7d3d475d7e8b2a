"""Peternell, "Rational Parametrizations for Envelopes of Quadric Families", Sec. 4.6 example:
the parabolic cylinder Delta with tangent planes
    [-(p/2)(1+t^2)/(2t), 2t/(1+t^2), -(1-t^2)/(1+t^2), 0]
moved by the printed one-parameter family of motions X' = X B(u),
    B = [[1+u^2, 0, 0, 0], [s u(1+u^2)/4, 1+u^2, 0, 0], [0, 0, 1-u^2, -2u], [0, 0, 2u, 1-u^2]]
(printed: s = +1). We compute the envelope point e ∩ e_t ∩ e_u for s = +1 and s = -1 and
compare with the printed point representation (p = 4 makes the printed constants 12 = 3p,
16 = 4p fit; p = 4 is the value the printed point needs).

Result: the printed point is the envelope for s = -1 (the translation part of B has the
opposite sign), not for the printed s = +1. See docs/math/laguerre-pn.md#sec-4-6-example.
"""
import sympy as sp

t, u = sp.symbols("t u")
p = sp.Integer(4)
e = sp.Matrix([[-(p / 2) * (1 + t**2) / (2 * t), 2 * t / (1 + t**2), -(1 - t**2) / (1 + t**2), 0]])

printed = sp.Matrix(
    [
        -4 * t**2 * (t**2 - 1) * (u**2 + 1),
        (2 * t**4 - u * t**2 - 12 * t**2 + 2) * (t**2 - 1) * (u**2 + 1),
        2 * t * (4 * (u**2 - 1) * (t**2 - 1) ** 2 + t**2 * u * (1 + u**2)),
        t * (16 * u * (t**2 - 1) ** 2 + t**2 * (1 - u**4)),
    ]
)


def envelope_point(s):
    B = sp.Matrix(
        [
            [1 + u**2, 0, 0, 0],
            [s * u * (1 + u**2) / 4, 1 + u**2, 0, 0],
            [0, 0, 1 - u**2, -2 * u],
            [0, 0, 2 * u, 1 - u**2],
        ]
    )
    G = (e * B).applyfunc(sp.simplify)
    rows = [G, G.diff(t), G.diff(u)]
    A = sp.Matrix([[r[1], r[2], r[3]] for r in rows])
    b = sp.Matrix([-r[0] for r in rows])
    x = A.LUsolve(b).applyfunc(sp.simplify)
    return x


for s in (1, -1):
    x = envelope_point(s)
    px = [sp.simplify(printed[i] / printed[0]) for i in range(1, 4)]
    same = all(sp.simplify(x[i] - px[i]) == 0 for i in range(3))
    print(f"translation sign s = {s:+d}: printed point is the envelope: {same}")
    if s == -1:
        assert same
    else:
        assert not same
print("ok: the printed point belongs to s = -1 (entry B[1][0] = -u(1+u^2)/4)")

#!/usr/bin/env python3
"""Symbolic check of the quaternion DPH forms (Besednjak, "DPH-krivulje in polinomske
vijačnice", Prop. 4.6, (4.12), (4.20), (4.21)); see docs/math/ph-preimage.md#dph-forms.

For A = u + v i + p j + q k with symbolic functions u, v, p, q of t:
  * (4.20)  j(αβ' − α'β) = ½ (A*A' − A'*A) × i   with α = u + iv, β = q + ip;
  * αβ' − α'β = g + i f  (not f + i g as the printed (4.18));
  * ½ C i C* = (a² − b²) j + 2ab k for C = −b + a i + a j + b k  (Prop. 4.6);
  * D i D* = 2(a² − b²) j − 4ab k for D = jC, so (4.21)
        (A*A' − A'*A) × i = h D i D*
    holds iff g + i f = h (a + i b)²  (the Hopf form), and fails for the a, b of (4.12)
    (f + i g = h (a + i b)²) unless f = g.
Run: python3 scripts/checks/dph_quaternion_forms.py  (prints "ok" or raises).
"""
import sympy as sp

t = sp.symbols("t")
u, v, p, q, a, b = (sp.Function(n)(t) for n in "uvpqab")
I = sp.I


def qmul(x, y):
    a0, a1, a2, a3 = x
    b0, b1, b2, b3 = y
    return (
        a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3,
        a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
        a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1,
        a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0,
    )


def conj(x):
    return (x[0], -x[1], -x[2], -x[3])


def sandwich_i(x):
    return qmul(qmul(x, (0, 1, 0, 0)), conj(x))


def zero(e):
    return sp.simplify(sp.expand(e)) == 0


A = (u, v, p, q)
Ad = tuple(sp.diff(c, t) for c in A)
M = tuple(x - y for x, y in zip(qmul(conj(A), Ad), qmul(conj(Ad), A)))
assert zero(M[0])
V = M[1:]
Vxi = (0, V[2], -V[1])  # V × i

alpha = u + I * v
beta = q + I * p
P = sp.expand(alpha * sp.diff(beta, t) - sp.diff(alpha, t) * beta)
g, f = sp.re(P), sp.im(P)
g = sp.expand(u * sp.diff(q, t) - sp.diff(u, t) * q - v * sp.diff(p, t) + sp.diff(v, t) * p)
f = sp.expand(u * sp.diff(p, t) - sp.diff(u, t) * p + v * sp.diff(q, t) - sp.diff(v, t) * q)
assert zero(P - (g + I * f)), "αβ' − α'β = g + i f"
# (4.20): j(g + f i) = g j − f k
jP = (0, 0, g, -f)
assert all(zero(jP[k] - sp.Rational(1, 2) * (0, *Vxi)[k]) for k in range(4)), "(4.20)"

C = (-b, a, a, b)
CiC = sandwich_i(C)
assert zero(CiC[0]) and zero(CiC[1])
assert zero(CiC[2] / 2 - (a**2 - b**2)) and zero(CiC[3] / 2 - 2 * a * b), "Prop 4.6 C"
D = qmul((0, 0, 1, 0), C)
assert all(zero(D[k] - (-a, b, -b, -a)[k]) for k in range(4)), "D = jC"
DiD = sandwich_i(D)
assert zero(DiD[1]) and zero(DiD[2] - 2 * (a**2 - b**2)) and zero(DiD[3] + 4 * a * b)
# (4.21) holds with g = h(a² − b²), f = 2hab, i.e. αβ' − α'β = g + i f = h(a + ib)²:
# (A*A' − A'*A) × i = (0, 2g, −2f) and h·D i D* = (0, 2h(a² − b²), −4hab).
assert zero(Vxi[1] - 2 * g) and zero(Vxi[2] + 2 * f)
print("ok")

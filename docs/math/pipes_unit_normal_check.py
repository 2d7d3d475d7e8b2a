"""Sympy checks of docs/math/pipes.md, "The degree of a unit normal field" (no test suite:
run `python3 docs/math/pipes_unit_normal_check.py`, it asserts and prints what it checks).

1. The 16-term discriminant of a quartic is sympy's, and every term has the factor a or b.
2. A Pythagorean V of degree <= 2 (V = C i C* with C linear, or V = h * constant) has
   disc4(|V|^2) = 0 (random examples).
3. The seed quintics: the gallery's L1 = span(p) with |p|^2 = 17t^2 - 2t + 1 (no square),
   issue 17's dim L2 = 2 with Delta of degree 12 without real roots: bound 4.
4. The quaternion factor condition does not decide it: A = (t + i + k)(t - 1 - j) has the
   unit normal A j A*/|A|^2 with a denominator of degree 2; A = (t - 1 - j)(t + i + k) has
   none of its right factors in R + R i or R + R j, yet V = (-2t, -2t, t^2 - 2) is normal
   with |V|^2 = (t^2 + 2)^2.
"""
import random

import sympy as sp
from sympy.algebras.quaternion import Quaternion as Q

t, lam = sp.symbols("t lam")
I = Q(0, 1, 0, 0)
J = Q(0, 0, 1, 0)


def disc4(F):
    a, b, c, d, e = [sp.expand(F).coeff(t, k) for k in (4, 3, 2, 1, 0)]
    return sp.expand(
        256*a**3*e**3 - 192*a**2*b*d*e**2 - 128*a**2*c**2*e**2 + 144*a**2*c*d**2*e
        - 27*a**2*d**4 + 144*a*b**2*c*e**2 - 6*a*b**2*d**2*e - 80*a*b*c**2*d*e
        + 18*a*b*c*d**3 + 16*a*c**4*e - 4*a*c**3*d**2 - 27*b**4*e**2 + 18*b**3*c*d*e
        - 4*b**3*d**3 - 4*b**2*c**3*e + b**2*c**2*d**2)


def vec(q):
    return [sp.expand(q.b), sp.expand(q.c), sp.expand(q.d)]


def norm2(v):
    return sp.expand(sum(x**2 for x in v))


def orthogonal_fields(h, d):
    cs = sp.symbols("c0:%d" % (3 * (d + 1)))
    V = [sum(cs[3*k + i] * t**k for k in range(d + 1)) for i in range(3)]
    eqs = sp.Poly(sp.expand(sum(V[i] * h[i] for i in range(3))), t).all_coeffs()
    M = sp.Matrix([[sp.diff(e, c) for c in cs] for e in eqs])
    return [[sum(v[3*k + i] * t**k for k in range(d + 1)) for i in range(3)] for v in M.nullspace()]


def bernstein_preimage(cs):
    n = len(cs) - 1
    b = [sp.binomial(n, k) * t**k * (1 - t)**(n - k) for k in range(n + 1)]
    return Q(*[sp.expand(sum(bk * c[i] for bk, c in zip(b, cs))) for i in range(4)])


def hodograph(A):
    return vec(A * I * A.conjugate())


# 1. the discriminant
a, b, c, d, e = sp.symbols("a b c d e")
f = a*t**4 + b*t**3 + c*t**2 + d*t + e
D = disc4(f)
assert sp.expand(D - sp.discriminant(f, t)) == 0
assert sp.expand(D.subs({a: 0, b: 0})) == 0
print("1. disc4 is the discriminant; every term has a or b")

# 2. Pythagorean fields of degree <= 2 have disc4(|V|^2) = 0
random.seed(1)
for _ in range(20):
    C = Q(*[random.randint(-5, 5) + random.randint(-5, 5) * t for _ in range(4)])
    V = vec(C * I * C.conjugate())
    assert sp.expand(norm2(V) - sp.expand((C * C.conjugate()).a) ** 2) == 0
    assert disc4(norm2(V)) == 0
    h = random.randint(-3, 3) + random.randint(-3, 3) * t + random.randint(-3, 3) * t**2
    V = [h * random.randint(-3, 3) for _ in range(3)]
    assert disc4(norm2(V)) == 0
print("2. Pythagorean V of degree <= 2: disc4(|V|^2) = 0 (40 random cases)")

# 3. the seed quintics
h = hodograph(bernstein_preimage([[1, 0, 0, 0], [0, 1, 0, 1], [1, 0, 1, 0]]))
L0, L1, L2 = (orthogonal_fields(h, k) for k in range(3))
assert (len(L0), len(L1), len(L2)) == (0, 1, 2)
p = L1[0]
assert sp.factor(norm2(p)) == 17*t**2 - 2*t + 1 and sp.discriminant(norm2(p), t) < 0
print("3. gallery quintic: dim L0, L1, L2 = 0, 1, 2; |p|^2 =", norm2(p), ": bound 4")
h = hodograph(bernstein_preimage([[1, 0, 0, 0], [1, 1, 0, 1], [0, 0, 1, 1]]))
L0, L1, L2 = (orthogonal_fields(h, k) for k in range(3))
assert (len(L0), len(L1), len(L2)) == (0, 0, 2)
va, vb = L2
delta = sp.Poly(disc4(norm2([lam*x + y for x, y in zip(va, vb)])), lam)
assert delta.degree() == 12 and len(sp.real_roots(delta)) == 0
assert disc4(norm2(va)) != 0
print("   issue 17's quintic: dim L0, L1, L2 = 0, 0, 2; Delta of degree 12, no real root: bound 4")

# 4. the factors of the preimage do not decide it
A = (Q(t, 1, 0, 1) * Q(t - 1, 0, -1, 0))
N = vec(A * J * A.conjugate())
s = sp.expand((A * A.conjugate()).a)
g = sp.gcd(sp.gcd(sp.gcd(N[0], N[1]), N[2]), s)
assert sp.degree(sp.cancel(s / g), t) == 2
assert sp.expand(sum(x*y for x, y in zip(N, hodograph(A)))) == 0
print("4. A = (t + i + k)(t - 1 - j): A j A*/|A|^2 has a denominator of degree",
      sp.degree(sp.cancel(s / g), t))
A = (Q(t - 1, 0, -1, 0) * Q(t, 1, 0, 1))
h = hodograph(A)
V = [-2*t, -2*t, t**2 - 2]
assert sp.expand(sum(x*y for x, y in zip(V, h))) == 0
assert sp.expand(norm2(V) - (t**2 + 2)**2) == 0
print("   A = (t - 1 - j)(t + i + k): V = (-2t, -2t, t^2 - 2) is normal, |V|^2 = (t^2 + 2)^2")
print("all checks passed")

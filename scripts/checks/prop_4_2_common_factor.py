"""Prop. 4.2 (Peternell, "Rational Parametrizations for Envelopes of Quadric Families", §4.6):
the common factor of the envelope point of a developable PN surface moved by a screw family.

Draw of `pn_motion::random_developables_under_random_motions` (isotropic cubic
y = (c0 t + c1 t² + c2 t³, c3 + t + c4 t², c5 + c6 t + c7 t² + c8 t³),
c = [3/2, -3/2, 1, 0, 3/2, -1/3, -2, -3, 4/3], screw b = [0, 4/3, 4/3, -2/3, 1/2, -3]):
the moved γ-hyperplanes G(t, u) = E(t)·[[w, 0], [a, A]](u) as rcagd builds them
(DevelopableMotionEnvelope::moved_planes). We form the raw point of the plane-field envelope
exactly as rcagd::pn::support::from_plane_field does and factor the gcd of its four
coordinates.

Result: G4 = 3 w(u) s(t) with w = 1 + u² (the family weight A44) and s the developable's plane
norm; det(n_t, n_u, n) = -864 w² s · t(12t⁴ - 30t³ + 60t² - 9t + 13); the raw point has
W = G4³Δ (w⁵s⁴ times the rest) and gcd(W, X1, X2, X3) = 972 w⁴ s³: the exact path's
point (bidegree (14, 4)) is the raw one divided by w⁴s³ (docs/math/laguerre-pn.md#prop-4-2-common-factor).
"""
import sympy as sp

t, u = sp.symbols("t u")
G = [sp.expand(sp.sympify(g, locals={"t": t, "u": u})) for g in [
    "(36)*t**6*u**3 + (-6)*t**6*u**2 + (36)*t**6*u + (-6)*t**6 + (-108)*t**5*u**3 + (18)*t**5*u**2 + (-108)*t**5*u + (18)*t**5 + (270)*t**4*u**3 + (-45)*t**4*u**2 + (270)*t**4*u + (-45)*t**4 + (-22)*t**3*u**3 + (73)*t**3*u**2 + (-150)*t**3*u + (41)*t**3 + (45)*t**2*u**3 + (9/2)*t**2*u**2 + (285)*t**2*u + (-279/2)*t**2 + (32)*t*u**3 + (96)*t*u**2 + (-128)*t*u + (-80)*t + (-36)*u**3 + (-2)*u**2 + (-36)*u + -2",
    "(-24)*t**3*u**2 + (24)*t**3 + (36)*t**2*u**2 + (-72)*t**2*u + (-36)*t**2 + (-36)*t*u**2 + (-48)*t*u + (36)*t",
    "(48)*t**3*u + (-36)*t**2*u**2 + (-72)*t**2*u + (36)*t**2 + (-24)*t*u**2 + (72)*t*u + (24)*t",
    "(12)*t**6*u**2 + (12)*t**6 + (-36)*t**5*u**2 + (-36)*t**5 + (90)*t**4*u**2 + (90)*t**4 + (-18)*t**3*u**2 + (-18)*t**3 + (39)*t**2*u**2 + (39)*t**2 + (-12)*u**2 + -12",
    "(12)*t**6*u**2 + (12)*t**6 + (-36)*t**5*u**2 + (-36)*t**5 + (90)*t**4*u**2 + (90)*t**4 + (-18)*t**3*u**2 + (-18)*t**3 + (39)*t**2*u**2 + (39)*t**2 + (12)*u**2 + 12",
]]
n0, n = G[4], G[1:4]
assert sp.expand(sum(v * v for v in n) - n0**2) == 0
nt = [sp.diff(v, t) for v in n]
nu = [sp.diff(v, u) for v in n]
delta = sp.expand(sp.Matrix([nt, nu, n]).det())
hn, hd = G[0], G[4]
eta_t = sp.expand(sp.diff(hn, t) * hd - hn * sp.diff(hd, t))
eta_u = sp.expand(sp.diff(hn, u) * hd - hn * sp.diff(hd, u))
a = sp.Matrix(nu).cross(sp.Matrix(n))
b = sp.Matrix(n).cross(sp.Matrix(nt))
X = [sp.expand(-(hn * hd * delta * n[i] + n0**2 * (eta_t * a[i] + eta_u * b[i]))) for i in range(3)]
W = sp.expand(hd**2 * delta * n0)
g = sp.gcd(sp.gcd(sp.gcd(W, X[0]), X[1]), X[2])
w = 1 + u**2
s = sp.factor_list(G[4])[1][1][0] if sp.degree(sp.factor_list(G[4])[1][0][0], t) == 0 else sp.factor_list(G[4])[1][0][0]
print("G4 =", sp.factor(G[4]))
print("delta =", sp.factor(delta))
print("gcd =", sp.factor(g))
assert sp.simplify(g / (w**4 * s**3)).is_number
Wr = sp.cancel(W / g)
print("reduced bidegrees: W", (sp.degree(Wr, t), sp.degree(Wr, u)),
      "X", [(sp.degree(sp.cancel(x / g), t), sp.degree(sp.cancel(x / g), u)) for x in X])
print("OK: the common factor is w(u)^4 s(t)^3")

"""Cone of revolution spanned by two oriented spheres (Peternell, Thm 4.5 / (4.5)-(4.19)).

Checks (sympy, exact):
1. the vertex form of the cone, Phi_V(x) = ((x-V).M)^2 - (|M|^2-R^2)|x-V|^2 with
   V = (r2 m1 - r1 m2)/(r2 - r1), is identical with the vertex-free form
   Phi(x) = ((x-m1).M + r1 R)^2 - (|M|^2 - R^2)(|x-m1|^2 - r1^2)
   used by the library (valid also for R = 0, where the cone is a cylinder);
2. the contact point x = m1 + r1 n of a common oriented tangent plane (n.M = -R, |n| = 1)
   lies on Phi.
See docs/math/laguerre-pn.md#cone-of-two-cycles.
"""
import sympy as sp

x = sp.Matrix(sp.symbols("x1:4"))
m1 = sp.Matrix(sp.symbols("a1:4"))
m2 = sp.Matrix(sp.symbols("b1:4"))
r1, r2 = sp.symbols("r1 r2")
M = m1 - m2
R = r1 - r2
V = (r2 * m1 - r1 * m2) / (r2 - r1)
q = M.dot(M) - R**2
phi_v = ((x - V).dot(M)) ** 2 - q * (x - V).dot(x - V)
phi = ((x - m1).dot(M) + r1 * R) ** 2 - q * ((x - m1).dot(x - m1) - r1**2)
print("Phi_V - Phi =", sp.factor(sp.together(phi_v - phi)))
assert sp.simplify(phi_v - phi) == 0, "vertex form and vertex-free form differ"

# contact point of a plane with unit normal n, n.M = -R
n1, n2 = sp.symbols("n1 n2")
# choose M along e3 by rotation invariance: M = (0, 0, L), then n3 = -R/L
L = sp.symbols("L", positive=True)
sub = {m1[0]: 0, m1[1]: 0, m1[2]: 0, m2[0]: 0, m2[1]: 0, m2[2]: -L}
n3 = -R / L
nv = sp.Matrix([n1, n2, n3])
xc = m1.subs(sub) + r1 * nv
val = phi.subs(sub).subs(dict(zip(x, xc)))
val = sp.simplify(val.subs(n2**2, 1 - n1**2 - n3**2).expand())
print("Phi at the contact point (with |n| = 1):", sp.simplify(val.subs(n2, sp.sqrt(1 - n1**2 - n3**2))))
assert sp.simplify(val.subs(n2, sp.sqrt(1 - n1**2 - n3**2))) == 0
print("ok")

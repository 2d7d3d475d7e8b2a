"""The envelope of a two-parameter sphere family, recognized from its centres and radii.

Every op of rcagd is a Python function with the op's parameters (`help(rcagd.NAME)`); this
one takes the sphere family with centres (−u², 2u, 2v) and radii 4u + v² (D. Gruber,
*Rationale Parametrisierungen von Kugelhüllflächen*, 2008, (3.15)), finds the line net of
its normal lines and the support functions, and builds the rational envelope Ψ(s, t) with
its certificates (every point on its sphere, tangent to it). The same family with rational
support functions on the net works too (`a_denominator`).

    pip install ./crates/python
    python examples/python/sphere_family.py [OUT.step]
"""

import sys

import rcagd

env = rcagd.sphere_family_recognize(
    centre=[[[0, 0, 0], [0, 0, 2]], [[0, 2, 0], [0, 0, 0]], [[-1, 0, 0], [0, 0, 0]]],
    radius=[[0, 0, 1], [4, 0, 0]],
    domain=[1, 2, "1/4", 1],
    name="recognized",
)
print(f"{env.name}: {env.kind}, degree {env.degree}, "
      f"{len(env.certificates)} certificates, all hold: {env.all_certificates_hold}")

# the same net with a rational support function a = u²/(1 + u²)
rational = rcagd.sphere_family_envelope(
    "hyperbolic",
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 2, 0, 1], [0, 0, 1, 0]],
    [[0], [0], [1]],
    b=[[0, 0, 1]],
    a_denominator=[[1], [0], [1]],
    domain=[1, 2, "1/4", 1],
    name="rational_support",
)
print(f"{rational.name}: degree {rational.degree}, all hold: {rational.all_certificates_hold}")
assert env.all_certificates_hold and rational.all_certificates_hold

if len(sys.argv) > 1:
    rcagd.export([env, rational], sys.argv[1])
    print(f"wrote {sys.argv[1]}")

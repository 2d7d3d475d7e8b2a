"""The exact arc length of a PH curve against numerical quadrature, optionally plotted.

A Pythagorean-hodograph curve has a polynomial speed |r'(t)| = σ(t), so its arc length
is an exact rational number; rcagd reports it (value `arc_length`) for the spatial PH
quintic Hermite interpolant of Farouki, al-Kandari and Sakkalis. The polyline through
n points of the float evaluation (`Object.evaluate`, numpy, no Python loop) converges to
it; with matplotlib installed the curve and the convergence are plotted to a PNG.

    pip install ./crates/python [matplotlib]
    python examples/python/ph_arc_length.py [OUT.png]
"""

import sys
from fractions import Fraction

import numpy as np

import rcagd

curve = rcagd.ph_spatial_hermite(p0=(0, 0, 0), d0=(1, 0, 0),
                                 p1=(Fraction(-1, 15), Fraction(9, 5), Fraction(-1, 15)),
                                 d1=(-1, 2, 2), tau0=0, tau2=0)
exact = curve.values["arc_length"]
print(curve)
print(f"exact arc length: {exact} = {float(exact):.15f}")

ns = np.array([4, 8, 16, 32, 64, 128, 256, 512, 1024])
errors = []
for n in ns:
    x = curve.evaluate(np.linspace(0, 1, n + 1))
    length = np.linalg.norm(np.diff(x, axis=0), axis=1).sum()
    errors.append(abs(float(exact) - length))
    print(f"polyline of {n:5d} segments: {length:.15f} (error {errors[-1]:.2e})")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot")
    sys.exit(0)

out = sys.argv[1] if len(sys.argv) > 1 else "ph_arc_length.png"
fig = plt.figure(figsize=(10, 4.5))
ax = fig.add_subplot(1, 2, 1, projection="3d")
x = curve.evaluate(np.linspace(0, 1, 200))
ax.plot(x[:, 0], x[:, 1], x[:, 2])
ax.set_title(f"spatial PH quintic, arc length {exact}")
ax2 = fig.add_subplot(1, 2, 2)
ax2.loglog(ns, errors, "o-")
ax2.set_xlabel("polyline segments")
ax2.set_ylabel("|exact − polyline length|")
ax2.set_title("polyline length → exact arc length")
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out)

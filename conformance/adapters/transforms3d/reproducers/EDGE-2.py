#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quat2axangle and qlog at small angles, clause EDGE-2.

EDGE-2 (spec/SPEC.md 9): for rotation angles from 1e-9 to 1e-3 rad the result is within the operation's own
class (eps16 here: loose bar 256 eps), "Series or well-conditioned formulas (atan2, sin x/x by series) are
required; acos-based angles fail here". transforms3d 0.4.2 takes both angles from an arccos of the scalar
part: quat2axangle theta = 2 * math.acos(w) (quaternions.py:588) and qlog's vector part
v/|v| * np.arccos(w/|q|) (quaternions.py:371). Near w = 1 the rounding of w (eps/2) costs sqrt(eps) of
angle: every rotation below ~2e-8 rad comes out with angle 0 and a zero log, and larger small angles
carry errors of ~1e-16/theta rad. atan2(|v|, w) is accurate at every angle.
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys

CLAUSE = "EDGE-2"
try:
    from importlib.metadata import version
    import numpy as np
    import mpmath
    from transforms3d import quaternions as tq
    VERSION = version("transforms3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: transforms3d ? %s: SKIP: cannot import transforms3d: %s" % (CLAUSE, exc))
    sys.exit(77)

mpmath.mp.prec = 256
EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex


def mp(values):
    return [mpmath.mpf(c) for c in values]


print("rotorcert reproducer: transforms3d %s %s: quat2axangle and qlog take the angle from acos(w) and return "
      "angle 0 / log 0 for rotations of ~3e-8 rad" % (VERSION, CLAUSE))
shown = False
# rotorcert's worst inputs (family "angle 1e-9 .. 1e-3", seed 1), stored (x, y, z, w); transforms3d takes [w, x, y, z].
cases = [
    ("quat2axangle", "vector, theta = transforms3d.quaternions.quat2axangle([w, x, y, z])",
     ["-0x1.c181402922e2dp-28", "0x1.9a2d47ed1ca6bp-27", "0x1.4a5a7bddeba11p-29", "0x1.fffffffffffffp-1"]),
    ("qlog", "transforms3d.quaternions.qlog([w, x, y, z])[1:]  (the vector part: (theta/2) u for a unit q)",
     ["-0x1.970f0a062d178p-27", "0x1.d029ec0b0ce76p-31", "-0x1.ce8d81387e9d6p-28", "0x1.fffffffffffffp-1"]),
]
for name, call, hexes in cases:
    x, y, z, w = (h(s) for s in hexes)
    X, Y, Z, W = mp((x, y, z, w))
    nv = mpmath.sqrt(X * X + Y * Y + Z * Z)
    half = mpmath.atan2(nv, W)  # theta/2
    if name == "quat2axangle":
        vector, theta = tq.quat2axangle(np.array([w, x, y, z]))
        got = "theta = %s (%r), vector = [%s]" % (float(theta).hex(), float(theta), ", ".join(float(c).hex() for c in vector))
        ref = 2 * half
        want = "theta = 2 atan2(|v|, w) = %s (%s)" % (float(ref).hex(), mpmath.nstr(ref, 17))
        err = abs(mpmath.mpf(float(theta)) - ref)
        what = "absolute error of theta"
    else:
        v = tq.qlog(np.array([w, x, y, z]))[1:]
        got = "[%s]" % ", ".join(float(c).hex() for c in v)
        ref = [half * c / nv for c in (X, Y, Z)]
        want = "atan2(|v|, w) v/|v| = [%s]" % ", ".join(float(c).hex() for c in ref)
        err = mpmath.sqrt(sum((mpmath.mpf(float(g)) - r) ** 2 for g, r in zip(v, ref)))
        what = "METRIC-5, Euclidean"
    err_eps = float(err / EPS)
    bad = not (err_eps <= LOOSE)
    shown = shown or bad
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hexes))
    print("  library: %s" % got)
    print("  correct: %s (256-bit mpmath)" % want)
    print("  error:   %s rad = %.4g eps (%s; bar %d eps)%s" % (mpmath.nstr(err, 6), err_eps, what, LOOSE,
                                                              "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternions.qlog near a full turn, clause LOG-1.

LOG-1 (spec/SPEC.md 8.2): the rotation log of q is atan2(|v|, w) v/|v| = (theta/2) u, principal branch,
tolerance eps16 (METRIC-5, loose bar 256 eps). transforms3d 0.4.2 qlog ("Return natural logarithm of
quaternion") computes the vector part as v/vnorm * np.arccos(w/qnorm_) (quaternions.py:371). arccos is
ill-conditioned at +-1: near a full turn (w -> -1, |v| ~ 1e-8) the rounding of w/|q| (eps/2) moves
arccos by ~eps/|v|, here 1.4e-8 rad; near the identity the same makes the log of rotations below ~2e-8
rad exactly 0 (EDGE-2). atan2(|v|, w) has no such loss. (transforms3d's qlog also returns qeye, i.e.
[1, 0, 0, 0], for q with v = 0 -- log(1) should be 0 -- but its vector part, the rotation log, is 0 there.)
Upstream: no matching issue found in matthew-brett/transforms3d (issue #23 / PR #24 added qlog/qexp).
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys

CLAUSE = "LOG-1"
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
# rotorcert's worst input (log, "near a full turn: 2 pi - 1e-9 .. 1e-1", seed 1), stored (x, y, z, w);
# transforms3d takes [w, x, y, z].
hexes = ["-0x1.a84342447b0abp-27", "-0x1.a211ea065eb7dp-28", "-0x1.af698e602caa4p-29", "-0x1.fffffffffffffp-1"]
x, y, z, w = (h(s) for s in hexes)
v = tq.qlog(np.array([w, x, y, z]))[1:]
X, Y, Z, W = (mpmath.mpf(c) for c in (x, y, z, w))
nv = mpmath.sqrt(X * X + Y * Y + Z * Z)
ref = [mpmath.atan2(nv, W) * c / nv for c in (X, Y, Z)]
err = mpmath.sqrt(sum((mpmath.mpf(float(g)) - r) ** 2 for g, r in zip(v, ref)))
err_eps = float(err / EPS)
shown = not (err_eps <= LOOSE)
print("rotorcert reproducer: transforms3d %s %s: qlog takes the angle from arccos(w/|q|) and is off by 1.4e-8 rad "
      "near a full turn" % (VERSION, CLAUSE))
print("  call:    transforms3d.quaternions.qlog([w, x, y, z])[1:]  (the vector part: (theta/2) u)")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hexes))
print("  library: [%s]" % ", ".join(float(c).hex() for c in v))
print("  correct: atan2(|v|, w) v/|v| = [%s] (256-bit mpmath)" % ", ".join(float(c).hex() for c in ref))
print("  error:   %s rad = %.4g eps (METRIC-5, Euclidean; bar %d eps)%s" % (mpmath.nstr(err, 6), err_eps, LOOSE,
                                                                           "  <-- DEFECT" if shown else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

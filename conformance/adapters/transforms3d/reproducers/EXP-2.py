#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d qexp(qlog(q)) near a full turn, clause EXP-2.

EXP-2 (spec/SPEC.md 8.2): exp(log R) = R for every unit R, including w < 0; tolerance eps16, METRIC-1 of
exp(log q) against q (the rotation angle between them, sign-blind), loose bar 256 eps. transforms3d 0.4.2
qlog takes the angle from np.arccos(w/|q|) (quaternions.py:371), which loses about sqrt(eps) of accuracy
near w = +-1 (LOG-1): near a full turn the round trip through qexp comes back a whole 3e-8 rad (1.4e8 eps)
away from q -- qexp itself (quaternions.py:336-338) is accurate.
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys

CLAUSE = "EXP-2"
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


def metric1(a, b):
    """METRIC-1: 4 atan2(min(|a - b|, |a + b|), max(...)) of the normalised quaternions, in 256-bit mpmath."""
    a = [mpmath.mpf(float(c)) for c in a]
    b = [mpmath.mpf(float(c)) for c in b]
    na, nb = mpmath.sqrt(sum(c * c for c in a)), mpmath.sqrt(sum(c * c for c in b))
    a, b = [c / na for c in a], [c / nb for c in b]
    d = mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))
    s = mpmath.sqrt(sum((p + q) ** 2 for p, q in zip(a, b)))
    return 4 * mpmath.atan2(min(d, s), max(d, s))


# rotorcert's worst input (log_exp_round_trip, "near a full turn: 2 pi - 1e-9 .. 1e-1", seed 1), stored
# (x, y, z, w); transforms3d takes [w, x, y, z].
hexes = ["0x1.ed1af5cf74d79p-28", "-0x1.e93ee2f4806bp-28", "-0x1.9dd6dc9667343p-27", "-0x1.fffffffffffffp-1"]
x, y, z, w = (h(s) for s in hexes)
q = np.array([w, x, y, z])
back = tq.qexp(np.r_[0.0, tq.qlog(q)[1:]])  # the rotation log is qlog's vector part; exp of it
err = metric1(back, q)
err_eps = float(err / EPS)
shown = not (err_eps <= LOOSE)
print("rotorcert reproducer: transforms3d %s %s: qexp(qlog(q)) comes back 3e-8 rad away from q near a full turn "
      "(qlog's arccos)" % (VERSION, CLAUSE))
print("  call:    l = transforms3d.quaternions.qlog([w, x, y, z]); transforms3d.quaternions.qexp([0, l[1], l[2], l[3]])")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hexes))
print("  library: qexp(...) (w, x, y, z) = [%s]" % ", ".join(float(c).hex() for c in back))
print("  correct: q itself (w, x, y, z) = [%s]" % ", ".join(float(c).hex() for c in q))
print("  error:   %s rad = %.4g eps (METRIC-1 rotation distance, 256-bit mpmath; bar %d eps)%s"
      % (mpmath.nstr(err, 6), err_eps, LOOSE, "  <-- DEFECT" if shown else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

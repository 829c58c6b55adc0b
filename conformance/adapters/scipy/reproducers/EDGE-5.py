#!/usr/bin/env python3
"""rotorcert reproducer: scipy Rotation.from_quat and RigidTransform.from_dual_quat at scales 2^+-900, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q means the rotation q/|q| at every scale the format holds, and
a dual quaternion with a nonzero real part the rigid motion of its DQ-4 normalisation (class eps16, loose
bar 256 eps). Rotation.from_quat documents that "Each quaternion will be normalized to unit norm"
(scipy/spatial/transform/_rotation.py:411-413) but normalises without scaling:
_rotation_cy.pyx:58-70 `_normalize4` computes sqrt(x*x + y*y + z*z + w*w), which overflows to inf
for |q| >~ 2^511 (every component then divides to 0: the zero quaternion, returned as a rotation) and
underflows to 0 for |q| <~ 2^-538 (then from_quat raises "Found zero norm quaternions" for a nonzero
quaternion). Every Rotation call on such a q inherits it (as_quat, apply, as_matrix, as_rotvec, Slerp).
RigidTransform.from_dual_quat ("Initialize from a unit dual quaternion ... This function will enforce both
properties through normalization", _rigid_transform.py:809-822) normalises with
np.linalg.norm(real_part) (_rigid_transform_cy.pyx:378), unscaled too: at 2^-900 the norm underflows to 0
and the "real quaternion is 0" special case (:380-383) replaces the real part by the identity; at 2^900 it
overflows and the rotation is lost. A scaled norm (divide by the largest |component| first, or hypot) fixes
both.
Upstream: no matching issue found in scipy/scipy.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    from scipy.spatial.transform import RigidTransform, Rotation
    import numpy as np
    VERSION = version("scipy")
    np.seterr(all="ignore")  # numpy's overflow warnings; the numbers are the same
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, square root and quotients

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex


def unit(q):
    """q/|q| to 60 digits (scipy's order [x, y, z, w])."""
    n = sum(D(c) * D(c) for c in q).sqrt()
    return [D(c) / n for c in q]


def distance(got, ref):
    """METRIC-1 in radians, sign-free: 4 atan2(min(|a-b|, |a+b|), max(...)) of the normalised got."""
    if not all(math.isfinite(c) for c in got) or not any(got):
        return math.nan
    g = unit(got)
    m = sum((a - b) ** 2 for a, b in zip(g, ref)).sqrt()
    p = sum((a + b) ** 2 for a, b in zip(g, ref)).sqrt()
    return 4 * math.atan2(float(min(m, p)), float(max(m, p)))


DUAL_TINY = [h("0x1.60a82e345bbf9p-908"), h("0x1.21f07bc6e8a49p-898"), h("-0x1.3e8a4297c4a3dp-902"), h("-0x1.495757f9c13bcp-899")]
DUAL_HUGE = [h("-0x1.8bbfe6a094f28p+900"), h("-0x1.728b6e9f9f6e7p+901"), h("-0x1.96a822314cc39p+897"), h("-0x1.4ba8209c15672p+895")]
QUAT = "Rotation.from_quat(q).as_quat()"
DUAL = "RigidTransform.from_dual_quat(q + dual).as_dual_quat()[:4]"
cases = [  # (call, function, q, dual part or None): the certificate's inputs
    (QUAT, lambda q: list(Rotation.from_quat(q).as_quat()), [h("0x1p+1023")] * 4, None),  # EX-NORM-1-f
    (QUAT, lambda q: list(Rotation.from_quat(q).as_quat()),
     [h("-0x1.9703639b69f7dp-901"), h("0x1.093576b6aec89p-904"), h("-0x1.5c9d7d721bb1cp-900"), h("0x1.1ba0deb1ff762p-902")], None),
    (DUAL, lambda q: list(RigidTransform.from_dual_quat(q + DUAL_TINY).as_dual_quat()[:4]),
     [h("-0x1.9703639b69f7dp-901"), h("0x1.093576b6aec89p-904"), h("-0x1.5c9d7d721bb1cp-900"), h("0x1.1ba0deb1ff762p-902")], DUAL_TINY),
    (DUAL, lambda q: list(RigidTransform.from_dual_quat(q + DUAL_HUGE).as_dual_quat()[:4]),
     [h("0x1.43c518fb3ef4dp+891"), h("-0x1.61cc48a581d8ep+890"), h("0x1.e527c3bb01e85p+898"), h("0x1.72b28806d143fp+899")], DUAL_HUGE),
]

print("rotorcert reproducer: scipy %s %s: from_quat and from_dual_quat normalise without scaling: at |q| ~ 2^900 "
      "the rotation becomes 0 or the identity, at 2^-900 'zero norm' or the identity" % (VERSION, CLAUSE))
shown = False
for call, fn, q, dual in cases:
    ref = unit(q)
    try:
        got = [float(c) for c in fn(q)]
        result = "[%s]" % ", ".join(c.hex() for c in got)
        err = distance(got, ref)
    except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
        result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
    bad = not (err / EPS <= LOOSE)
    shown = shown or bad
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    if dual:
        print("           dual = [%s] (the real part q decides the rotation)" % ", ".join(c.hex() for c in dual))
    print("  library: %s" % result)
    print("  correct: [%s] (q/|q|, 60 digits; -q is the same rotation)" % ", ".join(float(c).hex() for c in ref))
    print("  error:   %s rad = %s eps (METRIC-1; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

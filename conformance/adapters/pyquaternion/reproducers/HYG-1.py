#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion's Quaternion.slerp modifies its endpoints in place, clause HYG-1.

HYG-1 (spec/SPEC.md 9a): after a call every input holds what it held before. Quaternion.slerp
normalises its endpoints with _fast_normalise() and flips q0 onto q1's hemisphere with in-place
assignment to q0.q (pyquaternion/quaternion.py, slerp), so the caller's own Quaternion objects
change: q0 = 1 comes back as -1 when q0 . q1 < 0, and a non-unit q0 comes back normalised. A caller
who interpolates a keyframe track with slerp(key[i], key[i + 1], t) finds its keys changed.
Upstream: known: KieranWynn/pyquaternion#39, fixed by PR #47 ("Remove implicit normalisation",
merged 2019-11-10; its description targets 1.0): the installed 0.9.9 still mutates.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "HYG-1"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)

print("rotorcert reproducer: pyquaternion %s %s: Quaternion.slerp modifies its endpoints" % (VERSION, CLAUSE))
# The suite's worst input (EX-SLERP-1-e): a = 1, b = -(a quarter turn about z), t = 1/2 ([x, y, z, w]).
a = [0.0, 0.0, 0.0, 1.0]
b = [0.0, 0.0, -float.fromhex("0x1.6a09e667f3bcdp-1"), -float.fromhex("0x1.6a09e667f3bcdp-1")]
q0 = Quaternion(a[3], a[0], a[1], a[2])
q1 = Quaternion(b[3], b[0], b[1], b[2])
before = [list(map(float, q0.elements)), list(map(float, q1.elements))]
Quaternion.slerp(q0, q1, amount=0.5)
after = [list(map(float, q0.elements)), list(map(float, q1.elements))]
shown = after != before
print("  call:    Quaternion.slerp(q0, q1, amount=0.5)")
print("  input:   q0 (w, x, y, z) = [%s], q1 = [%s]" % tuple(", ".join(c.hex() for c in q) for q in before))
print("  after:   q0 = [%s], q1 = [%s]%s" % (tuple(", ".join(c.hex() for c in q) for q in after) +
                                           ("  <-- DEFECT" if shown else "",)))
print("  correct: q0 and q1 unchanged")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

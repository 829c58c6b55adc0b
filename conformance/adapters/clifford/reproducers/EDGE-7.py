#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.exp() and .normal() of non-finite input, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR (an error, or all output
components NaN). MultiVector.exp() is clifford.taylor_expansions.exp, whose scaling loop starts from
max_val = int(max|coefficient|) in numba's 64-bit int: for a NaN or Inf coefficient the conversion
gives a negative number and `while max_val: max_val >>= 1` never ends, so exp() NEVER RETURNS
(from_axis_angle-style exp(-theta/2 I u^) and interpolate_rotors with t = NaN/Inf hang the same way).
MultiVector.normal() passes Inf through silently: (0, inf, 0, 1) normalises to (0, nan, 0, 0).
Neither function documents a finiteness precondition.
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import multiprocessing
import sys
import warnings

CLAUSE = "EDGE-7"
try:
    import clifford
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's inf/nan RuntimeWarnings; they change no value

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12; clifford.Cl(3) names e12, e13, e23 and e31 = -e13, so
# R = w - x*e23 + y*e13 - z*e12, back x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar]. A
# quaternion-view log v = (x, y, z) is the bivector -(x e23 + y e31 + z e12) = -x*e23 + y*e13 - z*e12.
# The coefficients are set by blade (R[(2, 3)] = ...), not as w - x*e23 + ...: inf * e23 would put
# 0 * inf = NaN into every other coefficient.
layout, blades = clifford.Cl(3)
e12 = blades["e12"]


def mv(s, b23, b13, b12):
    M = layout.MultiVector()
    M[()], M[(2, 3)], M[(1, 3)], M[(1, 2)] = s, b23, b13, b12
    return M


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


def returns_within(fn, seconds):  # runs fn in a forked child; False if it is still running after `seconds`
    child = multiprocessing.get_context("fork").Process(target=fn)
    child.start()
    child.join(seconds)
    if child.is_alive():
        child.kill()
        child.join()
        return False
    return True


print("rotorcert reproducer: clifford %s %s: MultiVector.exp() of a bivector with a NaN or Inf coefficient "
      "never returns; normal() turns Inf into a partly-NaN rotor with no error" % (clifford.__version__, CLAUSE))
(0.5 * e12).exp()  # compile the numba code here, so that the child below only runs it
shown = False
for v in ([0.0, 0.0, math.nan], [0.0, 0.0, math.inf]):
    B = mv(0.0, -v[0], v[1], -v[2])
    ok = returns_within(B.exp, 3.0)
    shown = shown or not ok
    print("  call:    B[(2, 3)], B[(1, 3)], B[(1, 2)] = -x, y, -z; B.exp()   (a finite B takes well under 1 ms)")
    print("  input:   v (x, y, z) = [%s]" % ", ".join(c.hex() for c in v))
    print("  library: %s" % ("returned" if ok else "did not return within 3 s (stopped)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]")

q = [0.0, math.inf, 0.0, 1.0]
got = quat(mv(q[3], -q[0], q[1], -q[2]).normal())
refused = all(math.isnan(c) for c in got)  # RESULT-2: all outputs NaN counts as DOMAIN_ERROR
shown = shown or not refused
print("  call:    R[()], R[(2, 3)], R[(1, 3)], R[(1, 2)] = w, -x, y, -z; R.normal()")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: [%s]%s" % (", ".join(c.hex() for c in got), "" if refused else "  (partly finite, no error)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

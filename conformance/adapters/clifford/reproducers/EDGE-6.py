#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) zero axis and zero quaternion, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero quaternion and a zero axis (AXANG-2) are DOMAIN_ERROR (an error, or
every output component NaN). clifford has no axis-angle constructor; its documented rotor idiom is
R = e^(-theta/2 B^) with the unit plane B^ = I u/|u| (tutorial g3-algebra-of-space, "Rotation").
For u = 0, u.normal() is 0/0 = NaN and MultiVector.exp() of a NaN bivector NEVER RETURNS (its
Taylor-series scaling loop, see EDGE-7). tools.g3.quaternion_to_matrix ("Converts a quaternion into a
rotation matrix") maps the zero quaternion to the identity matrix without any error.
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import multiprocessing
import sys
import warnings

CLAUSE = "EDGE-6"
try:
    import clifford
    from clifford.tools.g3 import quaternion_to_matrix
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's 0/0 RuntimeWarning; it changes no value

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12 (clifford.Cl(3): e31 = -e13). I = e123 and I e1 = e23,
# I e2 = e31, I e3 = e12, so exp(-(theta/2) I u/|u|) is the quaternion (sin(theta/2) u/|u|, cos(theta/2)).
# clifford.tools.g3 orders quaternions [w, x, y, z] and returns row-major nested arrays.
layout, blades = clifford.Cl(3)
e1, e2, e3, e12, e123 = blades["e1"], blades["e2"], blades["e3"], blades["e12"], blades["e123"]


def returns_within(fn, seconds):  # runs fn in a forked child; False if it is still running after `seconds`
    child = multiprocessing.get_context("fork").Process(target=fn)
    child.start()
    child.join(seconds)
    if child.is_alive():
        child.kill()
        child.join()
        return False
    return True


print("rotorcert reproducer: clifford %s %s: the rotor of a zero axis, exp(-theta/2 I u.normal()), never "
      "returns; quaternion_to_matrix(0) returns the identity" % (clifford.__version__, CLAUSE))
theta, axis = float.fromhex("0x1.921fb54442d18p+0"), [0.0, 0.0, 0.0]
(0.5 * e12).exp()  # compile the numba code here, so that the child below only runs it
u = axis[0] * e1 + axis[1] * e2 + axis[2] * e3
ok = returns_within(lambda: (-(theta / 2) * (e123 * u.normal())).exp(), 3.0)
shown = not ok
print("  call:    u = x*e1 + y*e2 + z*e3; (-(theta / 2) * (e123 * u.normal())).exp()   (takes < 1 ms for u != 0)")
print("  input:   theta = %s, axis u = [%s]" % (theta.hex(), ", ".join(c.hex() for c in axis)))
print("  library: %s" % ("returned" if ok else "did not return within 3 s (stopped)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]")

q = [0.0, 0.0, 0.0, 0.0]  # (x, y, z, w)
m = quaternion_to_matrix([q[3], q[0], q[1], q[2]])
rows = [[float(m[r][c]) for c in range(3)] for r in range(3)]
refused = all(math.isnan(c) for row in rows for c in row)
shown = shown or not refused
print("  call:    clifford.tools.g3.quaternion_to_matrix([w, x, y, z])")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: rows %s%s" % (rows, "" if refused else "  (the identity, no error)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or nine NaN entries (a zero quaternion is no rotation)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) clifford.tools.log_rotor of the identity rotor 1, clause EDGE-1.

EDGE-1 (spec/SPEC.md 9): identity in gives identity out exactly; log(1) = 0 (also LOG-1: "log(1) = 0
exactly"). tools.log_rotor ("Logarithm of a simple rotor") takes
the branch `if abs(V(2)) < eps: return log(float(V(0)))` for every rotor with |<R>2| < 1e-12, but
clifford/tools/__init__.py never imports or defines `log` (line 470 of the installed 1.5.1), so the
call raises NameError: name 'log' is not defined. Same line as LOG-2 (log of -1).
Upstream: no matching issue found in pygae/clifford (the line is unchanged on its master).
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import contextlib
import io
import sys

CLAUSE = "EDGE-1"
try:
    import clifford
    import clifford.tools
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12; clifford.Cl(3) names e12, e13, e23 and e31 = -e13, so
# R = w - x*e23 + y*e13 - z*e12. A quaternion-view log v = (x, y, z) is the bivector
# -(x e23 + y e31 + z e12) = -x*e23 + y*e13 - z*e12, so back: x = -L[e23], y = +L[e13], z = -L[e12].
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]

q = [0.0, 0.0, 0.0, 1.0]  # (x, y, z, w): the identity rotor 1

print("rotorcert reproducer: clifford %s %s: clifford.tools.log_rotor(1) raises NameError "
      "('log' is not imported) instead of returning exactly 0" % (clifford.__version__, CLAUSE))
R = q[3] - q[0] * e23 + q[1] * e13 - q[2] * e12
printed = io.StringIO()
try:
    with contextlib.redirect_stdout(printed):  # log_rotor also print()s its argument here
        L = clifford.tools.log_rotor(R)
    got = [-float(L[(2, 3)]), float(L[(1, 3)]), -float(L[(1, 2)])]
    bad = got != [0.0, 0.0, 0.0]  # class exact: -0 equals +0
    result = "[%s]" % ", ".join(c.hex() for c in got)
except Exception as exc:  # noqa: BLE001 - the defect is the exception itself
    bad, result = True, "raised %s: %s" % (type(exc).__name__, exc)
print("  call:    clifford.tools.log_rotor(R), R = w - x*e23 + y*e13 - z*e12")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: %s%s" % (result, "   (it also printed %r)" % printed.getvalue().strip() if printed.getvalue() else ""))
print("  correct: [0x0p+0, 0x0p+0, 0x0p+0]  exactly (class exact)%s" % ("  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)

#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) zero axis, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero axis (AXANG-2; also with angle 0) is DOMAIN_ERROR (an error, or every
output component NaN); since spec 2.2.0 ACC-1 zero_sentinel also accepts the identity rotor or the
all-zero rotor. clifford has no axis-angle constructor; its documented rotor idiom is
R = e^(-theta/2 B^) with the unit plane B^ = I u/|u| (tutorial g3-algebra-of-space, "Rotation").
For u = 0, u.normal() is 0/0 = NaN and MultiVector.exp() of a NaN bivector NEVER RETURNS (its
Taylor-series scaling loop, clifford/taylor_expansions.py exp; see EDGE-7): no answer at all, neither
an error nor a sentinel. (quaternion_to_matrix(0) = the identity, the zero rotor's product and
sandwich = 0 are ACC-1 zero_sentinel answers since 2.2.0 and no longer a defect.)
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
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's 0/0 RuntimeWarning; it changes no value

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12 (clifford.Cl(3): e31 = -e13). I = e123 and I e1 = e23,
# I e2 = e31, I e3 = e12, so exp(-(theta/2) I u/|u|) is the quaternion (sin(theta/2) u/|u|, cos(theta/2)).
layout, blades = clifford.Cl(3)
e1, e2, e3, e12, e123 = blades["e1"], blades["e2"], blades["e3"], blades["e12"], blades["e123"]


def quat(R):  # (x, y, z, w) of the rotor R = w - x e23 - y e31 - z e12 (clifford names e13 = -e31)
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


def call_within(fn, seconds):  # runs fn in a forked child: its result, or None if still running after `seconds`
    recv, send = multiprocessing.get_context("fork").Pipe(duplex=False)
    child = multiprocessing.get_context("fork").Process(target=lambda: send.send(fn()))
    child.start()
    child.join(seconds)
    if child.is_alive():
        child.kill()
        child.join()
        return None
    return recv.recv() if recv.poll() else "raised an exception"


print("rotorcert reproducer: clifford %s %s: the rotor of a zero axis, exp(-theta/2 I u.normal()), never "
      "returns" % (clifford.__version__, CLAUSE))
theta, axis = float.fromhex("0x1.921fb54442d18p+0"), [0.0, 0.0, 0.0]
(0.5 * e12).exp()  # compile the numba code here, so that the child below only runs it
u = axis[0] * e1 + axis[1] * e2 + axis[2] * e3
got = call_within(lambda: quat((-(theta / 2) * (e123 * u.normal())).exp()), 3.0)
if got is None:
    shown, shown_as = True, "did not return within 3 s (stopped)  <-- DEFECT"
elif isinstance(got, str):
    shown, shown_as = False, got + " (DOMAIN_ERROR)"
else:  # an answer: DOMAIN_ERROR if every component is non-finite, ACC-1 zero_sentinel if all 0 or the identity
    accepted = (all(not math.isfinite(c) for c in got) or all(c == 0 for c in got) or got == [0.0, 0.0, 0.0, 1.0])
    shown, shown_as = not accepted, "[%s] (x, y, z, w)%s" % (", ".join(c.hex() for c in got),
                                                             "" if accepted else "  <-- DEFECT")
print("  call:    u = x*e1 + y*e2 + z*e3; (-(theta / 2) * (e123 * u.normal())).exp()   (takes < 1 ms for u != 0)")
print("  input:   theta = %s, axis u = [%s]" % (theta.hex(), ", ".join(c.hex() for c in axis)))
print("  library: %s" % shown_as)
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]; acceptable (ACC-1 zero_sentinel): the "
      "identity [0, 0, 0, 1] or [0, 0, 0, 0]")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

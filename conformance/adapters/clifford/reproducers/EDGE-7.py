#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.exp() of a non-finite bivector never returns, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR (an error, or all output
components NaN); since spec 2.7.0 ACC-1 nonfinite_propagation also accepts an answer with at least one
output component NaN or +-Inf. What is never acceptable is no answer at all. MultiVector.exp() is
clifford.taylor_expansions.exp (numba), whose scaling loop (taylor_expansions.py:57-63) starts from
max_val = int(max|coefficient|) in a 64-bit int: for a NaN or Inf coefficient the conversion gives a
negative number and `while max_val: max_val >>= 1` never reaches 0, so exp() NEVER RETURNS. The rotor of
an axis and an angle (clifford's e**(-B theta/2) with B = I u/|u|) hangs for a NaN or Inf angle or axis
component, and so does exp of a NaN or Inf bivector. exp() documents no precondition. (normal(), products
and the matrix conversions carry NaN/Inf into their results, which ACC-1 accepts since 2.7.0.)
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
# back x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar]. I = e123 and I e1 = e23, I e2 = e31,
# I e3 = e12, so exp(-(theta/2) I u/|u|) is the quaternion (sin(theta/2) u/|u|, cos(theta/2)).
# A quaternion-view log v = (x, y, z) is the bivector -(x e23 + y e31 + z e12) = -x*e23 + y*e13 - z*e12,
# set blade by blade: inf * e23 would put 0 * inf = NaN into every other coefficient.
layout, blades = clifford.Cl(3)
e1, e2, e3, e12, e123 = blades["e1"], blades["e2"], blades["e3"], blades["e12"], blades["e123"]


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


def bivector(v):
    B = layout.MultiVector()
    B[(2, 3)], B[(1, 3)], B[(1, 2)] = -v[0], v[1], -v[2]
    return B


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


def judge(got, inputs):  # (defect?, how the library's answer reads) for a call on `inputs`
    if got is None:
        return True, "did not return within 3 s (stopped)  <-- DEFECT"
    if isinstance(got, str):
        return False, got + " (DOMAIN_ERROR)"
    # For a non-finite input some output component must be non-finite (DOMAIN_ERROR, or ACC-1
    # nonfinite_propagation); an all-finite answer hides it. A finite input is no EDGE-7 case.
    bad = any(not math.isfinite(c) for c in inputs) and all(math.isfinite(c) for c in got)
    return bad, "[%s] (x, y, z, w)%s" % (", ".join(c.hex() for c in got), "  <-- DEFECT" if bad else "")


print("rotorcert reproducer: clifford %s %s: MultiVector.exp() of a NaN or Inf bivector never returns (the rotor "
      "of a NaN angle, exp of a NaN vector)" % (clifford.__version__, CLAUSE))
(0.5 * e12).exp()  # compile the numba code here, so that the child below only runs it
shown = False

# The suite's worst input: from_axis_angle with a NaN angle ('NaN in angle').
theta = float.fromhex("-nan")
axis = [float.fromhex(s) for s in ("0x1.d74238ec14f41p-1", "-0x1.43e324b720c4fp-2", "-0x1.d676bd383060ep-3")]
u = axis[0] * e1 + axis[1] * e2 + axis[2] * e3
bad, shown_as = judge(call_within(lambda: quat((-(theta / 2) * (e123 * u.normal())).exp()), 3.0), [theta] + axis)
shown = shown or bad
print("  call:    u = x*e1 + y*e2 + z*e3; (-(theta / 2) * (e123 * u.normal())).exp()   (takes < 1 ms for a finite theta)")
print("  input:   theta = %s, axis u = [%s]" % ("-nan" if math.isnan(theta) else theta.hex(), ", ".join(c.hex() for c in axis)))
print("  library: %s" % shown_as)
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]; acceptable (ACC-1 nonfinite_propagation): "
      "any answer with a NaN or Inf component")

# exp of a NaN and of an infinite rotation vector (EX-EDGE-7's exp case and the suite's '+Inf in v').
for v in ([float.fromhex("-nan"), 0.0, 0.0],
          [float.fromhex(s) for s in ("-0x1.67411239df568p-4", "-0x1.2b673e4b02695p-4", "inf")]):
    bad, shown_as = judge(call_within(lambda: quat(bivector(v).exp()), 3.0), v)
    shown = shown or bad
    print("  call:    B[(2, 3)], B[(1, 3)], B[(1, 2)] = -x, y, -z; B.exp()   (takes < 1 ms for a finite B)")
    print("  input:   v (x, y, z) = [%s]" % ", ".join("-nan" if math.isnan(c) else c.hex() for c in v))
    print("  library: %s" % shown_as)
    print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan]; acceptable (ACC-1 nonfinite_propagation): "
          "any answer with a NaN or Inf component")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

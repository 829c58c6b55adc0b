#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) clifford.tools.g3c.rotor_parameterisation.interpolate_rotors, clause EDGE-4.

EDGE-4 (spec/SPEC.md 9): q and -q are the same rotation; results for negated inputs equal those for
the originals up to sign (slerp(a, -b, t) = slerp(a, b, t)), class eps8 (loose bar 128 eps).
interpolate_rotors' general_logarithm goes through R**2 and is sign-blind, so the branch is right, but
the Taylor-series exp (EXP-1) leaves the results for this pair and its negations ~1.4e4 eps off slerp.
interpolate_rotors(R_next, R_n, t) ("Interpolates all conformal type rotors") is clifford's only rotor
interpolation: exp(t general_logarithm(R_next ~R_n)) R_n, with the Taylor-series exp of EXP-1.
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import sys
import warnings

CLAUSE = "EDGE-4"
try:
    import clifford
    from clifford.tools.g3 import quaternion_to_rotor, rotor_to_quaternion
    from clifford.tools.g3c.rotor_parameterisation import interpolate_rotors
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # the DeprecationWarning of general_exp inside interpolate_rotors

# ---- independent reference: 60-digit decimal arithmetic (standard library only) -------------------
from decimal import Decimal as D, getcontext  # noqa: E402
getcontext().prec = 60
TINY = D(10) ** -70
def sincos(x):  # sin, cos of a Decimal by the Taylor series of e^(ix) (|x| < 10 here)
    s = c = D(0); t, n = D(1), 0
    while n < 2 or abs(t) > TINY:
        k = n % 4
        if k == 0: c += t
        elif k == 1: s += t
        elif k == 2: c -= t
        else: s -= t
        n += 1; t = t * x / n
    return s, c
def atan(x):  # halve the angle until |x| < 1/8, then the alternating series
    k = 0
    while abs(x) > D(1) / 8: x, k = x / (1 + (1 + x * x).sqrt()), k + 1
    s, p, n = D(0), x, 0
    while abs(p) > TINY: s, p, n = s + p / (2 * n + 1), -p * x * x, n + 1
    return s * 2 ** k
def atan2(y, x):
    r = (x * x + y * y).sqrt()
    if r == 0: return D(0)
    if x > 0: return 2 * atan(y / (r + x))
    return 4 * atan(D(1)) if y == 0 else 2 * atan((r - x) / y)
def norm(v): return sum(D(c) * D(c) for c in v).sqrt()
def dist(a, b):  # METRIC-1: 4 atan2(min(|a-b|,|a+b|), max(..)) of the normalised quaternions
    na, nb = norm(a), norm(b); a, b = [D(c) / na for c in a], [D(c) / nb for c in b]
    m, p = norm([x - y for x, y in zip(a, b)]), norm([x + y for x, y in zip(a, b)])
    return 4 * atan2(min(m, p), max(m, p))

def slerp_ref(a, b, t):  # SLERP-1 at 60 digits: normalise, b' = -b iff a.b < 0, then the sine formula
    na, nb = norm(a), norm(b); a, b = [D(c) / na for c in a], [D(c) / nb for c in b]
    d = sum(x * y for x, y in zip(a, b))
    if d < 0: b, d = [-c for c in b], -d
    s = norm([y - d * x for x, y in zip(a, b)])  # sin(Omega) = |b' - (a.b') a|
    if s == 0: return a
    om = atan2(s, d)
    return [(sincos((1 - D(t)) * om)[0] * x + sincos(D(t) * om)[0] * y) / s for x, y in zip(a, b)]


# ---- conventions --------------------------------------------------------------------------------
# clifford.tools.g3 works in the conformal layout clifford.g3c with quaternions ordered [w, x, y, z];
# its quaternion_to_rotor([w, x, y, z]) = w - e123 (x e1 + y e2 + z e3) = w - x e23 - y e31 - z e12,
# which is exactly rotorcert's Q2R-1, and rotor_to_quaternion is its inverse. rotorcert's slerp(a, b, t)
# (a at t = 0) is interpolate_rotors(R_b, R_a, t): its second argument is the t = 0 end.
def clifford_slerp(a, b, t):  # a, b as (x, y, z, w)
    Ra = quaternion_to_rotor([a[3], a[0], a[1], a[2]])
    Rb = quaternion_to_rotor([b[3], b[0], b[1], b[2]])
    w, x, y, z = rotor_to_quaternion(interpolate_rotors(Rb, Ra, t))
    return [float(x), float(y), float(z), float(w)]


EPS = 2.0 ** -52
h = float.fromhex
LOOSE = 128  # eps8 loose bar (spec/clauses.json)
a = [h("-0x1.a575c1c92e701p-1"), h("-0x1.3a21f99e5082fp-2"), h("-0x1.14be9e03eaa92p-3"), h("0x1.d54aefbac977bp-2")]  # (x, y, z, w)
b = [h("-0x1.7573d4578930cp-1"), h("-0x1.28378c1e198cap-3"), h("0x1.1d4c7c368e402p-1"), h("-0x1.7a6806881672ep-2")]
t = h("0x1.e3cb11853e43ep-1")

print("rotorcert reproducer: clifford %s %s: interpolate_rotors with a negated input is ~1.4e4 eps off slerp (Taylor-series exp)" % (clifford.__version__, CLAUSE))
got = clifford_slerp(a, b, t)
ref = slerp_ref(a, b, t)
e1_, e6_ = dist(got, ref), abs(norm(got) - 1)  # METRIC-1 (radians) and METRIC-6 (norm defect)
err = max(e1_, e6_)
bad = not (err <= LOOSE * D(EPS))
print("  call:    interpolate_rotors(Rb, Ra, t), Ra/Rb = clifford.tools.g3.quaternion_to_rotor([w, x, y, z])")
print("  input:   a = [%s]" % ", ".join(c.hex() for c in a))
print("           b = [%s]  (x, y, z, w), a.b = %s, t = %s" % (", ".join(c.hex() for c in b), float(sum(D(x) * D(y) for x, y in zip(a, b))), t.hex()))
print("  library: [%s]" % ", ".join(c.hex() for c in got))
print("  correct: [%s]  slerp at 60 digits (SLERP-1: hemisphere rule, sine formula)" % ", ".join(float(c).hex() for c in ref))
print("  error:   METRIC-1 %.3e rad = %.4g eps, METRIC-6 %.3e = %.4g eps (bar %d eps)%s"
      % (e1_, e1_ / D(EPS), e6_, e6_ / D(EPS), LOOSE, "  <-- DEFECT" if bad else ""))
for name, aa, bb in (("(-a, b)", [-c for c in a], b), ("(a, -b)", a, [-c for c in b])):
    g = clifford_slerp(aa, bb, t)
    e = max(dist(g, ref), abs(norm(g) - 1))  # the same rotation as slerp(a, b, t), up to sign
    print("  negated %s: [%s], error %.3e rad = %.4g eps%s" % (name, ", ".join(c.hex() for c in g), e, e / D(EPS),
          "  <-- DEFECT" if not e <= LOOSE * D(EPS) else ""))
    bad = bad or not e <= LOOSE * D(EPS)
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)


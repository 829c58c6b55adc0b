#!/usr/bin/env python3
"""rotorcert test-vector adapter for the Python geometric algebra library `clifford` (pygae).

    rotorcert vectors export --out VECTORS --scalar double
    python3 clifford_adapter.py --vectors VECTORS --out RESULTS.json
    rotorcert vectors check RESULTS.json --verbose

What is certified: clifford's own calls in Cl(3,0) (`clifford.Cl(3)`), binary64 (its default dtype),
and its 3D tools (`clifford.tools`, `clifford.tools.g3`, `clifford.tools.g3c`). The adapter only
converts between the ABI layouts and clifford multivectors; it never normalises, flips hemispheres,
checks domains or rescales on the library's behalf (conformance/CERTIFY.md): what clifford does is graded.

Basis and sign conventions (Q2R-1). clifford.Cl(3) names its bivectors e12, e13, e23 (bitmaps 3, 5,
6, each with sign +1), so the spec's e31 is -e13. A quaternion [x, y, z, w] becomes the rotor

    R = w - x e23 - y e31 - z e12 = w - x e23 + y e13 - z e12,

and back: w = <R>0, x = -R[e23], y = -R[e31] = +R[e13], z = -R[e12]. This is exactly the map of
clifford's own clifford.tools.g3.quaternion_to_rotor ([w, x, y, z] -> -e123 (x e1 + y e2 + z e3) + w)
and rotor_to_quaternion, which the adapter uses where it works in clifford's conformal layout.
A vector [x, y, z] is x e1 + y e2 + z e3; a bivector [b23, b31, b12] is b23 e23 - b31 e13 + b12 e12;
a trivector [a] is a e123. A rotation log [x, y, z] (quaternion view, (angle/2) axis) is the
bivector Phi(v) = -(x e23 + y e31 + z e12), so that exp(Phi(v)) = Phi(exp v).

Op mapping (every call is clifford's; A, B, R rotors as above):
  normalize        R.normal()                              (= R / abs(R), abs = sqrt(|<~R R>0|))
  compose          A * B                                   (geometric product; b applied first)
  inverse          R.inv()                                 (raises ValueError if <~R R>0 <= 1e-12)
  apply_vector     R * x * ~R                              (the sandwich of clifford's docs, ~ = reverse)
  apply_bivector   R * B * ~R
  apply_trivector  R * (a e123) * ~R
  to_matrix        clifford.tools.g3.quaternion_to_matrix([w, x, y, z])   (row-major -> column-major)
  from_matrix      clifford.tools.g3.rotation_matrix_to_quaternion(M)     (M row-major; -> [x, y, z, w])
  from_axis_angle  (-(angle/2) * (e123 * u.normal())).exp()      i.e. e**(-B angle/2), B = I u/|u|
  log              clifford.tools.log_rotor(R)             (bivector -> [x, y, z] by the inverse of Phi)
  exp              Phi(v).exp()                            (MultiVector.exp = taylor_expansions.exp)
  slerp            clifford.tools.g3c.rotor_parameterisation.interpolate_rotors(Rb, Ra, t), with
                   Ra, Rb = clifford.tools.g3.quaternion_to_rotor(...) in clifford's conformal layout
                   (the library's only rotor interpolation: exp(t log(Rb ~Ra)) Ra)
  sqrt             clifford.tools.g3c.square_roots_of_rotor(R)[0], with R = clifford.tools.g3.
                   quaternion_to_rotor(...) in clifford's conformal layout (as slerp), read back
                   with rotor_to_quaternion (Dorst and Valkenburg's polar decomposition of
                   1 + R; [0] is the root clifford's own n_th_rotor_root takes)
  log_exp_round_trip   exp of what log returned (rotorcert_vectors.round_trip)
Unsupported (no clifford function, and no one-line idiom of its calls): to_axis_angle, to_angle,
to_axis, nlerp, blend_qlb, blend_log (a hemisphere rule or a zero-angle default axis would be adapter
code), and every rigid/skinning op (clifford.pga is a bare Cl(3,0,1) layout without translators,
motor log/exp, decomposition or blending). adapter.json lists each with its reason.

Status (RESULT-2, the rule of the rotorcert_vectors package, conformance/packages/python): a
clifford exception -> DOMAIN_ERROR with NaN outputs; all outputs NaN -> DOMAIN_ERROR; anything else
-> OK with the outputs as computed. Reading the vectors, calling the ops and writing the results
file are the package's (scripts/setup-adapters installs it into the adapter's environment).
Two details of how a library failure reaches that rule:
  - An exception whose innermost frame is inside the clifford package is the library's, whatever
    its type: clifford.tools.log_rotor raises NameError ('log' is not imported) for every rotor
    with |<R>2| < 1e-12. It is re-raised as CliffordRaised so that rotorcert_vectors (which treats
    a bare NameError as an adapter defect) grades it as a refusal like any other library exception.
    A NameError (or AttributeError, ImportError, KeyError) raised in this file is an adapter defect:
    rotorcert_vectors.AdapterError, which stops the run.
  - clifford's Taylor exp (taylor_expansions.exp, numba) never returns for a multivector with a
    non-finite or >= 2^63 coefficient (int() of it overflows, and the scaling loop shifts a negative
    number forever). Calls that can reach it (exp, from_axis_angle, slerp, the round trip) run in a
    forked child with a CPU-time limit (HANG_CPU_S); a child killed by it raises
    rotorcert_vectors.DidNotReturn, which is reported with raw status byte 255 (a FAIL,
    conformance/VECTORS.md): a call that does not return is neither OK nor a DOMAIN_ERROR.
"""
import os
import pickle
import math
import signal
import sys
import traceback
import warnings

import numba.core.event
import numpy as np
import clifford
import clifford.tools
import clifford.tools.g3  # imports clifford.g3c: its layout is the conformal Cl(4,1)
import clifford.tools.g3c.rotor_parameterisation as rotor_param
from rotorcert_vectors import AdapterError, DidNotReturn, round_trip, run_adapter

# numpy's warnings (0/0, overflow) and clifford's DeprecationWarning of general_exp (called inside
# interpolate_rotors) only print; silencing them changes no value.
np.seterr(all="ignore")
warnings.simplefilter("ignore")

CLIFFORD_DIR = os.path.dirname(os.path.abspath(clifford.__file__))
HANG_CPU_S = 0.5      # CPU seconds a forked call may use; a normal call takes well under 10 ms
COMPILE_CPU_S = 60.0  # the same while numba compiles (see _CompileBudget)

LAYOUT, BLADES = clifford.Cl(3)
I3 = BLADES["e123"]


def _index(name):
    """Position of a basis blade in clifford's value array (its canonical order: '', e1, e2, e3,
    e12, e13, e23, e123), read from the layout rather than assumed."""
    nz = np.nonzero(BLADES[name].value)[0] if name else [0]
    return int(nz[0])


S, E1, E2, E3, E12, E13, E23, E123 = (_index(n) for n in ("", "e1", "e2", "e3", "e12", "e13", "e23", "e123"))


# ---- layout conversions (ABI <-> clifford); linear coefficient maps, exact in binary64 ----------

def _mv(pairs):
    value = np.zeros(LAYOUT.gaDims)
    for i, c in pairs:
        value[i] = c
    return LAYOUT.MultiVector(value)


def bivector(b23, b31, b12):
    """b23 e23 + b31 e31 + b12 e12 with e31 = -e13."""
    return _mv([(E23, b23), (E13, -b31), (E12, b12)])


def read_bivector(m):
    return [m.value[E23], -m.value[E13], m.value[E12]]


def rotor(q):
    """Phi(q) = w - x e23 - y e31 - z e12 of q = [x, y, z, w] (Q2R-1)."""
    x, y, z, w = q
    return _mv([(S, w), (E23, -x), (E13, y), (E12, -z)])


def quat(m):
    """Phi^-1: [x, y, z, w] = [-R_e23, -R_e31, -R_e12, <R>0]."""
    b23, b31, b12 = read_bivector(m)
    return [-b23, -b31, -b12, m.value[S]]


def vector(v):
    return _mv([(E1, v[0]), (E2, v[1]), (E3, v[2])])


def log_bivector(v):
    """The bivector Phi(v) of a quaternion-view log [x, y, z]."""
    return bivector(-v[0], -v[1], -v[2])


def wxyz(q):
    """clifford.tools.g3's quaternion [w, x, y, z] of an ABI [x, y, z, w], as the numpy array
    its own rotor_to_quaternion returns (with Python floats, q[i]**2 in quaternion_to_matrix would
    raise OverflowError where numpy gives inf)."""
    return np.array([q[3], q[0], q[1], q[2]])


# ---- library exceptions and non-returning calls -------------------------------------------------

class CliffordRaised(Exception):
    """An exception raised inside the clifford package (any type: clifford's NameError too)."""


def _in_clifford(exc):
    frames = traceback.extract_tb(exc.__traceback__)
    return bool(frames) and os.path.abspath(frames[-1].filename).startswith(CLIFFORD_DIR + os.sep)


def library(fn):
    """Marks exceptions raised inside clifford as the library's (see the module docstring)."""
    def call(*args):
        try:
            return fn(*args)
        except (NameError, AttributeError, ImportError, KeyError) as e:
            if _in_clifford(e):
                raise CliffordRaised("clifford raised %s: %s" % (type(e).__name__, e)) from e
            raise
    call.__name__ = fn.__name__
    return call


class _CompileBudget(numba.core.event.Listener):
    """In a forked child: numba compiling a branch the parent never ran is not a hang, so while a
    compilation runs the CPU limit is COMPILE_CPU_S, and HANG_CPU_S again once it ends."""
    def __init__(self):
        self.depth, self.compiled = 0, False

    def on_start(self, event):
        self.depth += 1
        self.compiled = True
        signal.setitimer(signal.ITIMER_PROF, COMPILE_CPU_S)

    def on_end(self, event):
        self.depth -= 1
        if self.depth == 0:
            signal.setitimer(signal.ITIMER_PROF, HANG_CPU_S)


ORDINARY_BOUND = 2.0 ** 30  # far from the 2^62 where clifford's exp stops returning


def _ordinary(args):
    """Whether every argument is ordinary: scalars finite and below ORDINARY_BOUND, each vector or
    quaternion finite with its norm within [1/ORDINARY_BOUND, ORDINARY_BOUND] (a zero, subnormal or
    huge one turns into NaN or infinity inside clifford, where its exp never returns)."""
    for a in args:
        if isinstance(a, (int, float)):
            if not math.isfinite(a) or abs(a) >= ORDINARY_BOUND:
                return False
        elif isinstance(a, (list, tuple)) and all(isinstance(x, (int, float)) for x in a):
            if not all(math.isfinite(x) for x in a):
                return False
            n = math.sqrt(sum(x * x for x in a))
            if not (1.0 / ORDINARY_BOUND <= n <= ORDINARY_BOUND):
                return False
        else:
            return False  # anything else (a multivector, an array): keep the isolation
    return True


def isolated(fn):
    """Runs fn in a forked child limited to HANG_CPU_S of CPU time outside numba compilation
    (SIGPROF's default action ends it even inside numba code); returns or raises what the child
    did. A child that compiled numba code and returned is run again here, so that the parent holds
    the compiled code and later children do not compile it again."""
    def call(*args):
        if _ordinary(args):
            # Every call clifford never returns from has a NaN, an infinity or a coefficient of
            # 2^62 or more (its Taylor exp doubles a bound until it exceeds the input). Ordinary
            # inputs run here: a fork per call made the adapter spend minutes in fork() alone.
            try:
                return [float(c) for c in fn(*args)]
            except CliffordRaised:
                raise
            except (NameError, AttributeError, ImportError, KeyError) as e:
                raise AdapterError("adapter defect in %s: %s: %s" % (fn.__name__, type(e).__name__, e)) from e
            except Exception as e:  # noqa: B902 - the library raised: its outcome (DOMAIN_ERROR rule)
                raise CliffordRaised("%s: %s" % (type(e).__name__, e)) from e
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:  # child
            os.close(r)
            budget = _CompileBudget()
            numba.core.event.register("numba:compile", budget)
            signal.setitimer(signal.ITIMER_PROF, HANG_CPU_S)
            try:
                msg = ("ok", [float(c) for c in fn(*args)])
            except BaseException as e:  # noqa: B902 - every outcome goes back to the parent
                msg = ("raise", type(e).__name__, str(e), isinstance(e, CliffordRaised) or
                       not isinstance(e, (NameError, AttributeError, ImportError, KeyError)))
            signal.setitimer(signal.ITIMER_PROF, 0)
            with os.fdopen(w, "wb") as f:
                f.write(pickle.dumps((budget.compiled, msg)))
            os._exit(0)
        os.close(w)
        chunks = []
        while True:
            chunk = os.read(r, 65536)
            if not chunk:
                break
            chunks.append(chunk)
        os.close(r)
        _, st = os.waitpid(pid, 0)
        if os.WIFSIGNALED(st):
            HUNG.append(fn.__name__)
            raise DidNotReturn("%s did not return within %.1f s CPU (signal %d)"
                               % (fn.__name__, HANG_CPU_S, os.WTERMSIG(st)))
        compiled, msg = pickle.loads(b"".join(chunks))
        if compiled:  # it returned in the child, so it returns here
            try:
                fn(*args)
            except Exception:
                pass
        if msg[0] == "ok":
            return msg[1]
        _, name, text, is_library = msg
        if is_library:
            raise CliffordRaised("%s: %s" % (name, text))
        raise AdapterError("adapter defect in %s: %s: %s" % (fn.__name__, name, text))
    call.__name__ = fn.__name__
    call.inner = fn  # for warm_up, which must run it in this process
    return call


HUNG = []  # the calls isolated() had to stop


# ---- the ops ---------------------------------------------------------------------------------------

@library
def normalize(q):
    return quat(rotor(q).normal())


@library
def compose(a, b):
    return quat(rotor(a) * rotor(b))


@library
def inverse(q):
    return quat(rotor(q).inv())


@library
def apply_vector(q, v):
    R = rotor(q)
    m = R * vector(v) * ~R
    return [m.value[E1], m.value[E2], m.value[E3]]


@library
def apply_bivector(q, b):
    R = rotor(q)
    return read_bivector(R * bivector(*b) * ~R)


@library
def apply_trivector(q, s):
    R = rotor(q)
    return (R * (s * I3) * ~R).value[E123]


@library
def to_matrix(q):
    m = clifford.tools.g3.quaternion_to_matrix(wxyz(q))  # rows
    return [m[r][c] for c in range(3) for r in range(3)]


@library
def from_matrix(m):
    a = np.array([[m[c * 3 + r] for c in range(3)] for r in range(3)])  # column-major -> rows
    w, x, y, z = clifford.tools.g3.rotation_matrix_to_quaternion(a)
    return [x, y, z, w]


@isolated
@library
def from_axis_angle(angle, axis):
    return quat((-(angle / 2) * (I3 * vector(axis).normal())).exp())


@library
def log(q):
    b23, b31, b12 = read_bivector(clifford.tools.log_rotor(rotor(q)))
    return [-b23, -b31, -b12]


@isolated
@library
def exp(v):
    return quat(log_bivector(v).exp())


@isolated
@library
def slerp(a, b, t):
    g3 = clifford.tools.g3
    Ra, Rb = g3.quaternion_to_rotor(wxyz(a)), g3.quaternion_to_rotor(wxyz(b))
    w, x, y, z = g3.rotor_to_quaternion(rotor_param.interpolate_rotors(Rb, Ra, t))
    return [x, y, z, w]


@isolated
@library
def sqrt(q):
    g3 = clifford.tools.g3
    root = clifford.tools.g3c.square_roots_of_rotor(g3.quaternion_to_rotor(wxyz(q)))[0]
    w, x, y, z = g3.rotor_to_quaternion(root)
    return [x, y, z, w]


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse,
    "apply_vector": apply_vector, "apply_bivector": apply_bivector, "apply_trivector": apply_trivector,
    "to_matrix": to_matrix, "from_matrix": from_matrix, "from_axis_angle": from_axis_angle,
    "log": log, "exp": exp, "slerp": slerp,
    "log_exp_round_trip": round_trip(log, exp),
    "sqrt": sqrt,
}


def warm_up():
    """Compiles clifford's numba code for both layouts in this process, before any fork: a child
    that had to compile would spend its CPU limit on numba, not on the call."""
    q, r = [0.1, 0.2, 0.3, 0.9], [0.3, -0.1, 0.2, 0.8]
    for fn, args in ((normalize, (q,)), (compose, (q, r)), (inverse, (q,)), (apply_vector, (q, [1, 2, 3])),
                     (apply_bivector, (q, [1, 2, 3])), (apply_trivector, (q, 2.0)), (to_matrix, (q,)),
                     (log, (q,)), (from_axis_angle.inner, (0.5, [1.0, 2.0, 3.0])),
                     (exp.inner, ([0.1, 0.2, 0.3],)), (slerp.inner, (q, r, 0.25)), (sqrt.inner, (q,))):
        fn(*args)


IMPLEMENTATION = {
    "name": "clifford",
    "version": clifford.__version__,
    "scalar": "double",
    "description": (
        "clifford %s (pygae, Python) in Cl(3,0), binary64: geometric product, reverse sandwich, "
        "normal(), inv(), tools.log_rotor, MultiVector.exp, tools.g3 matrix conversions, "
        "tools.g3c interpolate_rotors and square_roots_of_rotor; R = w - x e23 - y e31 - z e12 with e31 = -e13. Status rule "
        "(rotorcert_vectors): a clifford exception -> DOMAIN_ERROR with NaN outputs, all outputs NaN -> "
        "DOMAIN_ERROR, else OK as computed; a call that never returns (Taylor exp of a non-finite or "
        "huge bivector) -> raw status 255 (FAIL)." % clifford.__version__),
}


def main():
    warm_up()
    rc = run_adapter("rotorcert adapter for clifford " + clifford.__version__, IMPLEMENTATION, OPS)
    if HUNG:
        print("clifford: %d calls did not return (status 255): %s" % (len(HUNG), "; ".join(HUNG)))
    return rc


if __name__ == "__main__":
    sys.exit(main())

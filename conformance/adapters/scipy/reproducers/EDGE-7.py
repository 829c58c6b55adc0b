#!/usr/bin/env python3
"""rotorcert reproducer: scipy Rotation.from_matrix with an infinite entry, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR (an error, or every output
NaN), "even if the result would be mathematically defined". Since spec 2.7.0 (ACC-1
nonfinite_propagation) an answer with at least one NaN or infinite component is ACCEPTABLE (from_quat's
[0, nan, 0, 0] for [0, inf, 0, 1] is), as IEEE arithmetic carries it when a library checks nothing; an
all-finite answer to a non-finite input, a hang or a wrong status stays a FAIL.
Rotation.from_matrix checks no entry for finiteness: a matrix with an infinite entry passes its
determinant check (det = +inf passes `dets <= 0`, _rotation_cy.pyx:486-492, compiled into
scipy/spatial/transform/_rotation_cy.cpython-311-x86_64-linux-gnu.so), fails the orthogonality test and
goes to numpy.linalg.svd (:506), whose polar factor U @ Vt replaces it:
  - for the certificate's "+Inf in m" matrix svd returns NaN singular values but finite permutation
    matrices U and Vt (as numpy/numpy#3260 showed in 2013) whose product is the identity, and from_matrix
    returns the identity rotation [0, 0, 0, 1], all finite, with no error: the infinity is gone;
  - for "-Inf in m" svd never returns: LAPACK's dgesdd rescales the Inf into a NaN and dbdsqr then loops
    forever (numpy/numpy#32591, Reference-LAPACK/lapack#1409).
numpy PR #32593 (2.5.x backport #32719) makes svd raise LinAlgError for non-finite input, which would
turn both into a refusal; numpy 2.5 does not install on Python 3.11.
Upstream: no matching issue found in scipy/scipy for the missing finiteness check; the svd behaviour is
numpy/numpy#32591 and #3260.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import os
import pickle
import signal
import sys

CLAUSE = "EDGE-7"
try:
    from importlib.metadata import version
    import numpy as np
    from scipy.spatial.transform import Rotation
    VERSION = version("scipy")
    np.seterr(all="ignore")  # numpy's invalid-value warnings; the numbers are the same
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

LIMIT_S = 5  # seconds of CPU the from_matrix call may take in a child (it takes under a millisecond)
h = float.fromhex


def in_child(fn):
    """fn() in a forked child limited to LIMIT_S s of CPU: ('ok', list) / ('raise', text) / ('hung', s)."""
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(r)
        signal.setitimer(signal.ITIMER_PROF, LIMIT_S)  # SIGPROF's default action ends the child
        try:
            msg = ("ok", [float(c) for c in fn()])
        except Exception as exc:  # noqa: BLE001
            msg = ("raise", "%s: %s" % (type(exc).__name__, exc))
        with os.fdopen(w, "wb") as f:
            f.write(pickle.dumps(msg))
        os._exit(0)
    os.close(w)
    data = b""
    while True:
        chunk = os.read(r, 65536)
        if not chunk:
            break
        data += chunk
    os.close(r)
    _, status = os.waitpid(pid, 0)
    if os.WIFSIGNALED(status):
        return ("hung", "did not return within %d s of CPU (stopped by signal %d)" % (LIMIT_S, os.WTERMSIG(status)))
    return pickle.loads(data)


def column_major(m):
    """The certificate's matrices are column-major m[c*3 + r]; scipy takes rows M[r][c]."""
    return np.array(m).reshape(3, 3).T


cases = [
    ("Rotation.from_matrix(M).as_quat()", "m (column-major), '+Inf in m'",
     [h("-0x1.6d3e312fc4669p-1"), h("0x1.610b3b2c837ccp-2"), h("-0x1.38616b22654e5p-1"), h("-0x1.c816a296cd785p-2"),
      h("-0x1.ca58bc7b781d7p-1"), h("0x1.e84983a9ef1c7p-7"), h("-0x1.1503e5c8b4bb5p-1"), h("0x1.2127308e72ee5p-2"), h("inf")],
     lambda v: Rotation.from_matrix(column_major(v)).as_quat()),
    ("Rotation.from_matrix(M).as_quat()", "m (column-major), '-Inf in m'",
     [h("-0x1.cb1f62d564c5bp-5"), h("0x1.9a8b1632d62f9p-2"), h("-inf"), h("-0x1.36c0fb47cf9cp-1"),
      h("-0x1.7b533e930696ap-1"), h("-0x1.268a43cf1fffdp-2"), h("-0x1.95e5b763f9c57p-1"), h("0x1.13e6018d26d41p-1"),
      h("0x1.23b1c04162e56p-2")],
     lambda v: Rotation.from_matrix(column_major(v)).as_quat()),
]

print("rotorcert reproducer: scipy %s %s: from_matrix of a matrix with an infinite entry returns the "
      "identity, or never returns" % (VERSION, CLAUSE))
shown = False
for call, name, v, fn in cases:
    kind, value = in_child(lambda: fn(v))
    if kind == "ok":
        # the defect: a non-finite input answered with an all-finite, nonzero output (the Inf is gone)
        bad = (not all(math.isfinite(c) for c in v) and all(math.isfinite(c) for c in value)
               and not all(c == 0 for c in value))
        result = "[%s]%s" % (", ".join(c.hex() if math.isfinite(c) else repr(c) for c in value),
                             "  (all finite, status OK: no error)  <-- DEFECT" if bad else "")
    elif kind == "raise":
        bad, result = False, "raised " + value
    else:
        bad, result = True, value + "  <-- DEFECT"
    shown = shown or bad
    print("  call:    %s" % call)
    print("  input:   %s = [%s]" % (name, ", ".join(c.hex() if math.isfinite(c) else repr(c) for c in v)))
    print("  library: %s" % result)
print("  correct: DOMAIN_ERROR for each, promptly: an exception or all NaN (RESULT-2); acceptable (ACC-1 "
      "nonfinite_propagation): some component NaN or infinite")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

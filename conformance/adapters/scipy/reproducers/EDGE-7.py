#!/usr/bin/env python3
"""rotorcert reproducer: scipy Rotation.from_quat / from_matrix with infinite components, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR (an error, or every output
NaN), "even if the result would be mathematically defined". scipy.spatial.transform checks no input for
finiteness:
  - Rotation.from_quat([0, inf, 0, 1]) divides by the norm inf (_rotation_cy.pyx:58-70 `_normalize4`) and
    returns the rotation [0, nan, 0, 0], partly finite, with no error (as_quat, apply, Slerp carry it on);
  - Rotation.from_matrix lets a matrix with an infinite entry through its determinant check (det = +inf
    passes `dets <= 0`, _rotation_cy.pyx:486-492) and hands it to numpy.linalg.svd (:506), which for
    [[-0x1.cb1f62d564c5bp-5, ..., -inf, ...]] (the certificate's "-Inf in m") never returns: LAPACK's
    dgesdd rescales the Inf into a NaN and dbdsqr then loops forever (numpy/numpy#32591,
    Reference-LAPACK/lapack#1409; numpy PR #32719 makes svd raise LinAlgError for non-finite input in
    numpy 2.5, which does not install on Python 3.11), and for the "+Inf in m" matrix returns the
    identity rotation [0, 0, 0, 1] with no error.
Upstream: no matching issue found in scipy/scipy for the missing finiteness checks; the hang is
numpy/numpy#32591 (Reference-LAPACK/lapack#1409) reached through from_matrix.
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
    ("Rotation.from_quat(q).as_quat()", "q (x, y, z, w)", [0.0, math.inf, 0.0, 1.0],  # EX-EDGE-7-b
     lambda v: Rotation.from_quat(v).as_quat()),
    ("Rotation.from_matrix(M).as_quat()", "m (column-major)",
     [h("-0x1.6d3e312fc4669p-1"), h("0x1.610b3b2c837ccp-2"), h("-0x1.38616b22654e5p-1"), h("-0x1.c816a296cd785p-2"),
      h("-0x1.ca58bc7b781d7p-1"), h("0x1.e84983a9ef1c7p-7"), h("-0x1.1503e5c8b4bb5p-1"), h("0x1.2127308e72ee5p-2"), math.inf],
     lambda v: Rotation.from_matrix(column_major(v)).as_quat()),
    ("Rotation.from_matrix(M).as_quat()", "m (column-major)",
     [h("-0x1.cb1f62d564c5bp-5"), h("0x1.9a8b1632d62f9p-2"), -math.inf, h("-0x1.36c0fb47cf9cp-1"),
      h("-0x1.7b533e930696ap-1"), h("-0x1.268a43cf1fffdp-2"), h("-0x1.95e5b763f9c57p-1"), h("0x1.13e6018d26d41p-1"),
      h("0x1.23b1c04162e56p-2")],
     lambda v: Rotation.from_matrix(column_major(v)).as_quat()),
]

print("rotorcert reproducer: scipy %s %s: no finiteness checks: from_quat with an Inf returns a partly-NaN "
      "rotation, from_matrix with an Inf returns the identity or never returns" % (VERSION, CLAUSE))
shown = False
for call, name, v, fn in cases:
    kind, value = in_child(lambda: fn(v))
    if kind == "ok":
        refused = all(math.isnan(c) for c in value)
        result = "[%s]%s" % (", ".join(c.hex() for c in value), "" if refused else "  (status OK: no error)  <-- DEFECT")
    elif kind == "raise":
        refused, result = True, "raised " + value
    else:
        refused, result = False, value + "  <-- DEFECT"
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  input:   %s = [%s]" % (name, ", ".join(c.hex() for c in v)))
    print("  library: %s" % result)
print("  correct: DOMAIN_ERROR for each: an exception or all NaN, promptly (RESULT-2)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)

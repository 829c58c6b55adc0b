#!/usr/bin/env python3
"""A complete JSON-vectors adapter: the worked example of conformance/CERTIFY.md.

"Your library" here is two functions written with Python floats; replace them with calls into the
library you certify. The rotorcert_vectors package (conformance/packages/python; `pip install` it,
or this script finds it in the checkout) does the rest: reads the vectors exactly (hexfloat), calls
one function per vector, maps exceptions and all-NaN outputs to DOMAIN_ERROR (RESULT-2), declares
every other operation unsupported and writes the results file.

    rotorcert vectors export --out vectors --scalar double
    python3 minimal_adapter.py --vectors vectors --out results.json
    rotorcert vectors check results.json
"""
import math
import os
import sys

try:
    import rotorcert_vectors
except ImportError:  # not installed: the package of this checkout
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "packages", "python", "src"))
    import rotorcert_vectors


def normalize(q):  # NORM-1: q / |q|, scaled first so that |q|^2 cannot overflow or underflow
    if not all(math.isfinite(c) for c in q) or not any(q):
        raise ValueError("not a rotation")  # graded as DOMAIN_ERROR
    e = math.frexp(max(abs(c) for c in q))[1]
    s = [math.ldexp(c, -e) for c in q]
    n = math.sqrt(sum(c * c for c in s))
    return [c / n for c in s]


def compose(a, b):  # COMPOSE-1: the Hamilton product a b of [x, y, z, w] quaternions
    if not all(math.isfinite(c) for c in a + b) or not any(a) or not any(b):
        raise ValueError("not a rotation")
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


if __name__ == "__main__":
    sys.exit(rotorcert_vectors.run_adapter(__doc__.splitlines()[0], rotorcert_vectors.Implementation(
        name="minimal_py", version="1.0", scalar="double",
        description="CERTIFY.md's worked example: normalize and compose in Python",
        ops={"normalize": normalize, "compose": compose})))

#!/usr/bin/env python3
"""A minimal rotorcert test-vector adapter in pure Python (stdlib only, binary64 = Python float).

It implements four operations of the spec -- normalize (NORM-1), compose (COMPOSE-1), inverse
(INV-1) and apply_vector (APPLY-1) -- runs every binary64 vector of those operations from an
export of `rotorcert vectors export`, and writes a results file for `rotorcert vectors check`:

    rotorcert vectors export --out vectors --scalar double
    python3 vectors_example_adapter.py --vectors vectors --out results.json
    rotorcert vectors check results.json

Layouts (impl_abi.h): quaternion [x, y, z, w], vector [x, y, z]. Values are read from the "hex"
strings with float.fromhex and written back with float.hex, so nothing is lost on either side.
Inputs outside an operation's domain (a zero, NaN or infinite quaternion, a non-finite vector)
give DOMAIN_ERROR with every output NaN (RESULT-2, EDGE-6, EDGE-7).

--bug composes in the wrong order (b a instead of a b), a plausible defect: COMPOSE-1 must FAIL.
"""
import argparse
import json
import math
import os
import sys

NAN = float("nan")
OPS = ("normalize", "compose", "inverse", "apply_vector")


def finite(xs):
    return all(math.isfinite(x) for x in xs)


def is_rotation(q):
    """A quaternion that describes a rotation: finite and not zero."""
    return finite(q) and any(x != 0.0 for x in q)


def scaled(q):
    """q * 2^-e with 2^e near max|q_i|, and e: |q|^2 can then neither overflow nor underflow."""
    m = max(abs(x) for x in q)
    e = math.frexp(m)[1]
    return [math.ldexp(x, -e) for x in q], e


def normalize(q):
    if not is_rotation(q):
        return None
    s, _ = scaled(q)
    n = math.sqrt(sum(x * x for x in s))
    return [x / n for x in s]


def hamilton(a, b):
    """The Hamilton product a b of [x, y, z, w] quaternions (ijk = -1)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def compose(a, b, bug=False):
    """compose(a, b) = a b: b is applied first (COMPOSE-1), not normalised."""
    if not is_rotation(a) or not is_rotation(b):
        return None
    return hamilton(b, a) if bug else hamilton(a, b)


def inverse(q):
    """q* / |q|^2 (INV-1), scaled so that |q|^2 stays in range: inv(q) = conj(s) / |s|^2 * 2^-e."""
    if not is_rotation(q):
        return None
    s, e = scaled(q)
    n2 = sum(x * x for x in s)
    return [math.ldexp(c / n2, -e) for c in (-s[0], -s[1], -s[2], s[3])]


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def apply_vector(q, v):
    """q v q* with q normalised first (APPLY-1): v + 2w (u x v) + 2 u x (u x v)."""
    if not is_rotation(q) or not finite(v):
        return None
    x, y, z, w = normalize(q)
    u = [x, y, z]
    t = [2.0 * c for c in cross(u, v)]
    ut = cross(u, t)
    return [v[i] + w * t[i] + ut[i] for i in range(3)]


def run(op, inputs, bug):
    """(status, outputs) of one vector; outputs maps each output array to its values."""
    if op == "normalize":
        r, name, n = normalize(inputs["q"]), "out_q", 4
    elif op == "compose":
        r, name, n = compose(inputs["a"], inputs["b"], bug), "out_q", 4
    elif op == "inverse":
        r, name, n = inverse(inputs["q"]), "out_q", 4
    else:
        r, name, n = apply_vector(inputs["q"], inputs["v"]), "out_v", 3
    if r is None:
        return "DOMAIN_ERROR", {name: [NAN] * n}
    return "OK", {name: r}


def text(x):
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x.hex()


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--vectors", required=True, help="directory written by `rotorcert vectors export`")
    p.add_argument("--out", required=True, help="results file to write")
    p.add_argument("--bug", action="store_true", help="compose in the wrong order (b a)")
    p.add_argument("--name", help="the implementation's name in the results (default python_example[_bug])")
    p.add_argument("--version", default="1", help="the implementation's version in the results")
    args = p.parse_args(argv)

    with open(os.path.join(args.vectors, "index.json")) as f:
        index = json.load(f)
    results = []
    for entry in index["files"]:
        if entry["number_format"] != "binary64" or entry["op"] not in OPS:
            continue
        with open(os.path.join(args.vectors, entry["file"])) as f:
            vectors = json.load(f)
        for test in vectors["tests"]:
            inputs = {name: [float.fromhex(h) for h in arr["hex"]] for name, arr in test["in"].items()}
            status, out = run(vectors["op"], inputs, args.bug)
            results.append({"id": test["id"], "status": status,
                            "out": {name: [text(x) for x in values] for name, values in out.items()}})

    out_dir = os.path.dirname(os.path.abspath(args.out))
    doc = {
        "format": "rotorcert-results",
        "format_version": 1,
        "implementation": {
            "name": args.name or "python_example" + ("_bug" if args.bug else ""),
            "version": args.version,
            "scalar": "double",
            "description": "vectors_example_adapter.py: normalize, compose, inverse, apply_vector in pure Python",
        },
        "vectors": os.path.relpath(os.path.abspath(args.vectors), out_dir),
        "unsupported_ops": [],  # an op without any result counts as NOT_SUPPORTED anyway
        "results": results,
    }
    tmp = args.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.replace(tmp, args.out)
    print("wrote %d results to %s" % (len(results), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Reading rotorcert test vectors and writing a results file, for adapters written in Python.

An adapter supplies one function per ABI operation it maps (conformance/VECTORS.md):

    def compose(a, b): ...   # lists of floats in, a list of floats out (or a tuple for two outputs)

and calls `run_adapter(...)`. This module does everything else the same way for every adapter:
values are read from the vectors' "hex" strings (exact) and written back as hexfloat; n-way ops
get their k influences as lists of elements; the outcome of each call is mapped onto the spec's
status channel (RESULT-2) by one rule, stated here and in each certificate's description:

  - the library raised an exception         -> DOMAIN_ERROR, every output NaN
  - every output component is NaN            -> DOMAIN_ERROR (RESULT-2: no status channel)
  - anything else                            -> OK with the outputs as computed
  - the call never returned (the adapter ran it under a time limit and raised DidNotReturn)
                                             -> raw status byte 255, which `vectors check` grades
                                                FAIL: neither OK nor a refusal

The adapter never adds domain checks, rescaling or hemisphere flips of its own: what the library
does with a zero, huge or non-finite input is what gets graded.
"""
import argparse
import json
import math
import os
import sys

NAN = float("nan")
DID_NOT_RETURN = 255  # raw status byte (conformance/VECTORS.md: anything but OK and DOMAIN_ERROR fails)


class DidNotReturn(BaseException):
    """Raised by an adapter that ran a library call under a time limit and had to stop it (a
    BaseException, so that no library-refusal handler takes it for a DOMAIN_ERROR)."""

# Output arrays of each ABI op, in the order the op writes them, and their strides (impl_abi.h).
OUTPUTS = {
    "normalize": [("out_q", 4)], "compose": [("out_q", 4)], "inverse": [("out_q", 4)],
    "apply_vector": [("out_v", 3)], "apply_bivector": [("out_b", 3)], "apply_trivector": [("out_s", 1)],
    "to_matrix": [("out_m", 9)], "from_matrix": [("out_q", 4)],
    "to_axis_angle": [("out_angle", 1), ("out_axis", 3)], "from_axis_angle": [("out_q", 4)],
    "log": [("out_v", 3)], "exp": [("out_q", 4)], "slerp": [("out_q", 4)], "nlerp": [("out_q", 4)],
    "blend_qlb": [("out_q", 4)], "blend_log": [("out_q", 4)],
    "dq_from_rotation_translation": [("out_d", 8)], "dq_compose": [("out_d", 8)],
    "dq_apply_point": [("out_p", 3)], "dq_normalize": [("out_d", 8)], "dq_sclerp": [("out_d", 8)],
    "dq_blend": [("out_d", 8)], "rotate_about_axis": [("out_p", 3)],
    "skin_linear": [("out_v", 3)], "skin_dual_quaternion": [("out_v", 3)],
    "log_exp_round_trip": [("out_q", 4)],
}


def hexfloat(x):
    """A float as the results file wants it: C99 hexfloat, or nan / inf / -inf."""
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return x.hex()


def _decode(arr, stride, per_influence, k):
    """A vector's input array as the adapter function takes it: one element (a list of `stride`
    floats, or a float when stride is 1), or k elements for a per-influence input."""
    values = [float.fromhex(h) if h not in ("nan", "-nan", "inf", "-inf") else float(h.replace("-nan", "nan"))
              for h in arr["hex"]]
    if per_influence:
        return [values[i * stride:(i + 1) * stride] if stride > 1 else values[i] for i in range(k)]
    return values if stride > 1 else values[0]


def _flatten(value):
    if isinstance(value, (list, tuple)):
        return [float(c) for c in value]
    return [float(value)]


def call(op, fn, inputs):
    """(status, {output name: [floats]}, why) of one vector under the adapter's status rule; why
    names the exception when the library refused, or says the call did not return."""
    outs = OUTPUTS[op]
    try:
        result = fn(*inputs)
        if len(outs) == 1:
            result = (result,)
        arrays = {name: _flatten(v) for (name, _), v in zip(outs, result)}
        for name, stride in outs:
            if len(arrays[name]) != stride:
                raise ValueError("%s: %d values, expected %d" % (name, len(arrays[name]), stride))
    except DidNotReturn as e:
        return DID_NOT_RETURN, {name: [NAN] * stride for name, stride in outs}, "did not return: %s" % e
    except (NameError, AttributeError, ImportError, KeyError):
        raise  # a defect of the adapter, not a refusal of the library
    except Exception as e:  # the library refused the input
        return "DOMAIN_ERROR", {name: [NAN] * stride for name, stride in outs}, type(e).__name__
    if all(math.isnan(x) for values in arrays.values() for x in values):
        return "DOMAIN_ERROR", arrays, None
    return "OK", arrays, None


def round_trip(log, exp):
    """EXP-2 (op log_exp_round_trip): exp of what log returned; DOMAIN_ERROR when either refuses."""
    def fn(q):
        v = log(q)
        if all(math.isnan(float(c)) for c in v):
            raise ArithmeticError("log refused the input")
        return exp(list(v))
    return fn


def run_vectors(vectors_dir, ops, number_format="binary64"):
    """Runs every vector of `number_format` whose op is in `ops` (name -> function); returns the
    results list and, per op, a count of calls the library refused by an exception or that did not
    return."""
    with open(os.path.join(vectors_dir, "index.json")) as f:
        index = json.load(f)
    results, refused = [], {}
    for entry in index["files"]:
        if entry["number_format"] != number_format or entry["op"] not in ops:
            continue
        with open(os.path.join(vectors_dir, entry["file"])) as f:
            vf = json.load(f)
        op, fn = vf["op"], ops[vf["op"]]
        layout = [(a["name"], a["stride"], a.get("per_influence", False)) for a in vf["inputs"]]
        for test in vf["tests"]:
            inputs = [_decode(test["in"][name], stride, per, test["k"]) for name, stride, per in layout]
            status, out, why = call(op, fn, inputs)
            if why:
                key = "%s %s" % (op, "did not return" if status == DID_NOT_RETURN else "refused")
                refused[key] = refused.get(key, 0) + 1
            results.append({"id": test["id"], "status": status,
                            "out": {name: [hexfloat(x) for x in values] for name, values in out.items()}})
    return results, refused


def write_results(path, vectors_dir, implementation, results, unsupported):
    """The results file (format rotorcert-results 1), written atomically, one result per line."""
    out_dir = os.path.dirname(os.path.abspath(path))
    head = {
        "format": "rotorcert-results",
        "format_version": 1,
        "implementation": implementation,
        "vectors": os.path.relpath(os.path.abspath(vectors_dir), out_dir),
        "unsupported_ops": sorted(unsupported),
        "results": None,
    }
    text = json.dumps(head, indent=2)
    body = ",\n    ".join(json.dumps(r) for r in results)
    text = text.replace('"results": null', '"results": [\n    ' + body + "\n  ]" if results else '"results": []')
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text + "\n")
    os.replace(tmp, path)


def run_adapter(description, implementation, ops, all_ops=None, argv=None):
    """The command line every Python adapter has: --vectors DIR --out RESULTS.json.
    `implementation` is the results file's implementation object (name, version, scalar,
    description); `ops` maps ABI op names to functions; every other ABI op is declared
    unsupported (NOT_SUPPORTED, RESULT-1)."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--vectors", required=True, help="directory written by `rotorcert vectors export`")
    p.add_argument("--out", required=True, help="results file to write")
    args = p.parse_args(argv)
    fmt = "binary64" if implementation["scalar"] == "double" else "binary32"
    results, refused = run_vectors(args.vectors, ops, fmt)
    unsupported = [op for op in (all_ops or OUTPUTS) if op not in ops and op != "log_exp_round_trip"]
    write_results(args.out, args.vectors, implementation, results, unsupported)
    note = ", ".join("%s %d" % kv for kv in sorted(refused.items()))
    print("%s: wrote %d results to %s%s" % (implementation["name"], len(results), args.out,
                                             " (" + note + ")" if note else ""))
    return 0

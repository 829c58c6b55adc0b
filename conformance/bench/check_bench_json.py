#!/usr/bin/env python3
"""Validates a rotorcert_bench JSON file (Google Benchmark's format) without judging speed.

Checks: the file has a context (Google Benchmark's machine fields and ours) and a non-empty
benchmark list; no benchmark reports an error; every number is finite and positive (flops per
element may be 0: APPLY-3 does no arithmetic); op/* and baseline/* carry every counter of
counters.hpp, a label naming impl, scalar, op, n, k and target that agrees with the name, and
counters that agree with each other (ns per element = 1e9 / elements per second, bytes per
second = bytes per element x elements per second); roofline/* carry their roof; frame/* and
frame_pose/* carry the frame counters, a label naming impl, scalar, technique, scene, part and
target that agrees with the name, and us_per_frame = 1e6 / frames_per_second. With --expect
PREFIX, some benchmark's name must start with PREFIX; with --sizes, every op/baseline size must
be one of them.

Exit status 0 when the file is valid, 1 with one line per problem otherwise.
"""
import argparse
import json
import math
import sys

ELEMENT_COUNTERS = ("items_per_second", "bytes_per_second", "ns_per_element", "flops_per_element",
                    "bytes_per_element", "n", "k", "sets", "working_set_bytes")
ZERO_ALLOWED = {"flops_per_element"}
LABEL_KEYS = ("impl", "scalar", "op", "n", "k", "target")
CONTEXT_KEYS = ("date", "host_name", "num_cpus", "mhz_per_cpu", "caches", "cpu_model", "llc_bytes",
                "rotorcert_seed", "rotorcert_stream_bytes", "rotorcert_sizes", "hwy_target")
FRAME_COUNTERS = ("us_per_frame", "frames_per_second", "joints", "vertices", "influences", "levels",
                  "rotation_channels")
FRAME_LABEL_KEYS = ("impl", "scalar", "technique", "scene", "part", "target")
REL = 1e-6  # the counters derive from the same time and counts: only rounding separates them


def number(problems, where, name, value, allow_zero=False):
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        problems.append(f"{where}: {name} is not a finite number: {value!r}")
        return False
    if value < 0 or (value == 0 and not allow_zero):
        problems.append(f"{where}: {name} must be {'>= 0' if allow_zero else '> 0'}: {value!r}")
        return False
    return True


def close(a, b):
    return abs(a - b) <= REL * max(abs(a), abs(b))


def check_element(problems, b, sizes):
    name = b["name"]
    ok = True
    for c in ELEMENT_COUNTERS:
        if c not in b:
            problems.append(f"{name}: counter {c} missing")
            ok = False
        else:
            ok = number(problems, name, c, b[c], c in ZERO_ALLOWED) and ok
    label = dict(kv.split("=", 1) for kv in b.get("label", "").split() if "=" in kv)
    for key in LABEL_KEYS:
        if not label.get(key):
            problems.append(f"{name}: label lacks {key}= ({b.get('label', '')!r})")
            ok = False
    if not ok:
        return
    parts = name.split("/")  # op/<op>/<impl>/<scalar>/<n> or baseline/glm_<op>/<scalar>/<n>
    if parts[0] == "op" and (len(parts) != 5 or parts[1:4] != [label["op"], label["impl"], label["scalar"]]):
        problems.append(f"{name}: name does not match label {b['label']!r}")
    if parts[0] == "baseline" and (len(parts) != 4 or parts[1:3] != ["glm_" + label["op"], label["scalar"]]):
        problems.append(f"{name}: name does not match label {b['label']!r}")
    if parts[-1] != label["n"] or int(label["n"]) != b["n"]:
        problems.append(f"{name}: n of name, label and counter differ")
    if sizes and b["n"] not in sizes:
        problems.append(f"{name}: size {b['n']} not among {sorted(sizes)}")
    if label["scalar"] not in ("float", "double"):
        problems.append(f"{name}: scalar {label['scalar']!r}")
    if not close(b["ns_per_element"], 1e9 / b["items_per_second"]):
        problems.append(f"{name}: ns_per_element {b['ns_per_element']} != 1e9 / items_per_second")
    if not close(b["bytes_per_second"], b["bytes_per_element"] * b["items_per_second"]):
        problems.append(f"{name}: bytes_per_second != bytes_per_element x items_per_second")


def check_frame(problems, b):
    name = b["name"]
    pose = name.startswith("frame_pose/")
    ok = True
    for c in FRAME_COUNTERS:
        if c not in b:
            problems.append(f"{name}: counter {c} missing")
            ok = False
        else:
            # frame_pose skins no vertex; a scene's clips may animate no rotation
            zero = (c == "vertices" and pose) or c == "rotation_channels"
            ok = number(problems, name, c, b[c], zero) and ok
    label = dict(kv.split("=", 1) for kv in b.get("label", "").split() if "=" in kv)
    for key in FRAME_LABEL_KEYS:
        if not label.get(key):
            problems.append(f"{name}: label lacks {key}= ({b.get('label', '')!r})")
            ok = False
    if not ok:
        return
    parts = name.split("/")  # frame/<scene>/<impl>/<scalar>/<technique>
    if len(parts) != 5 or parts[1:] != [label["scene"], label["impl"], label["scalar"], label["technique"]]:
        problems.append(f"{name}: name does not match label {b['label']!r}")
    if label["part"] != ("pose" if pose else "frame"):
        problems.append(f"{name}: part={label['part']} in the label")
    if label["scalar"] not in ("float", "double") or label["technique"] not in ("LBS", "DQS"):
        problems.append(f"{name}: scalar or technique unknown ({b['label']!r})")
    if pose and b["vertices"] != 0:
        problems.append(f"{name}: frame_pose skins no vertex, vertices = {b['vertices']}")
    if not close(b["us_per_frame"], 1e6 / b["frames_per_second"]):
        problems.append(f"{name}: us_per_frame {b['us_per_frame']} != 1e6 / frames_per_second")


def check(doc, expect, sizes):
    problems = []
    if not isinstance(doc, dict):
        return ["top level is not an object"]
    ctx = doc.get("context")
    if not isinstance(ctx, dict):
        problems.append("no context")
    else:
        for key in CONTEXT_KEYS:
            if key not in ctx or ctx[key] in ("", None, []):
                problems.append(f"context: {key} missing or empty")
    benches = doc.get("benchmarks")
    if not isinstance(benches, list) or not benches:
        problems.append("no benchmarks")
        return problems
    names = []
    for b in benches:
        name = b.get("name", "<unnamed>")
        names.append(name)
        if b.get("error_occurred"):
            problems.append(f"{name}: error: {b.get('error_message', '')}")
            continue
        if b.get("run_type", "iteration") != "iteration":
            continue  # aggregates (--benchmark_repetitions) repeat the same counters
        for field in ("iterations", "real_time", "cpu_time"):
            number(problems, name, field, b.get(field))
        if name.startswith(("op/", "baseline/")):
            check_element(problems, b, sizes)
        elif name.startswith(("frame/", "frame_pose/")):
            check_frame(problems, b)
        elif name.startswith("roofline/peak_fma/"):
            number(problems, name, "flops_per_second", b.get("flops_per_second"))
        elif name.startswith("roofline/bandwidth/"):
            number(problems, name, "bytes_per_second", b.get("bytes_per_second"))
        else:
            problems.append(f"{name}: unknown benchmark family")
    for prefix in expect:
        if not any(n.startswith(prefix) for n in names):
            problems.append(f"no benchmark named {prefix}...")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("json_file")
    ap.add_argument("--expect", action="append", default=[], metavar="PREFIX")
    ap.add_argument("--sizes", default="", help="comma-separated batch sizes allowed")
    args = ap.parse_args()
    sizes = {int(s) for s in args.sizes.split(",") if s}
    try:
        with open(args.json_file, encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        print(f"{args.json_file}: {e}")
        return 1
    problems = check(doc, args.expect, sizes)
    for p in problems:
        print(p)
    n = len(doc.get("benchmarks", [])) if isinstance(doc, dict) else 0
    print(f"{args.json_file}: {n} benchmarks, {'valid' if not problems else f'{len(problems)} problem(s)'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

"""Unit tests of rotorcert_vectors: the status rule, the number texts, the results file, the reader.
Run by ctest (conformance_package_python_pytest) against the installed package:
`python -m pytest conformance/packages/python/tests`."""
import json
import math
import os

import pytest

import rotorcert_vectors as rv

# The results file both packages write for RESULTS_ENTRIES (node: test/rotorcert_vectors.test.js).
GOLDEN = """{
  "format": "rotorcert-results",
  "format_version": 1,
  "implementation": {
    "name": "golden",
    "version": "1",
    "scalar": "double",
    "claimed_clauses": [
      "NORM-1"
    ],
    "preconditions": [
      "slerp:t_in_unit_interval"
    ],
    "hygiene": [
      "HYG-1"
    ]
  },
  "vectors": "vectors",
  "unsupported_ops": [
    "compose",
    "slerp"
  ],
  "results": [
    {"id": "NORM-1/normalize/binary64/0001", "status": "OK", "out": {"out_q": ["0x0.0p+0", "-0x0.0p+0", "0x0.0000000000001p-1022", "0x1.fffffffffffffp+1023"]}},
    {"id": "EDGE-6/normalize/binary64/0001", "status": "DOMAIN_ERROR", "out": {"out_q": ["nan", "nan", "inf", "-inf"]}},
    {"id": "EDGE-7/normalize/binary64/0001", "status": 255, "out": {"out_q": ["nan", "nan", "nan", "nan"]}}
  ]
}
"""
RESULTS_ENTRIES = [
    rv.Outcome("OK", {"out_q": [0.0, -0.0, 5e-324, 1.7976931348623157e308]}).result("NORM-1/normalize/binary64/0001"),
    rv.Outcome("DOMAIN_ERROR", {"out_q": [math.nan, math.nan, math.inf, -math.inf]}).result("EDGE-6/normalize/binary64/0001"),
    rv.Outcome(255, {"out_q": [math.nan] * 4}).result("EDGE-7/normalize/binary64/0001"),
]


def test_hexfloat_and_parse_hex_are_exact():
    for x in (0.0, -0.0, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308, 0.1, -math.pi, 1 + 2 ** -52):
        assert rv.parse_hex(rv.hexfloat(x)) == x
        assert math.copysign(1.0, rv.parse_hex(rv.hexfloat(x))) == math.copysign(1.0, x)
    assert [rv.hexfloat(x) for x in (math.nan, math.inf, -math.inf)] == ["nan", "inf", "-inf"]
    assert math.isnan(rv.parse_hex("-nan")) and rv.parse_hex("-inf") == -math.inf
    assert rv.parse_hex("0x1.8p-999") == 1.5 * 2.0 ** -999  # the exporter's C99 spelling


def identity(q):
    return q


@pytest.mark.parametrize("fn, status, refusal", [
    (lambda q: q, "OK", None),
    (lambda q: [math.nan] * 4, "DOMAIN_ERROR", None),              # RESULT-2: all NaN
    (lambda q: [math.nan, 1.0, math.nan, math.nan], "OK", None),   # one number: not a refusal
    (lambda q: None, "DOMAIN_ERROR", "returned None"),
    (lambda q: 1 / 0, "DOMAIN_ERROR", "ZeroDivisionError"),        # the library refused
    (lambda q: [complex(0, 1)] * 4, "DOMAIN_ERROR", "returned TypeError"),
])
def test_status_rule(fn, status, refusal):
    outcome = rv.call("normalize", fn, [[0.0, 0.0, 0.0, 1.0]])
    assert (outcome.status, outcome.refusal) == (status, refusal)
    if status == "DOMAIN_ERROR" and refusal:
        assert all(math.isnan(x) for x in outcome.outputs["out_q"])


def test_did_not_return_is_status_255():
    def hangs(q):
        raise rv.DidNotReturn("stopped after 1 s")
    outcome = rv.call("normalize", hangs, [[0.0, 0.0, 0.0, 1.0]])
    assert outcome.status == rv.DID_NOT_RETURN == 255


@pytest.mark.parametrize("fn", [
    lambda q: undefined_name,  # noqa: F821 - the defect under test
    lambda q: q.no_such_attribute,
    lambda q: {}["key"],
    lambda q: [1.0, 2.0, 3.0],      # three values for a quaternion (LAYOUT-1)
])
def test_defects_of_the_mapping_are_not_refusals(fn):
    with pytest.raises(rv.AdapterError):
        rv.call("normalize", fn, [[0.0, 0.0, 0.0, 1.0]])


def test_two_outputs_come_as_a_tuple():
    outcome = rv.call("to_axis_angle", lambda q: (0.5, [1.0, 0.0, 0.0]), [[0.0, 0.0, 0.0, 1.0]])
    assert outcome.outputs == {"out_angle": [0.5], "out_axis": [1.0, 0.0, 0.0]}
    with pytest.raises(rv.AdapterError):
        rv.call("to_axis_angle", lambda q: [0.5, 1.0, 0.0, 0.0], [[0.0, 0.0, 0.0, 1.0]])


def test_round_trip_refuses_when_log_does():
    rt = rv.round_trip(lambda q: [math.nan] * 3, lambda v: [0.0, 0.0, 0.0, 1.0])
    assert rv.call("log_exp_round_trip", rt, [[0.0, 0.0, 0.0, 1.0]]).status == "DOMAIN_ERROR"
    rt = rv.round_trip(lambda q: [0.0, 0.0, 0.5], lambda v: [0.0, 0.0, math.sin(v[2]), math.cos(v[2])])
    assert rv.call("log_exp_round_trip", rt, [[0.0, 0.0, 0.0, 1.0]]).status == "OK"


def test_results_file_format(tmp_path):
    impl = rv.Implementation(name="golden", version="1", scalar="double", ops={"normalize": identity},
                             claimed_clauses=["NORM-1"], preconditions=["slerp:t_in_unit_interval"])
    (tmp_path / "vectors").mkdir()
    path = tmp_path / "results.json"
    unsupported = ["slerp", "compose"]
    rv.write_results(path, tmp_path / "vectors", impl, RESULTS_ENTRIES, unsupported)
    assert path.read_text() == GOLDEN
    assert json.loads(GOLDEN)["results"][2]["status"] == 255


def test_implementation_declares_every_other_op_unsupported_and_derives_the_round_trip():
    impl = rv.Implementation(name="x", scalar="float", ops={"log": identity, "exp": identity})
    assert impl.number_format == "binary32"
    assert "log_exp_round_trip" in impl.ops and "log_exp_round_trip" not in impl.unsupported_ops
    assert "log" not in impl.unsupported_ops and "normalize" in impl.unsupported_ops
    with pytest.raises(ValueError):
        rv.Implementation(name="x", scalar="double", ops={"normalise": identity})


def write_export(directory):
    """A one-file export in the formats of conformance/VECTORS.md."""
    os.makedirs(directory)
    vf = {"format": "rotorcert-vectors", "format_version": 1, "clause": "QLB-1", "op": "blend_qlb",
          "inputs": [{"name": "q", "stride": 4, "per_influence": True}, {"name": "w", "stride": 1, "per_influence": True}],
          "tests": [{"tcId": 1, "id": "QLB-1/blend_qlb/binary64/0001", "comment": "random", "flags": ["Random"], "k": 2,
                     "in": {"q": {"hex": ["0x0p+0", "0x0p+0", "0x0p+0", "0x1p+0", "0x1p-1", "0x0p+0", "0x0p+0", "-0x1.8p+0"]},
                            "w": {"hex": ["0x1p-1", "nan"]}},
                     "expected": {"status": "OK"}, "result": "valid"}]}
    with open(os.path.join(directory, "QLB-1_blend_qlb_binary64.json"), "w") as f:
        json.dump(vf, f)
    index = {"format": "rotorcert-vectors-index", "format_version": 1, "spec_version": "2.0.0", "seed": 1,
             "files": [{"file": "QLB-1_blend_qlb_binary64.json", "clause": "QLB-1", "level": "Blend", "op": "blend_qlb",
                        "number_format": "binary64", "tolerance": "eps32", "numberOfTests": 1}]}
    with open(os.path.join(directory, "index.json"), "w") as f:
        json.dump(index, f)


def test_reader_gives_k_elements_per_influence(tmp_path):
    write_export(tmp_path / "v")
    vs = rv.VectorSet(tmp_path / "v")
    assert [f.op for f in vs.files("binary64")] == ["blend_qlb"] and vs.files("binary32") == []
    (vector,) = vs.files("binary64")[0].vectors
    q, w = vector.arguments()
    assert q == [[0.0, 0.0, 0.0, 1.0], [0.5, 0.0, 0.0, -1.5]]
    assert w[0] == 0.5 and math.isnan(w[1])
    assert vector.describe_inputs().startswith("q=[0x0p+0, ")


def test_run_and_the_defect_message_name_the_vector(tmp_path):
    write_export(tmp_path / "v")

    def blend(q, w):
        return q[0]
    impl = rv.Implementation(name="x", scalar="double", ops={"blend_qlb": blend})
    run = rv.run(impl, tmp_path / "v", tmp_path / "r.json")
    assert [r["id"] for r in run.results] == ["QLB-1/blend_qlb/binary64/0001"]
    assert json.loads((tmp_path / "r.json").read_text())["vectors"] == "v"

    def broken(q, w):
        return q.shape
    with pytest.raises(rv.AdapterError, match=r"QLB-1/blend_qlb/binary64/0001 \(random\): blend_qlb\(q=\[0x0p\+0"):
        rv.run(rv.Implementation(name="x", scalar="double", ops={"blend_qlb": broken}), tmp_path / "v")


def test_a_foreign_file_is_refused(tmp_path):
    (tmp_path / "index.json").write_text('{"format": "something-else"}')
    with pytest.raises(rv.VectorsError):
        rv.VectorSet(tmp_path)


def test_a_call_that_modifies_its_inputs_is_reported():
    """HYG-1: the input lists, and library objects registered with watch(), are compared before and
    after the call; the result entry names what changed."""
    class Box:
        def __init__(self, v):
            self.v = list(v)

    def in_place(q):  # normalises the caller's list in place
        q[3] = 1.0
        return q

    def through_object(q):  # a library object built from the input, modified by the library
        box = rv.watch(Box(q))
        box.v[0] = -box.v[0]
        return [0.0, 0.0, 0.0, 1.0]

    clean = rv.call("normalize", identity, [[0.0, 0.0, 0.0, 2.0]])
    assert clean.modified == "" and "modified_inputs" not in clean.result("NORM-1/normalize/binary64/0001")
    listed = rv.call("normalize", in_place, [[0.0, 0.0, 0.0, 2.0]])
    assert "input lists" in listed.modified
    watched = rv.call("normalize", through_object, [[1.0, 0.0, 0.0, 0.0]])
    assert "watched input object 0 (Box)" in watched.result("NORM-1/normalize/binary64/0001")["modified_inputs"]

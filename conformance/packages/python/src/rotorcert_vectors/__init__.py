"""rotorcert-vectors: certify a rotation library written in Python against rotorcert's JSON test
vectors (conformance/VECTORS.md of rotorcert).

`rotorcert vectors export` writes the vectors; this package reads them exactly (every value from its
hexfloat), calls one function of yours per vector, maps what the call gave onto the spec's status
channel by one rule (RESULT-2, see `outcome`), and writes the results file that `rotorcert vectors
check` grades with the same judge as `rotorcert certify`.

Public API:

  Implementation(name, scalar, ops, version=, description=, claimed_clauses=, claimed_levels=,
                 preconditions=, conventions=)     what is certified; ops = {ABI op name: function}
  run(implementation, vectors, results_path=None) -> Run      every vector; writes the results file
  run_adapter(description, implementation, ops=None, argv=None)  an adapter script's command line
                                                               (--vectors DIR --out RESULTS.json)
  check(results_path, rotorcert="rotorcert", out=None) -> Certificate   `rotorcert vectors check`
  VectorSet(path), VectorFile, Vector                          the export, read lazily
  call(op, fn, args) -> Outcome                                one call under the status rule
  round_trip(log, exp)                                         EXP-2's log_exp_round_trip
  watch(*objects)                                              library objects built from the inputs,
                                                               checked for in-place modification (HYG-1)
  write_results(path, vectors_dir, implementation, results, unsupported), hexfloat, parse_hex
  DidNotReturn, AdapterError, VectorsError, CheckError

A function takes the op's inputs in the ABI's layouts (LAYOUT-1: quaternion [x, y, z, w], vector
[x, y, z], dual quaternion [real xyzw, dual xyzw], 3x3 matrix column-major, angles in radians):
one list of floats per input (a float for a scalar input such as slerp's t); an n-way op's
per-influence inputs are lists of k such elements. It returns its output (a list of floats, or a
float), or a tuple of them for an op with two outputs (to_axis_angle: angle, axis). To refuse an
input it raises an exception or returns None.

The pytest plugin (`pytest --rotorcert-vectors=DIR`) is `rotorcert_vectors.pytest_plugin`.
"""
from .abi import ABI_OPS, OUTPUTS, ROUND_TRIP
from .check import Certificate, CheckError, ClauseResult, check
from .numbers import hexfloat, parse_hex
from .outcome import (DID_NOT_RETURN, DOMAIN_ERROR, OK, AdapterError, DidNotReturn, Outcome, call,
                      round_trip, watch)
from .results import Implementation, results_text, write_results
from .runner import Run, run, run_adapter, run_file, run_vectors
from .vectors import Vector, VectorFile, VectorSet, VectorsError

__version__ = "0.1.0"

__all__ = [
    "ABI_OPS", "OUTPUTS", "ROUND_TRIP", "Certificate", "CheckError", "ClauseResult", "check", "hexfloat",
    "parse_hex", "DID_NOT_RETURN", "DOMAIN_ERROR", "OK", "AdapterError", "DidNotReturn", "Outcome", "call",
    "round_trip", "watch", "Implementation", "results_text", "write_results", "Run", "run", "run_adapter", "run_file",
    "run_vectors", "Vector", "VectorFile", "VectorSet", "VectorsError", "__version__",
]

"""Running every vector of an export through an Implementation, from a script or a test."""
import argparse
import sys

from .abi import ROUND_TRIP
from .outcome import AdapterError, DID_NOT_RETURN, call
from .results import Implementation, write_results
from .vectors import VectorSet


def run_file(vector_file, fn):
    """[(vector, Outcome)] of one vector file's op function on each of its vectors, in file order.
    A defect of fn (AdapterError) is re-raised with the vector's id and input in hexfloat."""
    outcomes = []
    for vector in vector_file.vectors:
        try:
            outcomes.append((vector, call(vector_file.op, fn, vector.arguments())))
        except AdapterError as e:
            raise AdapterError("%s (%s): %s(%s): %s" % (vector.id, vector.comment, vector_file.op,
                                                        vector.describe_inputs(), e), vector) from e.__cause__
    return outcomes


def refusal_key(op, outcome):
    return "%s %s" % (op, "did not return" if outcome.status == DID_NOT_RETURN else "refused")


class Run:
    """The outcome of every vector an Implementation answers: `results` (results-file entries in
    index order), `refused` ({"op refused" / "op did not return": count}), `outcomes`
    ({vector id: Outcome})."""

    def __init__(self, implementation, vector_set):
        self.implementation, self.vector_set = implementation, vector_set
        self.results, self.refused, self.outcomes = [], {}, {}

    def add(self, vector, outcome):
        self.results.append(outcome.result(vector.id))
        self.outcomes[vector.id] = outcome
        if outcome.refusal:
            key = refusal_key(vector.file.op, outcome)
            self.refused[key] = self.refused.get(key, 0) + 1

    def write(self, path):
        write_results(path, self.vector_set.directory, self.implementation, self.results,
                      self.implementation.unsupported_ops)


def run(implementation, vectors, results_path=None):
    """Runs every vector of `vectors` (a VectorSet, or the export's directory or index.json) of the
    implementation's number format whose op it has; writes the results file when results_path is
    given; returns the Run."""
    vector_set = vectors if isinstance(vectors, VectorSet) else VectorSet(vectors)
    result = Run(implementation, vector_set)
    for vector_file in vector_set.files(implementation.number_format, implementation.ops):
        for vector, outcome in run_file(vector_file, implementation.ops[vector_file.op]):
            result.add(vector, outcome)
    if results_path is not None:
        result.write(results_path)
    return result


def run_vectors(vectors_dir, ops, number_format="binary64"):
    """Every vector of `number_format` whose op is in `ops` ({name: function}): (results-file
    entries, {"op refused" / "op did not return": count})."""
    vector_set = VectorSet(vectors_dir)
    results, refused = [], {}
    for vector_file in vector_set.files(number_format, ops):
        for vector, outcome in run_file(vector_file, ops[vector_file.op]):
            results.append(outcome.result(vector.id))
            if outcome.refusal:
                key = refusal_key(vector_file.op, outcome)
                refused[key] = refused.get(key, 0) + 1
    return results, refused


def run_adapter(description, implementation, ops=None, all_ops=None, argv=None):
    """The command line of an adapter script: --vectors DIR --out RESULTS.json; returns the exit
    status (0). `implementation` is an Implementation, or a results-file implementation object
    (dict: name, version, scalar, description, ...) with `ops` ({ABI op: function}). Every ABI op
    without a function is declared unsupported (NOT_SUPPORTED, RESULT-1), or those of `all_ops`
    when given."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--vectors", required=True, help="directory written by `rotorcert vectors export`")
    p.add_argument("--out", required=True, help="results file to write")
    args = p.parse_args(argv)
    impl = implementation if isinstance(implementation, Implementation) else Implementation.from_dict(implementation, ops)
    result = run(impl, args.vectors)
    unsupported = (impl.unsupported_ops if all_ops is None else
                   [op for op in all_ops if op not in impl.ops and op != ROUND_TRIP])
    write_results(args.out, args.vectors, impl, result.results, unsupported)
    note = ", ".join("%s %d" % kv for kv in sorted(result.refused.items()))
    print("%s: wrote %d results to %s%s" % (impl.name, len(result.results), args.out,
                                             " (" + note + ")" if note else ""))
    sys.stdout.flush()
    return 0

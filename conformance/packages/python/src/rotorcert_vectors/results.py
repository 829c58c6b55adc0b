"""What is certified (Implementation) and the results file (format rotorcert-results, version 1,
conformance/VECTORS.md) that `rotorcert vectors check` grades."""
import json
import os

from .abi import ABI_OPS, NUMBER_FORMATS, OUTPUTS, ROUND_TRIP
from .outcome import round_trip


class Implementation:
    """A library to certify: the results file's `implementation` object and one function per ABI
    op it maps.

    name, scalar ("float" or "double": the binary32 or the binary64 vectors), ops ({ABI op name:
    function}; see `call` for what a function takes and returns) are required. version and
    description are free text. claimed_clauses / claimed_levels: what is certified (default: every
    clause with a result / the levels of the claimed clauses). preconditions / conventions (DECL-1):
    "op:id" strings of what the library documents, e.g. "slerp:t_in_unit_interval", "slerp:oriented".

    With `log` and `exp` and no function of its own for `log_exp_round_trip`, EXP-2's round trip is
    exp of what log returned (`round_trip`). Every ABI op without a function is declared
    unsupported (NOT_SUPPORTED, RESULT-1).
    """

    def __init__(self, name, scalar, ops, version=None, description=None, claimed_clauses=None,
                 claimed_levels=None, preconditions=(), conventions=()):
        if scalar not in NUMBER_FORMATS:
            raise ValueError("scalar must be 'float' or 'double', not %r" % (scalar,))
        unknown = sorted(set(ops) - set(OUTPUTS))
        if unknown:
            raise ValueError("not ABI ops (impls/include/rotorcert/impl_abi.h): %s" % ", ".join(unknown))
        self.name, self.scalar, self.version, self.description = name, scalar, version, description
        self.ops = dict(ops)
        if ROUND_TRIP not in self.ops and "log" in self.ops and "exp" in self.ops:
            self.ops[ROUND_TRIP] = round_trip(self.ops["log"], self.ops["exp"])
        self.claimed_clauses = list(claimed_clauses) if claimed_clauses is not None else None
        self.claimed_levels = list(claimed_levels) if claimed_levels is not None else None
        self.preconditions, self.conventions = list(preconditions), list(conventions)
        self._extra = {}

    @classmethod
    def from_dict(cls, implementation, ops):
        """From a results file's implementation object (a dict with name, scalar, ...) and ops; keys
        this class does not know are kept, in their order."""
        known = ("name", "scalar", "version", "description", "claimed_clauses", "claimed_levels",
                 "preconditions", "conventions")
        impl = cls(ops=ops, **{k: implementation[k] for k in known if k in implementation})
        impl._extra = {k: v for k, v in implementation.items() if k not in known}
        return impl

    @property
    def number_format(self):
        return NUMBER_FORMATS[self.scalar]

    @property
    def unsupported_ops(self):
        return sorted(op for op in ABI_OPS if op not in self.ops)

    def header(self):
        """The results file's `implementation` object (only the fields that are set)."""
        h = {"name": self.name}
        if self.version is not None:
            h["version"] = self.version
        h["scalar"] = self.scalar
        if self.description is not None:
            h["description"] = self.description
        for key in ("claimed_clauses", "claimed_levels"):
            if getattr(self, key) is not None:
                h[key] = getattr(self, key)
        for key in ("preconditions", "conventions"):
            if getattr(self, key):
                h[key] = getattr(self, key)
        h["hygiene"] = ["HYG-1"]  # every call is checked for modified inputs (outcome.watch)
        h.update(self._extra)
        return h

    def __repr__(self):
        return "Implementation(%r, %r, ops=%s)" % (self.name, self.scalar, sorted(self.ops))


def results_text(results_path, vectors_dir, implementation, results, unsupported):
    """The text of a results file: `implementation` (a dict or an Implementation), `results` (the
    entries, Outcome.result), `unsupported` (ABI op names). `vectors` is written relative to the
    results file. One result per line, so that a diff of two runs shows the vectors that differ."""
    out_dir = os.path.dirname(os.path.abspath(results_path))
    head = {
        "format": "rotorcert-results",
        "format_version": 1,
        "implementation": implementation.header() if isinstance(implementation, Implementation) else implementation,
        "vectors": os.path.relpath(os.path.abspath(vectors_dir), out_dir),
        "unsupported_ops": sorted(unsupported),
        "results": None,
    }
    text = json.dumps(head, indent=2)
    body = ",\n    ".join(json.dumps(r) for r in results)
    return text.replace('"results": null', '"results": [\n    ' + body + "\n  ]" if results else '"results": []') + "\n"


def write_results(path, vectors_dir, implementation, results, unsupported):
    """Writes the results file atomically (a reader never sees half of it)."""
    path = os.fspath(path)
    text = results_text(path, vectors_dir, implementation, results, unsupported)
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)

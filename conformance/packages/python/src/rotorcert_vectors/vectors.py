"""Reading an export of `rotorcert vectors export`: index.json and the vector files it lists
(formats rotorcert-vectors-index and rotorcert-vectors, version 1, conformance/VECTORS.md)."""
import json
import os

from .numbers import parse_hex


class VectorsError(Exception):
    """An export that cannot be read: missing, of another format, or malformed."""


def _load_json(path, what):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise VectorsError("cannot read %s %s: %s" % (what, path, e.strerror or e)) from e
    except ValueError as e:
        raise VectorsError("%s is not JSON: %s" % (path, e)) from e


def _check_format(doc, path, fmt):
    if not isinstance(doc, dict) or doc.get("format") != fmt or doc.get("format_version") != 1:
        raise VectorsError("%s: not a %s file of format_version 1" % (path, fmt))


class Vector:
    """One test of a vector file: its id (CLAUSE/op/format/tcId), what it probes, its inputs."""

    __slots__ = ("file", "id", "tc_id", "comment", "flags", "k", "result", "expected_status", "hex_inputs")

    def __init__(self, file, test):
        self.file = file
        self.id = test["id"]
        self.tc_id = test["tcId"]
        self.comment = test.get("comment", "")
        self.flags = tuple(test.get("flags", ()))
        self.k = test.get("k", 0)
        self.result = test.get("result")  # valid | invalid | acceptable
        self.expected_status = test.get("expected", {}).get("status")
        self.hex_inputs = {name: list(arr["hex"]) for name, arr in test["in"].items()}

    def arguments(self):
        """The inputs as the op's function takes them, in the file's input order: one element per
        input (a list of `stride` floats, or a float when the stride is 1); an input given per
        influence (n-way ops) is a list of k such elements. Values are exact (parse_hex)."""
        args = []
        for name, stride, per_influence in self.file.layout:
            values = [parse_hex(h) for h in self.hex_inputs[name]]
            if per_influence:
                args.append([values[i * stride:(i + 1) * stride] if stride > 1 else values[i]
                             for i in range(self.k)])
            else:
                args.append(values if stride > 1 else values[0])
        return args

    def describe_inputs(self):
        """The inputs in hexfloat as certificates print them: `a=[0x1p+0, ...] t=[0x1p-1]`."""
        return " ".join("%s=[%s]" % (name, ", ".join(self.hex_inputs[name])) for name, _, _ in self.file.layout)

    def __repr__(self):
        return "Vector(%s)" % self.id


class VectorFile:
    """One file of an export: the vectors of one (clause, op, number format). The header comes from
    index.json; the tests are read on first use."""

    def __init__(self, vector_set, entry):
        self.vector_set = vector_set
        self.file = entry["file"]
        self.path = os.path.join(vector_set.directory, entry["file"])
        self.clause = entry["clause"]
        self.level = entry.get("level")
        self.op = entry["op"]
        self.number_format = entry["number_format"]
        self.tolerance = entry.get("tolerance")
        self.number_of_tests = entry.get("numberOfTests")
        self._doc = None
        self._vectors = None

    def _load(self):
        if self._doc is None:
            doc = _load_json(self.path, "vector file")
            _check_format(doc, self.path, "rotorcert-vectors")
            if doc.get("op") != self.op or doc.get("clause") != self.clause:
                raise VectorsError("%s: clause/op %s/%s, index.json says %s/%s"
                                   % (self.path, doc.get("clause"), doc.get("op"), self.clause, self.op))
            self._doc = doc
        return self._doc

    @property
    def title(self):
        return self._load().get("clause_title", "")

    @property
    def layout(self):
        """(name, stride, per_influence) of each input array, in the op's argument order."""
        return [(a["name"], a["stride"], bool(a.get("per_influence", False))) for a in self._load()["inputs"]]

    @property
    def vectors(self):
        if self._vectors is None:
            self._vectors = [Vector(self, t) for t in self._load()["tests"]]
        return self._vectors

    def __repr__(self):
        return "VectorFile(%s)" % self.file


class VectorSet:
    """An export: `VectorSet(path)` with the export's directory or its index.json."""

    def __init__(self, path):
        path = os.fspath(path)
        if os.path.isdir(path):
            self.directory, self.index_path = path, os.path.join(path, "index.json")
        else:
            self.directory, self.index_path = os.path.dirname(path) or ".", path
        self.index = _load_json(self.index_path, "vectors index")
        _check_format(self.index, self.index_path, "rotorcert-vectors-index")
        try:
            self._files = [VectorFile(self, e) for e in self.index["files"]]
        except (KeyError, TypeError) as e:
            raise VectorsError("%s: malformed files list (%s)" % (self.index_path, e)) from e

    @property
    def spec_version(self):
        return self.index.get("spec_version")

    @property
    def rotorcert_version(self):
        return self.index.get("rotorcert_version")

    @property
    def seed(self):
        return self.index.get("seed")

    @property
    def cases_per_family(self):
        return self.index.get("cases_per_family")

    def files(self, number_format=None, ops=None):
        """The vector files in index order, of one number format ("binary64") and of the ops in
        `ops` (any container of op names) when given."""
        return [f for f in self._files
                if (number_format is None or f.number_format == number_format) and (ops is None or f.op in ops)]

    def __repr__(self):
        return "VectorSet(%r)" % self.directory

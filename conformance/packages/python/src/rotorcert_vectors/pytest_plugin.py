"""pytest plugin: certify the library a test suite tests, from that suite (entry point `pytest11`).

    rotorcert vectors export --out vectors --scalar double
    pytest --rotorcert-vectors=vectors [--rotorcert-results=results.json] [--rotorcert-check=rotorcert]

Inert unless --rotorcert-vectors is given. Then a conftest.py names the implementation:

    def pytest_rotorcert_implementation(config):
        return rotorcert_vectors.Implementation(name=..., scalar="double", ops={...}, ...)

and the plugin adds to the session one item per vector file the implementation answers, named
`rotorcert::CLAUSE[op]`, which calls the op's function on every vector of the file under the one
status rule (RESULT-2, rotorcert_vectors.outcome). An item fails, naming the vector id and its
input in hexfloat, when the function has a defect rather than an answer (NameError, a wrong number
of outputs, ...); a refusal of the library is its answer and is graded, not failed here. At the end
the results file is written. With --rotorcert-check, a last item `rotorcert::certificate` runs
`rotorcert vectors check` on it (the judge of `rotorcert certify`, against the 256-bit reference)
and fails when a claimed clause does not pass, listing those clauses with their worst inputs.
"""
import os
import pathlib
import traceback

import pytest

from . import pytest_hooks
from .check import CheckError, check
from .outcome import AdapterError
from .results import Implementation, write_results
from .runner import refusal_key, run_file
from .vectors import VectorSet, VectorsError

PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))


def pytest_addhooks(pluginmanager):
    pluginmanager.add_hookspecs(pytest_hooks)


def pytest_addoption(parser):
    group = parser.getgroup("rotorcert", "rotorcert test vectors (conformance/VECTORS.md)")
    group.addoption("--rotorcert-vectors", metavar="DIR",
                    help="certify the implementation of pytest_rotorcert_implementation against this export "
                         "of `rotorcert vectors export` (a directory or its index.json)")
    group.addoption("--rotorcert-results", metavar="FILE", default="rotorcert-results.json",
                    help="the results file to write (default: rotorcert-results.json)")
    group.addoption("--rotorcert-check", metavar="ROTORCERT",
                    help="grade the results with `ROTORCERT vectors check` in a last item, "
                         "rotorcert::certificate, which fails when a claimed clause does not pass")
    group.addoption("--rotorcert-report", metavar="DIR",
                    help="where `vectors check` writes report.json/.md/.html "
                         "(default: rotorcert-report beside the results file)")


class State:
    """The rotorcert part of one session."""

    def __init__(self, config):
        start = str(config.invocation_params.dir)
        self.config = config
        self.vectors_path = os.path.abspath(os.path.join(start, config.getoption("rotorcert_vectors")))
        self.results_path = os.path.abspath(os.path.join(start, config.getoption("rotorcert_results")))
        rotorcert = config.getoption("rotorcert_check")
        self.rotorcert = (os.path.abspath(os.path.join(start, rotorcert)) if rotorcert and os.sep in rotorcert
                          else rotorcert)
        report = config.getoption("rotorcert_report")
        self.report_dir = (os.path.abspath(os.path.join(start, report)) if report else
                           os.path.join(os.path.dirname(self.results_path), "rotorcert-report"))
        try:
            self.vector_set = VectorSet(self.vectors_path)
        except VectorsError as e:
            raise pytest.UsageError("--rotorcert-vectors: %s" % e) from e
        self.implementation = None
        self.files = []          # the VectorFiles the implementation answers, index order
        self.outcomes = {}       # VectorFile.file -> [(vector, Outcome)]
        self.unselected = []     # vector items deselected (-k, --deselect): the certificate needs all
        self.written = None      # number of results last written
        self.certificate = None

    def load_implementation(self):
        impl = self.config.hook.pytest_rotorcert_implementation(config=self.config)
        if impl is None:
            raise pytest.UsageError("--rotorcert-vectors: no conftest.py implements "
                                    "pytest_rotorcert_implementation(config) returning a rotorcert_vectors.Implementation")
        if not isinstance(impl, Implementation):
            raise pytest.UsageError("pytest_rotorcert_implementation returned %r, not a rotorcert_vectors.Implementation"
                                    % (impl,))
        self.implementation = impl
        self.files = self.vector_set.files(impl.number_format, impl.ops)

    def results(self):
        entries, refused = [], {}
        for vf in self.files:
            for vector, outcome in self.outcomes.get(vf.file, ()):
                entries.append(outcome.result(vector.id))
                if outcome.refusal:
                    key = refusal_key(vf.op, outcome)
                    refused[key] = refused.get(key, 0) + 1
        return entries, refused

    def write(self):
        entries, _ = self.results()
        os.makedirs(os.path.dirname(self.results_path) or ".", exist_ok=True)
        write_results(self.results_path, self.vector_set.directory, self.implementation, entries,
                      self.implementation.unsupported_ops)
        self.written = len(entries)


STATE = pytest.StashKey()


def pytest_configure(config):
    config.addinivalue_line("markers", "rotorcert: an item of the rotorcert test vectors")
    if not config.getoption("rotorcert_vectors"):
        return
    if getattr(config.option, "numprocesses", None):
        raise pytest.UsageError("--rotorcert-vectors: the results file is written by one process; run without -n")
    config.stash[STATE] = State(config)


def pytest_report_header(config):
    state = config.stash.get(STATE, None)
    if state is None:
        return None
    vs = state.vector_set
    return "rotorcert: vectors %s (rotorcert %s, spec %s, seed %s, %s cases per family), results %s" % (
        vs.directory, vs.rotorcert_version, vs.spec_version, vs.seed, vs.cases_per_family, state.results_path)


class VectorFileItem(pytest.Item):
    """Every vector of one vector file through the implementation's function for its op."""

    def __init__(self, *, vector_file, state, **kw):
        super().__init__(**kw)
        self.vector_file, self.state = vector_file, state
        self.add_marker("rotorcert")

    def runtest(self):
        vf = self.vector_file
        self.state.outcomes.pop(vf.file, None)
        self.state.outcomes[vf.file] = run_file(vf, self.state.implementation.ops[vf.op])

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, AdapterError):
            return format_adapter_error(excinfo.value)
        if isinstance(excinfo.value, VectorsError):
            return "rotorcert: %s" % excinfo.value
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.path, None, "rotorcert %s %s" % (self.vector_file.clause, self.vector_file.op)


def format_adapter_error(error):
    """The vector, its input and the traceback of the defect, without this package's frames."""
    lines = ["%s" % error]
    cause = error.__cause__
    if cause is not None:
        frames = [f for f in traceback.extract_tb(cause.__traceback__)
                  if not os.path.abspath(f.filename).startswith(PACKAGE_DIR + os.sep)]
        lines.append("Traceback (most recent call last, rotorcert_vectors' frames left out):")
        lines.extend(l.rstrip("\n") for l in traceback.format_list(frames))
        lines.extend(l.rstrip("\n") for l in traceback.format_exception_only(type(cause), cause))
    return "\n".join(lines)


class CertificateFailed(Exception):
    """A rotorcert item that fails with a message of its own, without a Python traceback."""


class CertificateItem(pytest.Item):
    """Writes the results file and grades it with `rotorcert vectors check`."""

    def __init__(self, *, state, **kw):
        super().__init__(**kw)
        self.state = state
        self.add_marker("rotorcert")

    def runtest(self):
        state = self.state
        if state.unselected:
            pytest.skip("%d of %d rotorcert vector items were deselected (%s...): a certificate needs all of them"
                        % (len(state.unselected), len(state.files), state.unselected[0]))
        state.write()
        try:
            cert = check(state.results_path, state.rotorcert, out=state.report_dir,
                         vectors=state.vector_set.index_path)
        except CheckError as e:
            raise CertificateFailed("rotorcert vectors check could not grade %s: %s" % (state.results_path, e)) from e
        state.certificate = cert
        if not cert.passed:
            failed = cert.failed_clauses()
            raise CertificateFailed("\n".join(
                ["rotorcert vectors check %s: exit %d, %s" % (state.results_path, cert.exit_code, cert.claim()),
                 "claimed clauses that do not pass: %s" % (", ".join(c.id for c in failed) or "(see the certificate)"),
                 "", cert.output.rstrip()]))

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, CertificateFailed):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.path, None, "rotorcert certificate"


@pytest.hookimpl(hookwrapper=True)
def pytest_collection_modifyitems(session, config, items):
    """Adds the rotorcert items before -k / --deselect select among them (and other plugins
    reorder them); afterwards notes the deselected vector items and puts the certificate last."""
    state = config.stash.get(STATE, None)
    if state is None:
        yield
        return
    state.load_implementation()
    directory = pathlib.Path(os.path.abspath(state.vector_set.directory))
    vector_items = []
    for vf in state.files:
        name = "%s[%s]" % (vf.clause, vf.op)
        vector_items.append(VectorFileItem.from_parent(session, name=name, nodeid="rotorcert::" + name,
                                                       path=pathlib.Path(vf.path), vector_file=vf, state=state))
    items.extend(vector_items)
    if not state.files:
        items.append(NothingToRunItem.from_parent(session, name="vectors", nodeid="rotorcert::vectors",
                                                  path=directory, state=state))
    certificate = None
    if state.rotorcert:
        certificate = CertificateItem.from_parent(session, name="certificate", nodeid="rotorcert::certificate",
                                                  path=directory, state=state)
        items.append(certificate)
    yield
    kept = set(map(id, items))
    state.unselected = [item.nodeid for item in vector_items if id(item) not in kept]
    if certificate is not None and id(certificate) in kept:  # it grades what the others wrote
        items.remove(certificate)
        items.append(certificate)


class NothingToRunItem(pytest.Item):
    """Fails: the export holds no vector of the implementation's number format and ops."""

    def __init__(self, *, state, **kw):
        super().__init__(**kw)
        self.state = state

    def runtest(self):
        impl = self.state.implementation
        raise CertificateFailed("%s has no vectors of %s for the ops of %s (%s): export them with "
                                "`rotorcert vectors export --scalar %s`" % (
                                    self.state.vector_set.index_path, impl.number_format, impl.name,
                                    ", ".join(sorted(impl.ops)), impl.scalar))

    def repr_failure(self, excinfo, style=None):
        return str(excinfo.value)

    def reportinfo(self):
        return self.path, None, "rotorcert vectors"


def pytest_sessionfinish(session, exitstatus):
    """Writes the results file unless the certificate item just did; not when no vector item ran
    (--collect-only, -k selecting other tests), which would overwrite a full file with an empty one."""
    state = session.config.stash.get(STATE, None)
    if state is None or state.implementation is None or not state.outcomes:
        return
    entries, _ = state.results()
    if state.written != len(entries):
        state.write()


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    state = config.stash.get(STATE, None)
    if state is None or state.implementation is None or state.written is None:
        return
    _, refused = state.results()
    note = ", ".join("%s %d" % kv for kv in sorted(refused.items()))
    tr = terminalreporter
    tr.write_sep("-", "rotorcert")
    impl = state.implementation
    tr.write_line("%s (%s): wrote %d results to %s%s" % (
        impl.name, impl.scalar, state.written, state.results_path,
        " (DOMAIN_ERROR by the status rule: " + note + ")" if note else ""))
    if state.certificate is not None:
        tr.write_line("certificate: %s (%s)" % (state.certificate.claim(),
                                                os.path.join(state.report_dir, "report.html")))
    elif not state.rotorcert:
        tr.write_line("grade it: rotorcert vectors check %s" % state.results_path)

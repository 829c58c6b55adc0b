#!/usr/bin/env python3
"""The ctests of the rotorcert-vectors packages: a library maintainer certifies from their own suite.

    test_packages.py python --rotorcert BIN --work DIR     pytest plugin  (conformance_package_python_pytest)
    test_packages.py node   --rotorcert BIN --work DIR     node:test helper (conformance_package_node_test)

Each installs the package from this checkout into a scratch environment under DIR, offline (python:
a virtual environment with --system-site-packages, where pytest comes from the system; node: a
scratch npm project), runs the package's unit tests, then the example project of the package
(example/: a quaternion library with normalize, compose, inverse, apply_vector, slerp) through its
own test runner with the rotorcert check, three times:

  correct                                      the run passes and the certificate passes;
  ROTORCERT_EXAMPLE_DEFECT=compose_reversed    the run fails, the certificate item/subtest fails
                                               naming COMPOSE-1 and the reverse_map convention (CONV-1);
  ROTORCERT_EXAMPLE_DEFECT=typo                the run fails, the COMPOSE-1 item/subtest fails naming
                                               the vector id and its input in hexfloat.

Exit 0 when every expectation holds, 1 otherwise, 77 (a ctest skip) when python3-venv, pip, pytest
>= 7, node >= 18 or npm is missing, saying which.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
# The clauses the examples claim (example/conftest.py, example/quaternion.test.js): only these are
# exported, few cases each, so that a run takes seconds.
CLAUSES = ["QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4",
           "SLERP-5", "EDGE-6", "EDGE-7"]
CASES = 8


class Skip(Exception):
    pass


def run(cmd, cwd=None, env=None, timeout=300):
    """(exit status, output) of cmd, echoed."""
    print("$ " + " ".join(cmd) + ("   (in %s)" % cwd if cwd else ""), flush=True)
    full_env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    full_env.update(env or {})
    try:
        p = subprocess.run(cmd, cwd=cwd, env=full_env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=timeout)
    except subprocess.TimeoutExpired as e:
        return 124, (e.stdout or b"").decode("utf-8", "replace") + "\n(timed out after %d s)" % timeout
    except OSError as e:
        return 127, str(e)
    return p.returncode, p.stdout.decode("utf-8", "replace")


class Expectations:
    def __init__(self):
        self.failures = []

    def check(self, ok, what, output=""):
        print("%s: %s" % ("ok  " if ok else "FAIL", what), flush=True)
        if not ok:
            self.failures.append(what)
            if output:
                print("---- output ----\n" + output.rstrip()[-6000:] + "\n----------------", flush=True)


def export(rotorcert, out):
    cmd = [rotorcert, "vectors", "export", "--out", out, "--scalar", "double", "--cases", str(CASES)]
    for c in CLAUSES:
        cmd += ["--clause", c]
    shutil.rmtree(out, ignore_errors=True)
    rc, output = run(cmd)
    if rc != 0:
        raise RuntimeError("rotorcert vectors export failed (%d):\n%s" % (rc, output))


def fresh_copy(src, dst):
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns("__pycache__", "node_modules", ".pytest_cache"))


# ---- python: the pytest plugin -------------------------------------------------------------------

def test_python(args, expect):
    package = os.path.join(args.packages, "python")
    work = os.path.abspath(args.work)
    venv = os.path.join(work, "venv")
    python = os.path.join(venv, "bin", "python")
    shutil.rmtree(venv, ignore_errors=True)
    rc, output = run([sys.executable, "-m", "venv", "--system-site-packages", venv])
    if rc != 0:
        raise Skip("cannot create a virtual environment with %s -m venv (Debian: python3-venv): %s"
                   % (sys.executable, output.strip().splitlines()[-1:] or ""))
    rc, output = run([python, "-c", "import pytest, sys; sys.exit(int(pytest.__version__.split('.')[0]) < 7)"])
    if rc != 0:
        raise Skip("pytest >= 7 is not importable by %s (Debian: python3-pytest)" % sys.executable)
    rc, output = run([python, "-m", "pip", "--version"])
    if rc != 0:
        raise Skip("pip is not available in the virtual environment (Debian: python3-venv, python3-pip)")

    # The install a maintainer does; offline: no index, no build isolation, no dependencies.
    rc, output = run([python, "-m", "pip", "install", "--disable-pip-version-check", "--no-input", "--no-index",
                      "--no-deps", "--no-build-isolation", package])
    expect.check(rc == 0, "pip install %s (offline)" % package, output)
    if rc != 0:
        return
    rc, output = run([python, "-c", "import rotorcert_vectors, sys; print(rotorcert_vectors.__file__)"])
    expect.check(rc == 0 and output.strip().startswith(venv + os.sep),
                 "rotorcert_vectors is imported from the virtual environment, not the checkout", output)

    rc, output = run([python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--rootdir", work,
                      os.path.join(package, "tests")], cwd=work)
    expect.check(rc == 0, "the package's unit tests pass", output)

    vectors = os.path.join(work, "vectors")
    export(args.rotorcert, vectors)
    project = os.path.join(work, "project")
    results = os.path.join(work, "results.json")

    def pytest_run(defect):
        fresh_copy(os.path.join(package, "example"), project)
        if os.path.exists(results):
            os.remove(results)
        env = {"ROTORCERT_EXAMPLE_DEFECT": defect}
        return run([python, "-m", "pytest", "-v", "-p", "no:cacheprovider", "-rfEs",
                    "--rotorcert-vectors=" + vectors, "--rotorcert-results=" + results,
                    "--rotorcert-check=" + args.rotorcert, "--rotorcert-report=" + os.path.join(work, "report")],
                   cwd=project, env=env)

    rc, output = pytest_run("")
    expect.check(rc == 0, "correct example: pytest exits 0", output)
    expect.check(re.search(r"rotorcert::certificate PASSED", output) is not None,
                 "correct example: rotorcert::certificate passed", output)
    expect.check(re.search(r"rotorcert::COMPOSE-1\[compose\] PASSED", output) is not None,
                 "correct example: one item per vector file (rotorcert::COMPOSE-1[compose])", output)
    expect.check(os.path.isfile(results) and os.path.isfile(os.path.join(work, "report", "report.json")),
                 "correct example: results file and report written")

    rc, output = pytest_run("compose_reversed")
    expect.check(rc == 1, "compose_reversed: pytest exits 1 (was %d)" % rc, output)
    expect.check("FAILED rotorcert::certificate" in output and
                 "claimed clauses that do not pass: COMPOSE-1\n" in output and
                 "consistent with convention: reverse_map" in output,
                 "compose_reversed: rotorcert::certificate fails naming COMPOSE-1 only, reverse_map", output)
    expect.check(re.search(r"FAILED rotorcert::(?!certificate)", output) is None,
                 "compose_reversed: every vector item passed (the defect is a wrong answer, not a crash)", output)

    rc, output = pytest_run("typo")
    expect.check(rc == 1, "typo: pytest exits 1 (was %d)" % rc, output)
    expect.check("FAILED rotorcert::COMPOSE-1[compose]" in output and
                 re.search(r"COMPOSE-1/compose/binary64/\d{4} \([^)]*\): compose\(a=\[0x", output) is not None and
                 "NameError: name 'hamiltonian' is not defined" in output,
                 "typo: rotorcert::COMPOSE-1[compose] fails naming the vector id, its hexfloat input and the NameError",
                 output)


# ---- node: the node:test helper --------------------------------------------------------------------

def test_node(args, expect):
    package = os.path.join(args.packages, "node")
    node, npm = shutil.which("node"), shutil.which("npm")
    if not node or not npm:
        raise Skip("node and npm are not installed (Debian: nodejs npm; scripts/bootstrap installs them)")
    rc, output = run([node, "-p", "process.versions.node"])
    version = tuple(int(x) for x in re.findall(r"\d+", output)[:2]) if rc == 0 else (0, 0)
    if version < (18, 0):
        raise Skip("node %s is older than 18 (node:test)" % output.strip())
    # TAP: "ok N - NAME" / "not ok N - NAME" to match; the default before --test-reporter existed.
    reporter = ["--test-reporter=tap"] if version >= (19, 6) or (18, 15) <= version < (19, 0) else []
    work = os.path.abspath(args.work)
    project = os.path.join(work, "project")
    shutil.rmtree(project, ignore_errors=True)
    os.makedirs(project)
    with open(os.path.join(project, "package.json"), "w") as f:
        f.write('{"name": "rotorcert-example-user", "version": "1.0.0", "private": true}\n')

    # The install a maintainer does; offline, a copy (not a link into the checkout), not saved.
    rc, output = run([npm, "install", "--no-save", "--no-audit", "--no-fund", "--install-links", "--offline",
                      "--cache", os.path.join(work, "npm-cache"), package], cwd=project)
    expect.check(rc == 0, "npm install %s (offline)" % package, output)
    installed = os.path.join(project, "node_modules", "rotorcert-vectors")
    expect.check(os.path.isdir(installed) and not os.path.islink(installed) and
                 os.path.isfile(os.path.join(installed, "lib", "node_test.js")),
                 "node_modules/rotorcert-vectors is a copy of the package")
    if rc != 0:
        return

    rc, output = run([node, "--test", os.path.join(package, "test", "rotorcert_vectors.test.js")], cwd=work)
    expect.check(rc == 0, "the package's unit tests pass", output)

    vectors = os.path.join(work, "vectors")
    export(args.rotorcert, vectors)
    results = os.path.join(work, "results.json")
    example = os.path.join(package, "example")

    def node_run(defect):
        for name in os.listdir(example):
            shutil.copy(os.path.join(example, name), os.path.join(project, name))
        if os.path.exists(results):
            os.remove(results)
        env = {"ROTORCERT_EXAMPLE_DEFECT": defect, "ROTORCERT_VECTORS": vectors, "ROTORCERT_RESULTS": results,
               "ROTORCERT_CHECK": args.rotorcert, "ROTORCERT_REPORT": os.path.join(work, "report")}
        return run([node, "--test"] + reporter + ["quaternion.test.js"], cwd=project, env=env)

    rc, output = node_run("")
    expect.check(rc == 0, "correct example: node --test exits 0", output)
    expect.check(re.search(r"^\s*ok \d+ - certificate$", output, re.M) is not None and
                 re.search(r"^\s*ok \d+ - COMPOSE-1\[compose\]$", output, re.M) is not None,
                 "correct example: subtests COMPOSE-1[compose] and certificate passed", output)
    expect.check(os.path.isfile(results) and os.path.isfile(os.path.join(work, "report", "report.json")),
                 "correct example: results file and report written")

    rc, output = node_run("compose_reversed")
    expect.check(rc == 1, "compose_reversed: node --test exits 1 (was %d)" % rc, output)
    expect.check(re.search(r"^\s*not ok \d+ - certificate$", output, re.M) is not None and
                 "claimed clauses that do not pass: COMPOSE-1\n" in output and
                 "consistent with convention: reverse_map" in output,
                 "compose_reversed: the certificate subtest fails naming COMPOSE-1 only, reverse_map", output)
    expect.check(re.search(r"^\s*not ok \d+ - [A-Z]+-\d+\[", output, re.M) is None,
                 "compose_reversed: every vector subtest passed (the defect is a wrong answer, not a crash)", output)

    rc, output = node_run("typo")
    expect.check(rc == 1, "typo: node --test exits 1 (was %d)" % rc, output)
    expect.check(re.search(r"^\s*not ok \d+ - COMPOSE-1\[compose\]$", output, re.M) is not None and
                 re.search(r"COMPOSE-1/compose/binary64/\d{4} \([^)]*\): compose\(a=\[0x", output) is not None and
                 "hamiltonian is not defined" in output,
                 "typo: subtest COMPOSE-1[compose] fails naming the vector id, its hexfloat input and the ReferenceError",
                 output)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("language", choices=("python", "node"))
    p.add_argument("--rotorcert", required=True, help="the rotorcert executable")
    p.add_argument("--work", required=True, help="scratch directory (replaced)")
    p.add_argument("--packages", default=HERE,
                   help="where the python/ and node/ packages are (default: this checkout's; the ctests "
                        "pass the installed PREFIX/share/rotorcert/packages)")
    args = p.parse_args(argv)
    if os.sep in args.rotorcert:  # the runs below start in other directories
        args.rotorcert = os.path.abspath(args.rotorcert)
    os.makedirs(args.work, exist_ok=True)
    expect = Expectations()
    try:
        (test_python if args.language == "python" else test_node)(args, expect)
    except Skip as e:
        print("SKIPPED: %s" % e)
        return SKIP
    if expect.failures:
        print("FAIL: %d expectation(s) not met: %s" % (len(expect.failures), "; ".join(expect.failures)))
        return 1
    print("PASS: the %s package certifies its example, and the planted defects fail as they must" % args.language)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

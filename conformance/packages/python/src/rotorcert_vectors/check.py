"""Grading a results file with `rotorcert vectors check` (the same judge as `rotorcert certify`)."""
import json
import os
import shutil
import subprocess
import tempfile

GOOD = ("PASS", "QUALITY_WARNING")


class CheckError(Exception):
    """rotorcert could not be run, or could not grade the file (its exit status 2: a usage error,
    an unreadable or malformed results or vector file)."""


class ClauseResult:
    """One clause of a certificate (report.json of `vectors check --out`)."""

    def __init__(self, entry):
        self.entry = entry
        self.id = entry["id"]
        self.level = entry.get("level")
        self.outcome = entry.get("outcome")
        self.claimed = bool(entry.get("claimed"))
        worst = entry.get("worst") or {}
        self.op, self.input, self.label = worst.get("op"), worst.get("input"), worst.get("label")
        self.error_eps, self.detail = worst.get("error_eps"), worst.get("detail")
        self.conventions = list(entry.get("conventions") or [])
        self.note = entry.get("note") or ""

    def describe(self):
        """One paragraph as the certificate prints it: outcome, error, op [case], input, conventions."""
        head = "%s %s" % (self.id, self.outcome)
        if self.error_eps is not None:
            head += "  %.3g eps" % self.error_eps
        if self.op:
            head += "  %s [%s]" % (self.op, self.label)
        lines = [head]
        if self.input:
            lines.append("    input:  " + self.input)
        if self.detail:
            lines.append("    detail: " + self.detail)
        if self.note:
            lines.append("    note:   " + self.note)
        if self.conventions:
            lines.append("    consistent with convention: " + " ".join(self.conventions))
        return "\n".join(lines)


class Certificate:
    """The outcome of `rotorcert vectors check`: `exit_code` (0 every claimed clause PASS or
    QUALITY_WARNING, 1 otherwise), `output` (the printed certificate), `report` (report.json),
    `report_dir` (report.json, report.md, report.html; None when it was a temporary directory)."""

    def __init__(self, exit_code, output, report, report_dir):
        self.exit_code, self.output, self.report, self.report_dir = exit_code, output, report, report_dir

    @property
    def passed(self):
        return self.exit_code == 0

    def clauses(self):
        impls = (self.report or {}).get("implementations") or []
        return [ClauseResult(c) for impl in impls for c in impl.get("clauses", [])]

    def failed_clauses(self):
        """The claimed clauses that did not pass (FAIL, NOT_SUPPORTED, ...): why the exit status is 1."""
        return [c for c in self.clauses() if c.claimed and c.outcome not in GOOD]

    def claim(self):
        impls = (self.report or {}).get("implementations") or []
        return impls[0].get("claim", "") if impls else ""


def find_rotorcert(rotorcert):
    """The rotorcert executable: a path, or a name looked up on PATH."""
    path = rotorcert if os.sep in rotorcert else shutil.which(rotorcert)
    if not path or not os.path.isfile(path) or not os.access(path, os.X_OK):
        raise CheckError("rotorcert executable not found: %s" % rotorcert)
    return path


def check(results_path, rotorcert="rotorcert", out=None, vectors=None, timeout=600):
    """Runs `rotorcert vectors check RESULTS [--vectors DIR] --out OUT` and returns the Certificate.
    Without `out` the report goes to a temporary directory, read and removed. Raises CheckError
    when rotorcert cannot grade the file (exit 2) or cannot be run."""
    exe = find_rotorcert(os.fspath(rotorcert))
    tmp = None
    if out is None:
        tmp = out = tempfile.mkdtemp(prefix="rotorcert-check-")
    try:
        cmd = [exe, "vectors", "check", os.fspath(results_path), "--out", os.fspath(out)]
        if vectors is not None:
            cmd += ["--vectors", os.fspath(vectors)]
        try:
            proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
        except (OSError, subprocess.TimeoutExpired) as e:
            raise CheckError("%s: %s" % (" ".join(cmd), e)) from e
        output = proc.stdout.decode("utf-8", "replace")
        if proc.returncode not in (0, 1):
            raise CheckError("%s exited with %d:\n%s" % (" ".join(cmd), proc.returncode, output))
        report = None
        try:
            with open(os.path.join(out, "report.json"), encoding="utf-8") as f:
                report = json.load(f)
        except (OSError, ValueError):
            pass
        return Certificate(proc.returncode, output, report, None if tmp else os.fspath(out))
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)

#!/usr/bin/env python3
"""Checks a report directory written by `rotorcert report` (report.json, report.md, report.html).

1. report.json is valid against spec/report.schema.json (python3-jsonschema).
2. report.html, loaded in headless Chromium, runs without console messages or uncaught exceptions,
   its inline script ran to the end (<body data-ready="1">), and its DOM holds what the JSON says:
   the overview matrices, per implementation a section with one certificate row per clause, the
   accuracy table and a chart per op, the mutants section as a table with one row per mutant (and
   as many highlighted rows as mutants not killed); nothing is loaded from outside the page.

Usage: report_browser_check.py REPORT_DIR [--schema FILE] [--chromium EXE] [--timeout S]
Exit: 0 all checks pass; 1 a check failed; 2 usage or unreadable input; 77 Chromium is not
installed (ctest SKIP_RETURN_CODE).
"""

import argparse
import html.parser
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import tempfile

SKIP = 77
SCRIPT_DIR = pathlib.Path(__file__).resolve().parent
DEFAULT_SCHEMA = SCRIPT_DIR / ".." / ".." / "spec" / "report.schema.json"

# Chromium writes page console output (console.log/error, uncaught exceptions, failed loads) to its
# log as "...:INFO:CONSOLE:12] "message", source: ..." (older versions: "CONSOLE(12)").
CONSOLE_LINE = re.compile(r":CONSOLE[:(]\d+")


class Failures:
    def __init__(self):
        self.messages = []

    def check(self, condition, message):
        if not condition:
            self.messages.append(message)
        return condition


def validate_json(report_dir, schema_file, fail):
    try:
        import jsonschema
    except ImportError:
        fail.check(False, "python3-jsonschema is not installed: cannot validate report.json (apt install python3-jsonschema)")
        return None
    try:
        report = json.loads((report_dir / "report.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        fail.check(False, f"report.json cannot be read: {e}")
        return None
    schema = json.loads(schema_file.read_text(encoding="utf-8"))
    validator_class = jsonschema.validators.validator_for(schema)
    validator_class.check_schema(schema)
    errors = sorted(validator_class(schema).iter_errors(report), key=lambda e: list(e.absolute_path))
    for e in errors[:20]:
        path = "/".join(str(p) for p in e.absolute_path) or "(top level)"
        fail.check(False, f"report.json does not match {schema_file.name} at {path}: {e.message[:300]}")
    if len(errors) > 20:
        fail.check(False, f"... and {len(errors) - 20} more schema errors")
    return report


class Dom(html.parser.HTMLParser):
    """What the checks need from the dumped DOM: body attributes, tables by class, and per section
    id the number of <svg> elements, certificate rows and mutant rows (all / not killed) inside it."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.body = {}
        self.tables = []  # class attribute of every <table>
        self.sections = {}  # id -> {"svg": n, "rows": n, "tables": [classes]}
        self.stack = []  # open <section> ids
        self.table_stack = []
        self.external = []  # attributes that would load something from outside the page
        self.styles = []
        self.in_style = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body":
            self.body = a
        if tag == "section":
            self.stack.append(a.get("id", ""))
            self.sections.setdefault(a.get("id", ""), {"svg": 0, "rows": 0, "tables": [], "mutant_rows": 0,
                                                        "not_killed_rows": 0, "render_rows": 0, "img": 0,
                                                        "library_rows": 0, "defect_rows": 0})
        if tag == "table":
            cls = a.get("class", "")
            self.tables.append(cls)
            self.table_stack.append(cls)
            for s in self.stack:
                self.sections[s]["tables"].append(cls)
        if tag == "svg":
            for s in self.stack:
                self.sections[s]["svg"] += 1
        if tag == "tr" and "data-outcome" in a and self.table_stack and "certificate" in self.table_stack[-1].split():
            for s in self.stack:
                self.sections[s]["rows"] += 1
        if tag == "tr" and "data-killed" in a and self.table_stack and "mutants" in self.table_stack[-1].split():
            for s in self.stack:
                self.sections[s]["mutant_rows"] += 1
                if "not-killed" in a.get("class", "").split():
                    self.sections[s]["not_killed_rows"] += 1
        if tag == "tr" and self.table_stack and "render" in self.table_stack[-1].split() and \
                any(c in a.get("class", "").split() for c in ("as-expected", "not-as-expected")):
            for s in self.stack:
                self.sections[s]["render_rows"] += 1
        if tag == "tr" and "data-library" in a and self.table_stack:
            kind = self.table_stack[-1].split()
            for s in self.stack:
                if "third-party" in kind:
                    self.sections[s]["library_rows"] += 1
                if "third-party-defects" in kind:
                    self.sections[s]["defect_rows"] += 1
        if tag == "img":
            for s in self.stack:
                self.sections[s]["img"] += 1
        if tag == "style":
            self.in_style = True
        # An <img> whose every src is a data:image/ URI is embedded (the render section's
        # figures), not loaded from elsewhere; every other such tag or attribute is external.
        embedded = tag == "img" and all((v or "").startswith("data:image/") for n, v in attrs if n == "src") \
            and any(n == "src" for n, _ in attrs)
        if tag in ("img", "iframe", "object", "embed", "link", "audio", "video", "source") and not embedded:
            self.external.append(f"<{tag}>")
        for name, value in attrs:
            value = value or ""
            if name in ("src", "srcset", "data", "poster", "action", "xlink:href"):
                if embedded and name == "src":
                    continue
                self.external.append(f"<{tag} {name}={value!r}>")
            elif name == "href" and not value.startswith("#"):
                self.external.append(f"<{tag} href={value!r}>")
            elif name == "style" and "url(" in value:
                self.external.append(f"<{tag} style={value!r}>")

    def handle_endtag(self, tag):
        if tag == "section" and self.stack:
            self.stack.pop()
        if tag == "table" and self.table_stack:
            self.table_stack.pop()
        if tag == "style":
            self.in_style = False

    def handle_data(self, data):
        if self.in_style:
            self.styles.append(data)


def anchor(cert):
    """The section id the renderer gives a certificate: name-scalar, other characters as '_'."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", f"{cert.get('name', '')}-{cert.get('scalar', '')}")


def find_chromium(explicit):
    if explicit:
        return explicit if shutil.which(explicit) else None
    for name in (os.environ.get("CHROMIUM"), "chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def load_in_browser(exe, page, timeout, fail):
    """Returns (dom, log) of the page in headless Chromium, or (None, log) when it did not load."""
    with tempfile.TemporaryDirectory(prefix="rotorcert-chromium-") as profile:
        cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
               "--enable-logging=stderr", "--v=0", f"--user-data-dir={profile}", "--dump-dom", page.as_uri()]
        # A session of its own, so that a timeout can end Chromium's child processes too.
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
                                env=dict(os.environ, HOME=profile))
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            fail.check(False, f"Chromium did not finish loading {page} within {timeout} s")
            return None, ""
    log = err.decode("utf-8", "replace")
    dom = out.decode("utf-8", "replace")
    if not fail.check(proc.returncode == 0, f"Chromium exited with status {proc.returncode}:\n{log[-3000:]}"):
        return None, log
    if not fail.check("<body" in dom, f"Chromium dumped no page for {page}:\n{log[-3000:]}"):
        return None, log
    return dom, log


def check_page(report, dom_text, log, fail):
    console = [line for line in log.splitlines() if CONSOLE_LINE.search(line) or "Uncaught" in line]
    for line in dict.fromkeys(console):  # Chromium may print a message twice
        fail.check(False, f"console output from the page (the page must log nothing): {line.strip()}")

    dom = Dom()
    dom.feed(dom_text)
    fail.check(dom.body.get("data-ready") == "1",
               "<body data-ready=\"1\"> missing: the page's inline script did not run to its end")
    for e in dom.external:
        fail.check(False, f"the page refers to an external resource: {e}")
    style = "".join(dom.styles)
    fail.check("url(" not in style and "@import" not in style, "the page's CSS loads something (url( or @import)")

    if report is None or report.get("implementations"):  # a bench report certifies nothing: no overview
        fail.check(any("levels-matrix" in t.split() for t in dom.tables), "the overview table of levels is missing")
        fail.check(any("clause-matrix" in t.split() for t in dom.tables), "the overview table of clauses is missing")
    if report is None:
        return
    certs = report.get("implementations", [])
    if any(c.get("accuracy") for c in certs):
        across = dom.sections.get("accuracy-across", {"svg": 0})
        fail.check(across["svg"] >= 1, "the section 'Accuracy across implementations' has no chart")
    for cert in certs:
        sid = anchor(cert)
        label = f"{cert.get('name')} ({cert.get('scalar')})"
        section = dom.sections.get(sid)
        if not fail.check(section is not None, f"{label}: no section with id {sid!r}"):
            continue
        clauses = cert.get("clauses", [])
        if clauses:
            fail.check("certificate" in " ".join(section["tables"]).split(), f"{label}: the certificate table is missing")
            fail.check(section["rows"] == len(clauses),
                       f"{label}: the certificate table has {section['rows']} clause rows, report.json {len(clauses)} clauses")
        accuracy = cert.get("accuracy", [])
        if accuracy:
            fail.check("accuracy" in " ".join(section["tables"]).split(), f"{label}: the accuracy table is missing")
            fail.check(section["svg"] >= len(accuracy),
                       f"{label}: {section['svg']} charts for {len(accuracy)} ops (one histogram per op expected)")
    for name in report.get("sections", {}):
        fail.check(f"section-{name}" in dom.sections, f"report.json section {name!r} is not shown in the page")
    mutants = report.get("sections", {}).get("mutants")
    if isinstance(mutants, dict) and isinstance(mutants.get("mutants"), list):
        section = dom.sections.get("section-mutants")
        if section is not None and fail.check("mutants" in " ".join(section["tables"]).split(),
                                              "the mutants section has no mutants table"):
            listed = mutants["mutants"]
            fail.check(section["mutant_rows"] == len(listed),
                       f"the mutants table has {section['mutant_rows']} rows, report.json {len(listed)} mutants")
            survivors = sum(1 for m in listed if m.get("killed") is not True)
            fail.check(section["not_killed_rows"] == survivors,
                       f"the mutants table highlights {section['not_killed_rows']} rows as not killed, "
                       f"report.json has {survivors} mutants not killed")


    speed = report.get("sections", {}).get("speed")
    if isinstance(speed, dict) and isinstance(speed.get("ops"), list):
        section = dom.sections.get("section-speed")
        if section is not None:
            ops = {r.get("op") for r in speed["ops"] if r.get("n") == 4096}
            frames = {f.get("scene") for f in speed.get("frames", [])}
            ops_with_points = {p.get("op") for p in speed.get("accuracy_vs_speed", [])}
            want = len(ops) + len(frames) + len(ops_with_points)
            fail.check(section["svg"] == want,
                       f"the speed section has {section['svg']} charts, report.json calls for {want} "
                       f"({len(ops)} ops at 4096, {len(frames)} characters, {len(ops_with_points)} accuracy plots)")
    render = report.get("sections", {}).get("render")
    if isinstance(render, dict) and isinstance(render.get("rows"), list):
        section = dom.sections.get("section-render")
        if section is not None:
            fail.check(section["render_rows"] == len(render["rows"]),
                       f"the render table has {section['render_rows']} rows, report.json {len(render['rows'])}")
            figures = render.get("figures", [])
            fail.check(section["img"] == len(figures),
                       f"the render section shows {section['img']} images, report.json has {len(figures)} figures")
    check_third_party(report, dom, fail)


def check_third_party(report, dom, fail):
    """The third-party section shows a row per library and a row per defect of report.json."""
    tp = report.get("sections", {}).get("third_party")
    if not (isinstance(tp, dict) and isinstance(tp.get("libraries"), list)):
        return
    section = dom.sections.get("section-third_party")
    if section is None:
        return
    libs = tp["libraries"]
    defects = sum(len(l.get("defects", [])) for l in libs)
    fail.check(section["library_rows"] == len(libs),
               f"the third-party table has {section['library_rows']} rows, report.json {len(libs)} libraries")
    fail.check(section["defect_rows"] == defects,
               f"the third-party section shows {section['defect_rows']} defects, report.json has {defects}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report_dir", type=pathlib.Path)
    parser.add_argument("--schema", type=pathlib.Path, default=DEFAULT_SCHEMA, help="default: %(default)s")
    parser.add_argument("--chromium", help="the browser executable (default: $CHROMIUM, chromium, chromium-browser, google-chrome)")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds Chromium may take (default: %(default)s)")
    args = parser.parse_args()

    report_dir = args.report_dir.resolve()
    for f in ("report.json", "report.html"):
        if not (report_dir / f).is_file():
            print(f"report_browser_check: {report_dir / f} does not exist", file=sys.stderr)
            return 2
    if not args.schema.is_file():
        print(f"report_browser_check: schema {args.schema} does not exist (use --schema)", file=sys.stderr)
        return 2

    fail = Failures()
    report = validate_json(report_dir, args.schema.resolve(), fail)
    md = report_dir / "report.md"
    fail.check(md.is_file() and md.stat().st_size > 0, f"{md} is missing or empty")

    exe = find_chromium(args.chromium)
    if exe is None:
        for m in fail.messages:
            print(f"FAIL: {m}", file=sys.stderr)
        print("report_browser_check: SKIPPED the browser check: Chromium is not installed "
              "(apt install chromium, or pass --chromium / set $CHROMIUM)", file=sys.stderr)
        return 1 if fail.messages else SKIP

    dom, log = load_in_browser(exe, report_dir / "report.html", args.timeout, fail)
    if dom is not None:
        check_page(report, dom, log, fail)

    if fail.messages:
        for m in fail.messages:
            print(f"FAIL: {m}", file=sys.stderr)
        print(f"report_browser_check: {len(fail.messages)} problem(s) in {report_dir}", file=sys.stderr)
        return 1
    certs = report.get("implementations", []) if report else []
    print(f"report_browser_check: OK: {report_dir}: report.json valid, report.html loads in {pathlib.Path(exe).name} "
          f"without console output, {len(certs)} implementation sections complete")
    return 0


if __name__ == "__main__":
    sys.exit(main())

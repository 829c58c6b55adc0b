#!/usr/bin/env python3
"""The ctest check of one third-party adapter: certify the library, then hold it to its known defects.

    check_adapter.py --rotorcert BIN --adapter NAME --out DIR [--env ENV] [rotorcert options...]

Runs `rotorcert thirdparty --adapter NAME --out DIR` (REPORT-3) and reads DIR/report.json:
  - certified: passes when the library is as expected -- exactly the clauses of its
    expected_failures.json FAIL, every other claimed clause passes (or is NOT_SUPPORTED) -- and
    every defect states its worst input and error and has a reproducer file; prints the
    certificate's defects either way;
  - not run because its registry package could not be installed or its Rust crate could not be
    built (scripts/setup-adapters recorded the failure in ENV/NAME/status.json: no cargo, no
    network, ...): exit 77, a skip, with the installer's reason;
  - anything else (not run for another reason, the adapter failed, not as expected): exit 1.
"""
import argparse
import json
import os
import subprocess
import sys

SKIP = 77


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--rotorcert", required=True)
    p.add_argument("--adapter", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--env", help="the adapters' environments (default: rotorcert's)")
    args, extra = p.parse_known_args(argv)

    cmd = [args.rotorcert, "thirdparty", "--adapter", args.adapter, "--out", args.out, "--quiet"] + extra
    if args.env:
        cmd += ["--adapters-env", args.env]
    print("$ " + " ".join(cmd), flush=True)
    rc = subprocess.run(cmd).returncode
    report_file = os.path.join(args.out, "report.json")
    if rc == 2 or not os.path.isfile(report_file):
        print("FAIL: rotorcert thirdparty exited with %d and wrote no report" % rc)
        return 1
    with open(report_file) as f:
        report = json.load(f)
    libs = report["sections"]["third_party"]["libraries"]
    if len(libs) != 1 or libs[0]["name"] != args.adapter:
        print("FAIL: the report names %s, not the adapter %s" % ([l["name"] for l in libs], args.adapter))
        return 1
    lib = libs[0]

    if lib["status"] == "not run":
        env_dir = args.env or report["sections"]["third_party"]["environments"]
        status_file = os.path.join(env_dir, args.adapter, "status.json")
        # The adapters scripts/setup-adapters installs: every vectors adapter, and the Rust plugins
        # it builds with cargo (thirdparty::Manifest::uses_environment).
        uses_env = lib["route"] == "vectors" or lib.get("language") == "rust"
        if uses_env and os.path.isfile(status_file):
            with open(status_file) as f:
                status = json.load(f)
            if not status.get("installed") and status.get("reason"):
                print("SKIPPED: %s could not be installed from %s: %s" % (status["package"]["name"],
                                                                       status["package"]["registry"], status["reason"]))
                return SKIP
        print("FAIL: %s was not run: %s" % (args.adapter, lib["reason"]))
        return 1
    if lib["status"] != "certified":
        print("FAIL: %s: %s" % (lib["status"], lib["reason"]))
        return 1

    # Listed defects marked "intermittent" (the library reads uninitialised memory): FAIL or not.
    listed_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), args.adapter, "expected_failures.json")
    intermittent = set()
    if os.path.isfile(listed_file):
        with open(listed_file) as f:
            intermittent = {(e["scalar"], e["clause"]) for e in json.load(f)["failures"] if e.get("intermittent")}
    failures = []
    for cert in lib["certificates"]:
        print("%s (%s): %s" % (cert["name"], cert["scalar"], cert["claim"]))
        for c in cert["clauses"]:
            if not c["claimed"] or c["outcome"] == "NOT_SUPPORTED":
                continue
            listed = c["expected_failure"] is not None
            ok = c["outcome"] == "FAIL" if listed else c["outcome"] in ("PASS", "QUALITY_WARNING")
            if listed and (cert["scalar"], c["id"]) in intermittent:
                ok = c["outcome"] in ("FAIL", "PASS", "QUALITY_WARNING")
            worst = c.get("worst") or {}
            print("  %-10s %-16s %s%s" % (c["id"], c["outcome"], "known defect " if listed else "",
                                          "" if ok else "<- NOT AS EXPECTED"))
            if not ok:
                failures.append("%s %s: %s (%s), worst input %s, error %s eps" % (
                    cert["scalar"], c["id"], c["outcome"], "listed as a known defect" if listed else "not listed",
                    worst.get("input"), worst.get("error_eps")))
    for d in lib["defects"]:
        worst = d.get("worst") or {}
        if not worst.get("input") or "error_eps" not in worst:
            failures.append("defect %s %s states no worst input or error" % (d["scalar"], d["clause"]))
        # REPORT-3: every defect has a reproducer in the library's own language; the
        # ctest reproducer_<adapter>_<file> runs it against the unmodified library.
        rep = d.get("reproducer")
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        if not rep or not os.path.isfile(os.path.join(root, rep.get("file", ""))):
            failures.append("defect %s %s has no reproducer in conformance/adapters/%s/reproducers/" %
                            (d["scalar"], d["clause"], args.adapter))
    if lib["as_expected"] is not True:
        failures.append("the section says the library is not as expected")
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print("%s: as expected, %d known defect(s); reproduce with: %s" % (args.adapter, len(lib["defects"]), lib["reproduce"]))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""rotorcert thirdparty --speed: every native (C-ABI) library certified in the run is timed beside
glm_quat in one benchmark run, and its section row carries ns per element and the ratio to
glm_quat per op (REPORT-3's speed column). Usage: thirdparty_speed.py ROTORCERT BENCH PLUGINS OUT"""
import json
import os
import subprocess
import sys

rotorcert, bench, plugins, out = sys.argv[1:5]
adapters = ["glm"]
if os.path.exists(os.path.join(plugins, "rotorcert_adapter_cqrlib.so")):
    adapters.append("cqrlib")  # a plugin: loaded by rotorcert_bench --plugin
cmd = [rotorcert, "thirdparty", "--speed", "--bench-binary", bench, "--plugins", plugins, "--out", out,
       "--clause", "NORM-1", "--cases", "4", "--search", "0", "-q"]
for a in adapters:
    cmd += ["--adapter", a]
run = subprocess.run(cmd, capture_output=True, text=True)
if run.returncode not in (0, 1):
    sys.exit("thirdparty --speed exited %d:\n%s%s" % (run.returncode, run.stdout, run.stderr))
section = json.load(open(os.path.join(out, "report.json")))["sections"]["third_party"]
speed = section.get("speed", {})
problems = []
if speed.get("baseline") != "glm_quat" or speed.get("elements") != 4096:
    problems.append("section.speed does not say how it measured: %r" % speed)
for lib in section["libraries"]:
    if lib["name"] not in adapters:
        continue
    tables = lib.get("speed", [])
    if not tables:
        problems.append("%s: no speed" % lib["name"])
    for t in tables:
        for o in t["ops"]:
            if not o.get("ns_per_element", 0) > 0 or not o.get("ratio", 0) > 0:
                problems.append("%s %s %s: %r" % (lib["name"], t["scalar"], o["op"], o))
        if lib["name"] == "glm" and abs(t.get("median_ratio", 0) - 1) > 1e-12:
            problems.append("glm against itself: median ratio %r, not 1" % t.get("median_ratio"))
md = open(os.path.join(out, "report.md")).read()
if "| speed |" not in md or "Speed: ns per element" not in md:
    problems.append("report.md has no speed column or note")
if problems:
    sys.exit("\n".join(problems))
print("PASS: %s timed against glm_quat" % ", ".join(adapters))

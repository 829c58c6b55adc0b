#!/usr/bin/env python3
"""Every adapter's pin is stated once for people (adapter.json "package".version, shown in the
report) and once for its registry's installer (requirements.txt, package.json and its lock,
Cargo.toml and Cargo.lock): the two must name the same version, or the report would certify one
release and print another. Usage: check_pins.py ADAPTERS_DIR. Exit 0 when every pin agrees."""
import json
import os
import re
import sys


def norm(name):
    return re.sub(r"[-_.]+", "-", name).lower()


def pins_of(d, m):
    """(file, version) pairs the installer reads for the library itself."""
    pkg, lang = m["package"]["name"], m.get("language")
    found = []
    if lang == "python":
        with open(os.path.join(d, "requirements.txt")) as f:
            for line in f:
                req = line.split("#")[0].strip()
                if "==" in req and norm(req.split("==")[0]) == norm(pkg):
                    found.append(("requirements.txt", req.split("==")[1].strip()))
    elif lang == "node":
        with open(os.path.join(d, "package.json")) as f:
            found.append(("package.json", json.load(f).get("dependencies", {}).get(pkg)))
        with open(os.path.join(d, "package-lock.json")) as f:
            lock = json.load(f)
        found.append(("package-lock.json", lock.get("packages", {}).get("node_modules/" + pkg, {}).get("version")))
    elif lang == "rust":
        with open(os.path.join(d, "Cargo.toml")) as f:
            mm = re.search(r'^%s\s*=\s*(?:\{[^}]*version\s*=\s*)?"=?([^"]+)"' % re.escape(pkg), f.read(), re.M)
        found.append(("Cargo.toml", mm.group(1) if mm else None))
        with open(os.path.join(d, "Cargo.lock")) as f:
            mm = re.search(r'\[\[package\]\]\nname = "%s"\nversion = "([^"]+)"' % re.escape(pkg), f.read())
        found.append(("Cargo.lock", mm.group(1) if mm else None))
    return found


def main(adapters):
    problems, checked = [], 0
    for name in sorted(os.listdir(adapters)):
        manifest = os.path.join(adapters, name, "adapter.json")
        if not os.path.isfile(manifest):
            continue
        with open(manifest) as f:
            m = json.load(f)
        want = m["package"]["version"]
        for file, got in pins_of(os.path.join(adapters, name), m):
            checked += 1
            if got != want:
                problems.append("%s: adapter.json pins %s %s, %s says %r" % (name, m["package"]["name"], want, file, got))
    for p in problems:
        print("FAIL: " + p)
    print("%d pin file(s) checked, %d disagree" % (checked, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))))

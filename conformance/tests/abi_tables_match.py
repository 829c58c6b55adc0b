#!/usr/bin/env python3
"""The vectors packages' op tables agree with the op list (impls/include/rotorcert/abi_op_list.h).

`rotorcert list --ops --json` prints the ABI's operations as the tool knows them (the op list with
the engine's array layouts). The Python package (rotorcert_vectors/abi.py) and the Node.js package
(lib/abi.js) each keep their own table of every op's output arrays, so that they run without the
tool; this check fails when an op is added, renamed or re-laid-out in one place and not the others.

usage: abi_tables_match.py ROTORCERT SOURCE_DIR   (exit 77, a skip, where node is not installed)
"""
import json
import shutil
import subprocess
import sys


def main():
    rotorcert, source = sys.argv[1], sys.argv[2]
    listed = json.loads(subprocess.run([rotorcert, "list", "--ops", "--json"], check=True,
                                       capture_output=True, text=True).stdout)
    want = {op["name"]: [[a["name"], a["stride"]] for a in op["outputs"]] for op in listed["ops"]}
    order = [op["name"] for op in listed["ops"]]

    sys.path.insert(0, source + "/conformance/packages/python/src")
    from rotorcert_vectors import abi  # noqa: E402 (the package as it is in the tree)
    tables = {"python rotorcert_vectors/abi.py": (list(abi.ABI_OPS),
                                                  {k: [list(x) for x in v] for k, v in abi.OUTPUTS.items()})}
    node = shutil.which("node")
    if node is not None:
        script = ("const a = require(process.argv[1]);"
                  "console.log(JSON.stringify({ops: a.ABI_OPS, outputs: a.OUTPUTS}));")
        got = json.loads(subprocess.run([node, "-e", script, source + "/conformance/packages/node/lib/abi.js"],
                                        check=True, capture_output=True, text=True).stdout)
        tables["node lib/abi.js"] = (got["ops"], got["outputs"])

    bad = []
    for where, (ops, outputs) in tables.items():
        if ops != order:
            bad.append("%s: ABI_OPS %s, the op list %s" % (where, ops, order))
        for name in order:
            if outputs.get(name) != want[name]:
                bad.append("%s: %s writes %s, the op list says %s" % (where, name, outputs.get(name), want[name]))
    for line in bad:
        print("MISMATCH " + line)
    print("%d ops, %d tables checked: %s" % (len(order), len(tables), "mismatch" if bad else "all agree"))
    if node is None:
        print("node not installed: lib/abi.js not checked")
        return 1 if bad else 77
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env bash
# The Debian package of the tool (cmake/RotorcertInstall.cmake): build it with cpack, check what
# it holds, unpack it into an empty root and run the main job, `rotorcert report`, from there.
# The unpacked tool must read its spec, known defects and mutants from the package
# (report.json run.data_dir), never from the source tree, and give the same verdicts.
#   debian_package.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1 work=$2
command -v dpkg-deb >/dev/null || { echo "SKIP: dpkg-deb is not installed"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/rotorcert_*_*.deb)
dpkg-deb --info "$deb" >"$work/info.txt"
dpkg-deb --contents "$deb" >"$work/contents.txt"
for f in ./usr/bin/rotorcert ./usr/libexec/rotorcert/rotorcert_bench ./usr/share/rotorcert/spec/clauses.json \
         ./usr/share/rotorcert/mutants/mutants.json ./usr/share/rotorcert/impls/glm_quat/expected_failures.json \
         ./usr/include/rotorcert/impl_abi.h ./usr/lib/cmake/rotorcert/rotorcertConfig.cmake \
         ./usr/lib/cmake/rotorcert/RotorcertCertification.cmake; do
  grep -q " $f\$" "$work/contents.txt" || { echo "FAIL: the package lacks $f"; exit 1; }
done
grep -q '^ Depends: .*libmpfr' "$work/info.txt" || { echo "FAIL: the package does not depend on MPFR:"; cat "$work/info.txt"; exit 1; }

root=$work/root
dpkg-deb -x "$deb" "$root"
"$root/usr/bin/rotorcert" report --out "$work/report" --cases 4 --no-bench --no-third-party --render-frames 1 -q -j 2
python3 - "$work/report/report.json" "$root/usr/share/rotorcert" "$(basename "$deb")" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
assert report["run"]["data_dir"] == sys.argv[2], "read its files from %s, not the package" % report["run"]["data_dir"]
summary = report["summary"]
assert summary["as_expected"] and summary["exit_code"] == 0, summary
assert summary["mutants_total"] >= 30 and summary["mutants_killed"] == summary["mutants_total"], summary
print("package %s: report from the unpacked root, %d tables as expected, %d/%d mutants killed" %
      (sys.argv[3], summary["tables"], summary["mutants_killed"], summary["mutants_total"]))
PY

#!/usr/bin/env bash
# A library maintainer's view of rotorcert (README "Use it from your own project"): install the
# build into a scratch prefix, build conformance/tests/external_project against the installed
# package (find_package(rotorcert), rotorcert_add_certification()), and run its ctest twice:
# as is, it must pass; with a planted defect (compose reversed), it must fail and name COMPOSE-1.
# Then a copy of the prefix runs the main job with the checkout (and the build tree in it) hidden
# behind an empty mount: nothing the installed tool reads at run time may come from there.
#   install_consumer.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
# The installed tool reads its own files, never the source tree (data_layout.hpp).
"$prefix/bin/rotorcert" certify --help >/dev/null

configure_and_test() {  # NAME EXTRA_CMAKE_ARGS...
  local name=$1
  shift
  cmake -S "$source/conformance/tests/external_project" -B "$work/$name" -G Ninja \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DMY_ROTATIONS_SOURCE="$source/impls/rotor_m2/rotor_m2.cpp" "$@" >"$work/$name.configure.log"
  cmake --build "$work/$name" >"$work/$name.build.log"
  ctest --test-dir "$work/$name" --output-on-failure >"$work/$name.ctest.log" 2>&1
}

if ! configure_and_test correct; then
  echo "FAIL: the correct library's certification failed"
  cat "$work/correct.ctest.log"
  exit 1
fi
grep -q "my_rotations_certified .*Passed" "$work/correct.ctest.log"
report=$work/correct/rotorcert/my_rotations_certified/report.json
grep -q "\"data_dir\": \"$prefix/share/rotorcert\"" "$report" || { echo "FAIL: the installed tool did not read $prefix/share/rotorcert"; exit 1; }
echo "correct library: certified, Core, Interp and Blend met"

if configure_and_test planted -DMY_ROTATIONS_PLANTED_DEFECT=ON; then
  echo "FAIL: the certification passed a library that composes in the wrong order"
  cat "$work/planted.ctest.log"
  exit 1
fi
if ! grep -q "required level Core not met; not passing:.*COMPOSE-1" "$work/planted.ctest.log"; then
  echo "FAIL: the planted defect failed the test, but not on COMPOSE-1:"
  cat "$work/planted.ctest.log"
  exit 1
fi
echo "planted defect: certification failed on COMPOSE-1, as it must"

# The checkout moved away: a copy of the prefix outside it, the checkout hidden in a private
# mount namespace (root, or a user namespace); strace's list of opened files where neither works.
moved=$(mktemp -d /tmp/rotorcert-moved-prefix.XXXXXX)
trap 'rm -rf "$moved"' EXIT
cp -a "$prefix" "$moved/prefix"
checkout=$(cd "$source" && pwd -P)
job=("$moved/prefix/bin/rotorcert" report --out "$moved/report" --cases 4 --no-bench --no-third-party --render-frames 1 -q -j 2)
if unshare -m --propagation private true 2>/dev/null; then
  unshare -m --propagation private sh -c 'mount -t tmpfs none "$0" && exec "$@"' "$checkout" "${job[@]}"
  how="with $checkout hidden (mount namespace)"
elif unshare -rm --propagation private true 2>/dev/null; then
  unshare -rm --propagation private sh -c 'mount -t tmpfs none "$0" && exec "$@"' "$checkout" "${job[@]}"
  how="with $checkout hidden (user and mount namespace)"
elif command -v strace >/dev/null; then
  strace -f -qq -e trace=open,openat,execve -o "$moved/files.txt" "${job[@]}"
  if grep -v ENOENT "$moved/files.txt" | grep -q "\"$checkout/"; then
    echo "FAIL: the installed tool opened files in the checkout:"
    grep -v ENOENT "$moved/files.txt" | grep "\"$checkout/" | head
    exit 1
  fi
  how="opening nothing in $checkout (strace)"
else
  echo "SKIP: neither unshare nor strace can show that the checkout is not read"
  exit 77
fi
python3 - "$moved/report/report.json" "$moved/prefix/share/rotorcert" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
assert report["run"]["data_dir"] == sys.argv[2], "the moved tool read %s" % report["run"]["data_dir"]
assert report["summary"]["as_expected"] and report["summary"]["exit_code"] == 0, report["summary"]
PY
echo "installed tool copied to $moved/prefix: the main job ran $how, as expected"

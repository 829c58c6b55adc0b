#!/usr/bin/env bash
# A library maintainer's view of rotorcert (README "Certify your library from CMake"): install the
# build into a scratch prefix, build conformance/tests/external_project against the installed
# package (find_package(rotorcert), rotorcert_add_certification()), and run its ctest twice:
# as is, it must pass; with a planted defect (compose reversed), it must fail and name COMPOSE-1.
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

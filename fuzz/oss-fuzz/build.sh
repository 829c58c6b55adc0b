#!/bin/bash -eu
# OSS-Fuzz / ClusterFuzzLite build of the rotorcert harnesses (fuzz/README.md). Runs inside the
# base-builder image with $SRC/rotorcert the repository; uses $CC $CXX $CFLAGS $CXXFLAGS
# (sanitizer and coverage flags chosen by the infrastructure) and $LIB_FUZZING_ENGINE, and writes
# the fuzzers with their seed corpora (<harness>_seed_corpus.zip) to $OUT. Downloads nothing.
cd "$SRC/rotorcert"

# libstdc++, as in the project's own builds: the system libraries linked in (Highway, MPFR's C++
# wrapper) are built against it. MPFR and GMP are linked statically: the runner image has no
# libmpfr/libgmp.
CXXFLAGS="${CXXFLAGS//-stdlib=libc++/}"
# Coverage feedback from the code under test only, as in the fuzz presets
# (fuzz/coverage_ignorelist.txt: the oracle stays uninstrumented, still sanitized). The coverage
# build (source-based profiles, no SanitizerCoverage) takes no ignore list.
if [ "${SANITIZER:-}" != coverage ]; then
  CFLAGS="$CFLAGS -fsanitize-coverage-ignorelist=$SRC/rotorcert/fuzz/coverage_ignorelist.txt"
  CXXFLAGS="$CXXFLAGS -fsanitize-coverage-ignorelist=$SRC/rotorcert/fuzz/coverage_ignorelist.txt"
fi
build=/work/rotorcert-build
cmake -S . -B "$build" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_C_FLAGS="$CFLAGS" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DROTORCERT_FUZZ=ON -DROTORCERT_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DROTORCERT_FUZZ_STATIC_DEPS=ON
cmake --build "$build" --target fuzz_all -j"$(nproc)"

for f in "$build"/fuzz/fuzz_*; do
  [ -x "$f" ] && [ -f "$f" ] || continue
  name=$(basename "$f")
  cp "$f" "$OUT/$name"
  harness=${name#fuzz_}
  if [ -d "fuzz/corpus/$harness" ]; then
    (cd "fuzz/corpus/$harness" && zip -q -r "$OUT/${name}_seed_corpus.zip" .)
  fi
  # Every seed of an operation harness is one batch; larger inputs only add elements.
  printf '[libfuzzer]\nmax_len = 65536\ntimeout = 60\nrss_limit_mb = 4096\n' > "$OUT/$name.options"
done

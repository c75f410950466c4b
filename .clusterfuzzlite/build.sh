#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz build script. Compiles every harness with $CC,
# $CXX, $CFLAGS and $CXXFLAGS (which carry the sanitizer and coverage flags of
# the build being made), links it with $LIB_FUZZING_ENGINE, and puts into $OUT
# each <name>_fuzzer with <name>_fuzzer_seed_corpus.zip (corpus/<name>/,
# regressions and grown/ included), <name>_fuzzer.dict (fuzz/<name>.dict) and
# <name>_fuzzer.options (fuzz/<name>.options).
# Runs in the repository root (the Dockerfile's WORKDIR) unless DCEL_SRC says
# otherwise; builds in $WORK.
# Outside the image (docs/fuzzing.md), $OUT may not exist yet: it is made.
src=${DCEL_SRC:-$PWD}
build=${WORK:-/tmp}/dcel-fuzz-build
: "${OUT:?OUT must name the folder for the fuzzers (made if missing)}"
mkdir -p "$OUT"

# CMAKE_BUILD_TYPE=None adds no flags of its own: $CFLAGS/$CXXFLAGS are all.
cmake -S "$src" -B "$build" -G Ninja \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_C_FLAGS="$CFLAGS" -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DCMAKE_BUILD_TYPE=None \
  -DDCEL_FUZZ_ONLY=ON -DDCEL_BUILD_CLI=OFF \
  -DDCEL_FUZZ_ENGINE=external -DDCEL_FUZZ_LDFLAGS="$LIB_FUZZING_ENGINE"
cmake --build "$build" --target all_fuzzers -j"$(nproc)"

for bin in "$build"/bin/*_fuzzer; do
  target=$(basename "$bin")
  name=${target%_fuzzer}
  cp "$bin" "$OUT/"
  rm -f "$OUT/${target}_seed_corpus.zip"
  # Seeds, regressions and the committed minimised corpus (grown/).
  (cd "$src/corpus/$name" && find . -type f -print | zip -q -j "$OUT/${target}_seed_corpus.zip" -@)
  if [ -f "$src/fuzz/$name.dict" ]; then cp "$src/fuzz/$name.dict" "$OUT/$target.dict"; fi
  if [ -f "$src/fuzz/$name.options" ]; then cp "$src/fuzz/$name.options" "$OUT/$target.options"; fi
done

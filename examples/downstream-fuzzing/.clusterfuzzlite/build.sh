#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz build script, run in the build image with $CC,
# $CXX, $CFLAGS, $CXXFLAGS (the sanitizer and coverage flags of the build being
# made), $LIB_FUZZING_ENGINE, $WORK and $OUT set:
#   1. dcel from source (DCEL_SRC, default third_party/dcel, e.g. a git
#      submodule), built with the same flags so that its code is instrumented
#      too, and installed into $WORK/dcel-prefix; or an installed dcel at
#      DCEL_PREFIX, used as it is;
#   2. this project's harnesses, copied into $OUT.
# Runs in the project's root (the Dockerfile's WORKDIR), or in PROJECT_SRC.
# Locally, from the project's root, the OSS-Fuzz way (libFuzzer, ASan, UBSan):
#   CC=clang-14 CXX=clang++-14 CXXFLAGS="-O1 -g -fsanitize=address,undefined,fuzzer-no-link" \
#   LIB_FUZZING_ENGINE=-fsanitize=fuzzer WORK=/tmp/work OUT=/tmp/out DCEL_SRC=path/to/dcel \
#   .clusterfuzzlite/build.sh
here=$(cd "${PROJECT_SRC:-$PWD}" && pwd)
mkdir -p "$WORK" "$OUT"
WORK=$(cd "$WORK" && pwd)  # relative paths (a local run) made absolute for CMake
OUT=$(cd "$OUT" && pwd)
if [ -z "${DCEL_PREFIX:-}" ]; then
  DCEL_PREFIX=$WORK/dcel-prefix
  # CMAKE_BUILD_TYPE=None adds no flags of its own: $CXXFLAGS are all.
  cmake -S "$(cd "${DCEL_SRC:-$here/third_party/dcel}" && pwd)" -B "$WORK/dcel-build" -G Ninja \
    -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DCMAKE_BUILD_TYPE=None \
    -DDCEL_DEVELOPER_MODE=OFF -DDCEL_BUILD_CLI=OFF
  cmake --build "$WORK/dcel-build"
  cmake --install "$WORK/dcel-build" --prefix "$DCEL_PREFIX"
fi
cmake -S "$here" -B "$WORK/my-build" -G Ninja \
  -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_PREFIX_PATH="$DCEL_PREFIX" -DLIB_FUZZING_ENGINE="${LIB_FUZZING_ENGINE:-}"
cmake --build "$WORK/my-build"
cp "$WORK/my-build/faces_fuzzer" "$OUT/"

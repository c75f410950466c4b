#!/bin/sh
# ctest package.pkg_config: compiles tiny.cpp against an installed dcel with
# nothing but the compiler and `pkg-config --cflags --libs dcel`, then runs it.
#   run.sh PREFIX CXX OUTDIR [EXTRA_FLAGS]   (EXTRA_FLAGS: the build's
#   sanitizer/coverage flags, which an instrumented library needs at link time)
set -eu
prefix=$1 cxx=$2 out=$3 extra=${4:-}
pc=$(find "$prefix" -name dcel.pc -path '*/pkgconfig/*' | head -n 1)
[ -n "$pc" ] || { echo "pkg_config: no dcel.pc under $prefix" >&2; exit 1; }
PKG_CONFIG_PATH=$(dirname "$pc")
export PKG_CONFIG_PATH
flags=$(pkg-config --cflags --libs dcel)
echo "pkg-config --cflags --libs dcel: $flags"
mkdir -p "$out"
# shellcheck disable=SC2086 # the flags are words
"$cxx" -std=c++20 $extra "$(dirname "$0")/tiny.cpp" $flags -o "$out/tiny"
"$out/tiny"

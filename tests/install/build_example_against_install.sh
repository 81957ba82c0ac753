#!/usr/bin/env bash
# Install test: installs Signorini into a scratch prefix, builds examples/library-usage
# against the exported CMake package, and runs it on 2 MPI ranks.
set -euo pipefail
source_dir=$1
build_dir=$2
work=$build_dir/install-test
rm -rf "$work"
cmake --install "$build_dir" --prefix "$work/prefix" > "$work.log" 2>&1 || { cat "$work.log"; exit 1; }
cmake -S "$source_dir/examples/library-usage" -B "$work/example" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/example" -j 2
mpiexec -np 2 "$work/example/hertz_strip"

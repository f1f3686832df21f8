#!/bin/sh
# Build the Ceres benchmark (scripts/ceres_bench/bench.cc) into target/ceres_bench/bench.
# Needs Debian's libceres-dev (apt-get install -y libceres-dev: Ceres 2.1 with SuiteSparse,
# glog, gflags, Eigen 3). A development tool: no crate depends on it.
# The compiler runs under flock /tmp/cargo.lock, so that it never runs beside a cargo build.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out="$here/../../target/ceres_bench"
mkdir -p "$out"
flock /tmp/cargo.lock g++ -std=c++17 -O3 -march=native -DNDEBUG \
    -I/usr/include/eigen3 \
    "$here/bench.cc" -o "$out/bench" \
    -lceres -lglog -lgflags -lpthread
echo "built $(cd "$out" && pwd)/bench"

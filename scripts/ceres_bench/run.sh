#!/bin/sh
# orthocheck's bundle adjustment beside Ceres on the same problems (docs/limits.md, "Bundle
# adjustment's cost"): builds the C++ benchmark, writes the problems, times orthocheck's
# adjustment and every Ceres configuration, REPEAT (default 5) runs each, medians.
#
#   scripts/ceres_bench/run.sh [OUTDIR]        (default /tmp/ceres_bench)
#
# Problems: dense_250x200 (250 points in 200 frames, 1 % noise, the Tomasi–Kanade start),
# turntable_500x36w5 (synth --turntable --points 500 --frames 36 --window 5 --noise 0.001
# --seed 1) and tt100k (scripts/cli_limits.py's turntable of 100,000 points each in 2 of 100
# frames, 0.2 % noise: the largest turntable the project runs, at BUNDLE_OBSERVATIONS), the
# turntables from the pipeline's own start (variable projection from the chained pairs).
# Every build and every timed run holds /tmp/cargo.lock, so no other build on this shared
# machine runs beside it.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${1:-/tmp/ceres_bench}
repeat=${REPEAT:-5}
problems=${PROBLEMS:-dense_250x200 turntable_500x36w5 tt100k}
mkdir -p "$out/problems"

"$here/build.sh"

if [ ! -f "$out/tt100k.csv" ]; then
    python3 -c "import sys; sys.path.insert(0, '$root/scripts'); import cli_limits; cli_limits.turntable('$out', 'tt100k.csv', 100_000, 100, 2)"
fi

cd "$root"
flock /tmp/cargo.lock cargo run --release -p orthocheck-benches --example ceres_export -- \
    "$out/problems" --repeat "$repeat" --csv tt100k "$out/tt100k.csv" | tee "$out/orthocheck.txt"

lscpu | grep 'Model name' | tee "$out/machine.txt"
for p in $problems; do
    flock /tmp/cargo.lock "$root/target/ceres_bench/bench" "$out/problems/$p.txt" \
        --repeat "$repeat" --solver sparse,dense --threads 1,2 --rot quat,matrix \
        --tol tight,default | tee "$out/ceres_$p.txt"
done

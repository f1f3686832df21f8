#!/bin/sh
# orthocheck's bundle adjustment beside Ceres on the same problems (docs/architecture.md,
# "Bundle adjustment beside Ceres"): builds the C++ benchmark, writes the problems, times orthocheck's
# adjustment and every Ceres configuration, REPEAT (default 5) runs each, medians.
#
#   scripts/ceres_bench/run.sh [OUTDIR]        (default /tmp/ceres_bench)
#
# Problems: dense_250x200 (250 points in 200 frames, 1 % noise, the Tomasi–Kanade start),
# turntable_500x36w5 (synth --turntable --points 500 --frames 36 --window 5 --noise 0.001
# --seed 1), family_largest (the turntable family's scene with the most observations, seed 1,
# benches/turntable_family.rs) and tt100k (scripts/cli_limits.py's turntable of 100,000
# points each in 2 of 100 frames, 0.2 % noise: the largest turntable the project runs, at
# BUNDLE_OBSERVATIONS), the turntables from the pipeline's own start (variable projection
# from the chained pairs).
# PROBLEMS="…" picks some; REACH_TT100K="C1,C2" also times how long orthocheck takes to
# bring tt100k's cost down to each Cᵢ (e.g. Ceres' final costs, which it reaches only after
# far more than the pipeline's 200 iterations); SKIP_CERES=1 times orthocheck only.
#
# Configurations of Ceres (bench.cc): SPARSE_SCHUR and DENSE_SCHUR, 1 and 2 threads, the
# rotation a quaternion (QuaternionManifold) or orthocheck's R·exp([δ]×), tolerances at
# rounding (4ε, orthocheck's stopping rule), and Ceres' default tolerances (quaternion).
# Every build and every timed run holds /tmp/cargo.lock (released between configurations),
# so no other build on this shared machine runs beside a timing.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${1:-/tmp/ceres_bench}
repeat=${REPEAT:-5}
problems=${PROBLEMS:-dense_250x200 turntable_500x36w5 family_largest tt100k}
mkdir -p "$out/problems"

"$here/build.sh"

if [ ! -f "$out/tt100k.csv" ]; then
    python3 -c "import sys; sys.path.insert(0, '$root/scripts'); import cli_limits; cli_limits.turntable('$out', 'tt100k.csv', 100_000, 100, 2)"
fi

cd "$root"
lscpu | grep 'Model name' | tee "$out/machine.txt"
flock /tmp/cargo.lock cargo build --release -p orthocheck-benches --example ceres_export
for p in $problems; do
    case $p in
        tt100k) extra="--csv tt100k $out/tt100k.csv ${REACH_TT100K:+--reach $REACH_TT100K}" ;;
        *) extra="" ;;
    esac
    # shellcheck disable=SC2086
    flock /tmp/cargo.lock target/release/examples/ceres_export "$out/problems" \
        --repeat "$repeat" --only "$p" $extra | tee "$out/orthocheck_$p.txt"
done

[ -n "${SKIP_CERES:-}" ] && exit 0
for p in $problems; do
    : > "$out/ceres_$p.txt"
    for config in "quat tight" "matrix tight" "quat default"; do
        set -- $config
        for solver in sparse dense; do
            for threads in 1 2; do
                flock /tmp/cargo.lock "$root/target/ceres_bench/bench" "$out/problems/$p.txt" \
                    --repeat "$repeat" --solver "$solver" --threads "$threads" --rot "$1" \
                    --tol "$2" | tee -a "$out/ceres_$p.txt"
            done
        done
    done
done

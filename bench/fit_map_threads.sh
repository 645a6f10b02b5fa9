#!/bin/sh
# `mdr fit --map` on threads: a synthetic JPK map of N curves (scripts/make_instrument_test_files.py map N: the
# vendor map's pixel 109 copied N times on a ceil(sqrt(N))^2 grid) fitted with examples/fit/jpk-map-hertz.toml at
# each --jobs given; prints the wall time of each and checks that every map.csv has the bytes of the first.
# Usage: bench/fit_map_threads.sh MDR_BINARY N WORKDIR JOBS...   (e.g. build/bin/mdr 4096 /tmp/maps 1 2)
set -eu
mdr=$(realpath "$1"); count=$2; work=$3; shift 3
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
map="$work/map-$count.jpk-force-map"
[ -f "$map" ] || /usr/bin/python3 "$root/scripts/make_instrument_test_files.py" map "$count" "$map"
first=""
for jobs in "$@"; do
    out="$work/out-$jobs"
    rm -rf "$out"
    start=$(date +%s%N)
    "$mdr" fit "$root/examples/fit/jpk-map-hertz.toml" --map "$map" --out "$out" --jobs "$jobs" \
        >"$work/log-$jobs" || true
    end=$(date +%s%N)
    echo "jobs $jobs: $(( (end - start) / 1000000 )) ms wall; $(head -1 "$work/log-$jobs")"
    if [ -z "$first" ]; then
        first="$out/map.csv"
    else
        cmp "$first" "$out/map.csv" && echo "  map.csv identical to the first's"
    fi
done

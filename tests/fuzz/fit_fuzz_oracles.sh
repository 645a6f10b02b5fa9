#!/bin/bash
# Checks that every oracle of mdr_fit_fuzz can fail: for each, a fake `mdr` that misbehaves in that one way runs
# in place of mdr on the seeds (unmutated), and the fuzzer must count every seed as failing that oracle.
#
#   fit_fuzz_oracles.sh MDR_FIT_FUZZ CORPUS_DIR
set -u
fuzzer=$1
corpus=$2
seeds=$(find "$corpus" -mindepth 2 -maxdepth 2 -name case.toml | wc -l)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# oracle name, then the body of the fake mdr (run as `mdr fit case.toml --out out` in the case's directory)
declare -A fakes=(
    [crash]='kill -SEGV $$'
    [hang]='sleep 30'
    [memory]='echo "mdr: error: std::bad_alloc" >&2; exit 1'
    [exit_code]='exit 3'
    [exit1_result]='echo "mdr: error: the fit failed" >&2; exit 1'
    [exit2_wrote]='mkdir -p out && echo x > out/partial.csv; echo "mdr: error: x = 1: bad" >&2; exit 2'
    [one_line]='printf "mdr: error: x = 1:\nbad\n" >&2; exit 2'
    [non_finite]='mkdir -p out && echo "{\"rms_residual\": null}" > out/fit.json; exit 0'
    [unreadable]='mkdir -p out && printf "curve,t\na, b,1\n" > out/curves.csv && echo "{}" > out/fit.json; exit 1'
    [raw_bytes]='printf "mdr: error: x = \033[31m: bad\n" >&2; exit 2'
    [solver_log]='echo "W1127 10:00:00.000000 1 trust_region_minimizer.cc:71] step failed" >&2; exit 2'
    [uncaught]='echo "terminate called after throwing an instance of std::out_of_range" >&2; exit 2'
    [user_files]='echo more >> notes.txt; echo "mdr: error: x = 1: bad" >&2; exit 2'
    [leftovers]='mkdir .out.mdr-partial-1; echo "mdr: error: x = 1: bad" >&2; exit 2'
)
# Whether the summary line counts every seed as failing oracle $2.
fails_all() { [[ "$1 " == *" $2=$seeds "* ]]; }

failed=0
for oracle in "${!fakes[@]}"; do
    printf '#!/bin/bash\n%s\n' "${fakes[$oracle]}" > "$work/mdr-$oracle"
    chmod +x "$work/mdr-$oracle"
    summary=$(cd "$work" && "$fuzzer" "$corpus" 0 --mutants 0 --timeout 0.3 --keep 0 --mdr "$work/mdr-$oracle" 2>/dev/null)
    if ! fails_all "$summary" "$oracle"; then
        echo "oracle $oracle did not fail all $seeds seeds: $summary"
        failed=1
    fi
done
# A process the fake leaves behind is a leftover too.
printf '#!/bin/bash\n(sleep 30 &)\necho "mdr: error: x = 1: bad" >&2; exit 2\n' > "$work/mdr-process"
chmod +x "$work/mdr-process"
summary=$(cd "$work" && "$fuzzer" "$corpus" 0 --mutants 0 --keep 0 --mdr "$work/mdr-process" 2>/dev/null)
fails_all "$summary" leftovers || { echo "a process left behind was not found: $summary"; failed=1; }
[[ $failed == 0 ]] && echo "fit_fuzz_oracles: each of ${#fakes[@]} oracles failed all $seeds seeds of a fake mdr"
exit $failed

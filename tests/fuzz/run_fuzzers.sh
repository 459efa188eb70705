#!/usr/bin/env bash
# `bash bench.sh fuzz` (which installs clang and libclang-rt-14-dev first): builds the fuzz preset
# (clang, libFuzzer, ASan + UBSan) and runs each fuzz target for a fixed number of executions
# with a fixed seed, starting from a COPY of its committed seed corpus and regressions in
# build/fuzz/corpus/<target> (the committed corpus never grows). Findings (crash-*, leak-*,
# timeout-*, oom-*) go to build/fuzz/findings/<target>/, libFuzzer's output to
# build/fuzz/findings/<target>.log. Prints per target the executions (libFuzzer's "Done N runs"),
# the findings, the coverage of its final line and the time, then a total line; exits 1 when
# anything was found.
#
# Overrides (environment): QT_FUZZ_RUNS_IMAGE_READER (default 1000000), QT_FUZZ_RUNS_CLI_ARGS
# (1000000), QT_FUZZ_RUNS_PIPELINE (100000), QT_FUZZ_SEED (1), QT_FUZZ_TARGETS (the targets to
# run, default "image_reader cli_args pipeline"), QT_FUZZ_BUILD (build directory, default
# build/fuzz: the preset's).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${QT_FUZZ_BUILD:-build/fuzz}
seed=${QT_FUZZ_SEED:-1}
targets=${QT_FUZZ_TARGETS:-image_reader cli_args pipeline}
jobs=$(nproc)

cmake --preset fuzz -B "$build" >/dev/null
bins=()
for t in $targets; do bins+=("fuzz_$t"); done
cmake --build "$build" -j"$jobs" --target "${bins[@]}" >/dev/null

runs_for() {
    case "$1" in
        image_reader) echo "${QT_FUZZ_RUNS_IMAGE_READER:-1000000}" ;;
        cli_args) echo "${QT_FUZZ_RUNS_CLI_ARGS:-1000000}" ;;
        pipeline) echo "${QT_FUZZ_RUNS_PIPELINE:-100000}" ;;
        *) echo "unknown fuzz target '$1'" >&2; exit 2 ;;
    esac
}

total_execs=0
total_findings=0
total_seconds=0
printf '%-14s %12s %9s %9s %8s %14s %8s\n' target executions findings coverage seeds corpus seconds
for t in $targets; do
    runs=$(runs_for "$t")
    work="$build/corpus/$t"
    findings="$build/findings/$t"
    log="$build/findings/$t.log"
    rm -rf "$work" "$findings"
    mkdir -p "$work" "$findings"
    cp tests/fuzz/corpus/"$t"/* "$work"/
    if [ -d tests/fuzz/regressions/"$t" ]; then cp tests/fuzz/regressions/"$t"/* "$work"/; fi
    seeds=$(ls "$work" | wc -l)
    start=$(date +%s)
    set +e
    "$build/tests/fuzz/fuzz_$t" -runs="$runs" -seed="$seed" -timeout=25 -artifact_prefix="$findings/" \
        -print_final_stats=1 "$work" >"$log" 2>&1
    rc=$?
    set -e
    seconds=$(( $(date +%s) - start ))
    # Executions: "Done N runs in S second(s)"; a run that stopped at a finding has no such line,
    # then the final stats (or the last status line) say how far it got.
    execs=$(grep -a -o '^Done [0-9]* runs' "$log" | awk '{print $2}' | tail -1 || true)
    [ -n "$execs" ] || execs=$(grep -a -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}' | tail -1 || true)
    [ -n "$execs" ] || execs=$(grep -a -o '^#[0-9]*' "$log" | tr -d '#' | tail -1 || true)
    [ -n "$execs" ] || execs=0
    cov=$(grep -a -o 'cov: [0-9]*' "$log" | awk '{print $2}' | tail -1 || true)
    corp=$(grep -a -o 'corp: [0-9]*/[0-9]*[a-zA-Z]*' "$log" | awk '{print $2}' | tail -1 || true)
    found=$(find "$findings" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
    if [ "$rc" -ne 0 ] && [ "$found" -eq 0 ]; then
        found=1  # libFuzzer failed without writing an artifact: count it, the log says why
        echo "fuzz_$t exited with status $rc without an artifact; see $log" >&2
    fi
    printf '%-14s %12s %9s %9s %8s %14s %8s\n' "$t" "$execs" "$found" "${cov:-?}" "$seeds" "${corp:-?}" "$seconds"
    total_execs=$((total_execs + execs))
    total_findings=$((total_findings + found))
    total_seconds=$((total_seconds + seconds))
done
printf '%-14s %12s %9s %9s %8s %14s %8s\n' total "$total_execs" "$total_findings" "" "" "" "$total_seconds"
if [ "$total_findings" -ne 0 ]; then
    echo "findings in $build/findings/<target>/ (reproduce: $build/tests/fuzz/fuzz_<target> FILE)" >&2
    exit 1
fi

#!/usr/bin/env bash
# A long fuzzing campaign of one target of the fuzz build, beyond the short runs of ctest:
#   cmake --preset fuzz && cmake --build --preset fuzz -j2
#   tests/fuzz/campaign.sh TARGET SECONDSs|RUNS [JOBS]      e.g. campaign.sh hdr 600s 2
# It starts from the kept inputs (tests/fuzz/regressions, tests/fuzz/seeds) and the collected
# seeds, and keeps what it finds in build/fuzz/corpus/TARGET (outside the source tree; the next
# campaign goes on from there). The dictionary, the largest input and the cap of one allocation
# are those of the target's line in tests/fuzz/CMakeLists.txt (PBR_FUZZ_PLAN). At the end it
# prints the inputs run, the edges covered (libFuzzer's cov:) and features (ft:), and where the
# crashes went: each is a finding to fix at its cause, its input kept in
# tests/fuzz/regressions/TARGET.
set -euo pipefail

usage() {
    echo "usage: $0 TARGET SECONDSs|RUNS [JOBS]   (e.g. $0 hdr 600s 2)" >&2
    exit 2
}
[[ $# -ge 2 && $# -le 3 ]] || usage
target=$1
amount=$2
jobs=${3:-1}
[[ $jobs =~ ^[1-9][0-9]*$ ]] || usage

source_dir=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$source_dir/../.." && pwd)
build=$root/build/fuzz
fuzzer=$build/bin/${target}_fuzz
if [[ ! -x $fuzzer ]]; then
    echo "error: $fuzzer: not built (cmake --preset fuzz && cmake --build --preset fuzz -j2)" >&2
    exit 1
fi
plan=$(grep -E "^ +\"$target +" "$source_dir/CMakeLists.txt" | tr -d '"') || true
[[ -n $plan ]] || { echo "error: no line for $target in PBR_FUZZ_PLAN" >&2; exit 1; }
read -r _ dict _ max_len malloc_mb <<<"$plan"

if [[ $amount =~ ^([0-9]+)s$ ]]; then
    limit=(-max_total_time="${BASH_REMATCH[1]}")
elif [[ $amount =~ ^[0-9]+$ ]]; then
    limit=(-runs="$amount")
else
    usage
fi
corpus=$build/corpus/$target
crashes=$build/crashes/$target
logs=$build/logs/$target
mkdir -p "$corpus" "$crashes" "$logs"
rm -f "$logs"/*.log
inputs=()
for dir in "$source_dir/regressions/$target" "$source_dir/seeds/$target" "$build/seeds/$target"; do
    [[ -d $dir ]] && inputs+=("$dir")
done
if [[ $target == model ]]; then  # Assimp's own leaks (lsan_assimp.supp)
    export LSAN_OPTIONS="suppressions='$source_dir/lsan_assimp.supp':print_suppressions=0"
fi

# With several jobs libFuzzer writes one log a job (fuzz-N.log) in the folder it runs in; one
# job runs in this process, its log written under the same name.
cd "$logs"
parallel=()
output=$logs/fuzz-0.log
if [[ $jobs -gt 1 ]]; then
    parallel=(-jobs="$jobs" -workers="$jobs")
    output=$logs/campaign.log
fi
status=0
"$fuzzer" "${limit[@]}" "${parallel[@]}" -max_len="$max_len" -dict="$source_dir/dict/$dict.dict" \
    -rss_limit_mb=2048 -malloc_limit_mb="$malloc_mb" -timeout=10 -artifact_prefix="$crashes/" \
    -print_final_stats=1 "$corpus" "${inputs[@]}" >"$output" 2>&1 || status=$?

# The last report of each job: inputs run, edges (cov:) and features (ft:).
runs=0
for log in "$logs"/fuzz-*.log; do
    last=$(grep -E '^#[0-9]+' "$log" | tail -n 1) || continue
    [[ -n $last ]] || continue
    echo "$(basename "$log"): $last"
    runs=$((runs + $(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")))
done
echo "$target: $runs inputs run; corpus $(ls "$corpus" | wc -l) files in $corpus"
found=$(ls "$crashes" | wc -l)
if [[ $found -gt 0 ]]; then
    echo "$target: $found crash input(s) in $crashes:"
    ls -l "$crashes"
    status=1
elif [[ $status -ne 0 ]]; then
    echo "$target: the fuzzer exited with $status (its log: $logs)"
fi
exit "$status"

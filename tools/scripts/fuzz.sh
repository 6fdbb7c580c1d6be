#!/usr/bin/env bash
# Fuzzes the readers (scene text, OBJ, MTL, numbers) with libFuzzer, ASan and UBSan:
#   tools/scripts/fuzz.sh SECONDS [CORPUS_DIR...]
# Builds the `fuzz` preset (clang) and runs every target for SECONDS. Each target's corpus
# starts from tests/fuzz/corpus/<target>/, the files of its kind in assets/ and the files in
# the CORPUS_DIRs; what it learns is kept in build-fuzz/corpus/<target>/ for the next run.
# Exits non-zero on any crash, leak, hang, out-of-memory or sanitizer report, naming the input
# it saved (build-fuzz/findings/<target>/), which then belongs in a regular unit test.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]] || [ "$1" -lt 1 ]; then
    echo "usage: tools/scripts/fuzz.sh SECONDS [CORPUS_DIR...]  (SECONDS per target, >= 1)" >&2
    exit 2
fi
seconds=$1
shift
for dir in "$@"; do
    [ -d "$dir" ] || { echo "fuzz: no such corpus folder: $dir" >&2; exit 2; }
done
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j"$(nproc)"

declare -A kinds=([fuzz_scene]="*.scene" [fuzz_obj]="*.obj" [fuzz_mtl]="*.mtl" [fuzz_number]="")
status=0
for target in fuzz_scene fuzz_obj fuzz_mtl fuzz_number; do
    corpus=build-fuzz/corpus/$target
    findings=build-fuzz/findings/$target
    mkdir -p "$corpus" "$findings"
    if [ -n "${kinds[$target]}" ]; then
        find assets -name "${kinds[$target]}" -size -1M -exec cp {} "$corpus/" \;
    fi
    log=build-fuzz/findings/$target.log
    echo "fuzz: $target for ${seconds}s"
    # -max_len: the readers' cost is linear in their input; longer inputs only slow the search.
    if build-fuzz/bin/$target -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" \
        "$corpus" "tests/fuzz/corpus/$target" "$@" > "$log" 2>&1; then
        echo "fuzz: $target: $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" |
            grep -o '[0-9]*$') inputs, nothing found"
    else
        echo "fuzz: $target FOUND A PROBLEM; saved input(s):" >&2
        ls -1 "$findings" | sed "s|^|  $findings/|" >&2
        grep -m 1 -E "ERROR|runtime error|deadly signal|timeout|out-of-memory" "$log" >&2 || true
        echo "  full report: $log" >&2
        status=1
    fi
done
exit $status

#!/usr/bin/env bash
# Seeds known bugs one at a time and checks that the tests catch each (issue 12):
#   tools/scripts/mutants.sh [--list FILE] [--only ID,...] [--build-dir DIR] [--tests REGEX]
#                            [--targets T,...] [--stop-on-failure] [-j N]
# Copies the working tree (tracked and untracked, not ignored, files) into DIR/src and builds
# it in DIR/build, so neither your tree nor build/ is touched. Then, for each entry of the list
# (tools/scripts/mutants.txt): plant it, rebuild, run the selected tests, put the file back.
# A mutant is "caught" when a test fails, "MISSED" when all pass, "BROKEN" when it does not
# build (a list entry to fix, not a catch). Exits non-zero when any mutant is missed or broken,
# or when an entry's original text is not found exactly once. DIR is kept between runs: the
# next run copies only files that changed and rebuilds incrementally.
set -euo pipefail

repo=$(cd "$(dirname "$0")/../.." && pwd)
helper=$repo/tools/scripts/mutants.py
list=$repo/tools/scripts/mutants.txt
work=$repo/build-mutants
only=""
# By default every test of the reference (label `reference`: hand-computed values) and of the
# shader (label `render`: images against the reference), less those that cannot see a bug in
# shading, intersection or traversal and cost time: the lavapipe loop-limit tests (30,000
# spheres without a grid), buffer limits and packing, the compile dispatch, the comparison
# helpers. New tests in those two binaries join the selection by themselves.
# An entry may name its own selection instead (targets:, labels:, tests: in the list), for code
# that only other tests can see (scene reading, the grid cache, the tools); --tests and --targets
# on the command line override every entry's.
default_labels='^(reference|render)$'
default_exclude='LoopCut|LoopLimit|Oversized|TexelAndStorage|CompileDispatch|LargeScene|ScenePacking|TracerFeatures|FrameParams|ImageCompare'
default_targets=reference_tests,render_tests
cli_tests='' cli_targets=''
labels='' exclude='' tests='' targets=$default_targets
jobs=$(nproc)
stop=''

usage() {
    sed -n '2,12s/^# \{0,1\}//p' "$0"
    cat <<EOF

options:
  --list FILE      the mutants (default tools/scripts/mutants.txt; its format is described there)
  --only ID,...    only these mutants, in this order
  --build-dir DIR  scratch folder for the copy (DIR/src) and its build (DIR/build), logs in
                   DIR/logs (default build-mutants/, which git ignores)
  --tests REGEX    ctest -R selection for every entry, instead of each entry's own (its
                   tests: and labels: lines) or the default (labels reference and render,
                   less the tests that cannot see a shading bug; see the top of this script)
  --targets T,...  what to build before the tests, for every entry (default: the entry's
                   targets: line, else $default_targets);
                   they must hold the tests that are selected
  --stop-on-failure
                   stop a mutant's tests at its first failing test: quicker, but the report
                   names only the tests that had failed by then
  -j N             build and test jobs (default $(nproc))
EOF
}

die() {
    echo "mutants: $*" >&2
    exit 2
}

while [ $# -gt 0 ]; do
    case $1 in
    --list) [ $# -ge 2 ] || die "--list needs a file"; list=$(realpath "$2"); shift 2 ;;
    --only) [ $# -ge 2 ] || die "--only needs ids"; only=$2; shift 2 ;;
    --build-dir) [ $# -ge 2 ] || die "--build-dir needs a folder"; work=$(realpath -m "$2"); shift 2 ;;
    --tests) [ $# -ge 2 ] || die "--tests needs a regex"; cli_tests=$2; shift 2 ;;
    --targets) [ $# -ge 2 ] || die "--targets needs targets"; cli_targets=$2; shift 2 ;;
    --stop-on-failure) stop=--stop-on-failure; shift ;;
    -j) [ $# -ge 2 ] && [[ $2 =~ ^[1-9][0-9]*$ ]] || die "-j needs a number"; jobs=$2; shift 2 ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; die "unknown argument: $1" ;;
    esac
done
[ -f "$list" ] || die "no such list: $list"
command -v python3 > /dev/null || die "python3 is needed (tools/scripts/mutants.py)"
case $work in
"$repo" | "$repo/build" | "$repo/build/"*) die "--build-dir $work would overwrite your tree or build/" ;;
"$repo/"*) git -C "$repo" check-ignore -q "$work/" ||
    die "--build-dir $work is inside the repository but not ignored by git: choose build-*/ or a folder outside" ;;
esac

# Every entry must apply before anything is built: a stale list fails here, loudly.
python3 "$helper" check "$list" "$repo" >&2 || die "fix the list first ($list)"
selected=$(python3 "$helper" ids "$list" "$only") || die "bad --only: $only"
mapfile -t entries <<< "$selected"

src=$work/src
build=$work/build
logs=$work/logs
saved=$work/saved
mkdir -p "$src" "$build" "$logs"
rm -rf "$saved"
git -C "$repo" ls-files -z --cached --others --exclude-standard | python3 "$helper" sync "$repo" "$src"

# Whatever happens (an error, Ctrl-C), the scratch copy gets its original files back.
restore() {
    if [ -d "$saved" ]; then
        python3 "$helper" revert "$src" "$saved" || echo "mutants: could not restore $src" >&2
        rm -rf "$saved"
    fi
}
trap restore EXIT

build_targets() { # log file
    local args=()
    IFS=, read -ra names <<< "$targets"
    for t in "${names[@]}"; do args+=(--target "$t"); done
    cmake --build "$build" -j "$jobs" "${args[@]}" > "$1" 2>&1
}

# Runs the selected tests; prints the names of those that failed, one a line. Status 0 when
# all pass. A run that hangs is stopped after an hour and counts as failing.
run_tests() { # log file
    local status=0
    local args=(--test-dir "$build" -j "$jobs" --no-tests=error --output-on-failure)
    [ -n "$tests" ] && args+=(-R "$tests")
    [ -n "$labels" ] && args+=(-L "$labels")
    [ -n "$exclude" ] && args+=(-E "$exclude")
    [ -n "$stop" ] && args+=("$stop")
    timeout 3600 ctest "${args[@]}" > "$1" 2>&1 || status=$?
    awk '/The following tests FAILED:/ { f = 1; next }
         f && /^[[:space:]]+[0-9]+ - / {
             sub(/^[[:space:]]+[0-9]+ - /, ""); sub(/ \([^)]*\)$/, ""); sub(/ +#.*$/, ""); print
         }' "$1"
    [ "$status" -eq 124 ] && echo "(ctest timed out after 3600 s)"
    return $status
}

# Sets targets, labels, tests and exclude for an entry's fields (its own selection, or the
# defaults), the command line's --tests and --targets first.
select_for() { # entry-targets entry-labels entry-tests
    targets=${cli_targets:-${1:-$default_targets}}
    if [ -n "$cli_tests" ]; then
        tests=$cli_tests labels='' exclude=''
    elif [ -n "$3" ]; then
        tests=$3 labels=$2 exclude=''
    elif [ -n "$2" ]; then # by label: less the slow tests that cannot see a bug, as by default
        tests='' labels=$2 exclude=$default_exclude
    else
        tests='' labels=$default_labels exclude=$default_exclude
    fi
}

start=$SECONDS
echo "mutants: ${#entries[@]} mutant(s) from ${list#"$repo"/}; scratch copy in $work"
if [ ! -f "$build/CMakeCache.txt" ]; then
    echo "mutants: configuring $build (first run: the build takes several minutes)"
    cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release > "$logs/configure.log" 2>&1 ||
        die "configure failed: $logs/configure.log"
fi
# The unmutated tree must build and pass each distinct selection the entries use.
declare -A baselines=()
for entry in "${entries[@]}"; do
    IFS=$'\x1f' read -r _id etargets elabels etests _desc <<< "$entry"
    select_for "$etargets" "$elabels" "$etests"
    key="$targets|$labels|$tests"
    [ -n "${baselines[$key]:-}" ] && continue
    baselines[$key]=1
    b=${#baselines[@]}
    echo "mutants: baseline $b: building $targets; tests ${tests:+-R $tests }${labels:+-L $labels}"
    build_targets "$logs/baseline$b.build.log" ||
        die "the unmutated tree does not build: $logs/baseline$b.build.log"
    t0=$SECONDS
    if ! failed=$(run_tests "$logs/baseline$b.test.log"); then
        echo "$failed" | sed 's/^/  /' >&2
        die "tests fail without any mutant: fix them first ($logs/baseline$b.test.log)"
    fi
    count=$(grep -Eo 'out of [0-9]+' "$logs/baseline$b.test.log" | grep -Eo '[0-9]+' || echo "the")
    echo "mutants: baseline $b: $count selected tests pass in $((SECONDS - t0)) s"
done
echo "mutants: now each mutant"

declare -a rows=()
missed=() broken=()
n=0
for entry in "${entries[@]}"; do
    IFS=$'\x1f' read -r id etargets elabels etests _desc <<< "$entry"
    select_for "$etargets" "$elabels" "$etests"
    n=$((n + 1))
    t0=$SECONDS
    printf '[%2d/%d] %-30s ' "$n" "${#entries[@]}" "$id"
    mkdir -p "$saved"
    python3 "$helper" apply "$list" "$id" "$src" "$saved" || die "could not plant $id"
    if ! build_targets "$logs/$id.build.log"; then
        result=BROKEN
        detail="does not build: $logs/$id.build.log"
        broken+=("$id")
    elif failed=$(run_tests "$logs/$id.test.log"); then
        result=MISSED
        detail="every selected test passed"
        missed+=("$id")
    else
        result=caught
        if [ -z "$failed" ]; then
            detail="ctest failed without naming a test: $logs/$id.test.log"
        else
            detail="$(echo "$failed" | grep -c .) failed: $(echo "$failed" | paste -sd, - | sed 's/,/, /g')"
        fi
    fi
    restore
    echo "$result in $((SECONDS - t0)) s  ($detail)"
    rows+=("$(printf '%-30s %-7s %5s s  %s' "$id" "$result" "$((SECONDS - t0))" "$detail")")
done

echo
echo "mutant                         result   time  tests that failed"
printf '%s\n' "${rows[@]}" | cut -c1-200
total=${#entries[@]}
echo
echo "mutants: $((total - ${#missed[@]} - ${#broken[@]})) of $total caught in $(((SECONDS - start) / 60)) min $(((SECONDS - start) % 60)) s; logs in $logs"
status=0
if [ ${#missed[@]} -gt 0 ]; then
    echo "mutants: MISSED (no test failed): ${missed[*]}" >&2
    status=1
fi
if [ ${#broken[@]} -gt 0 ]; then
    echo "mutants: BROKEN (do not build; fix the list): ${broken[*]}" >&2
    status=1
fi
exit $status

#!/usr/bin/env bash
# Soaks prism-view: tools/scripts/soak.sh MINUTES [SCENE]   (--help for the details)
# Flies, resizes, reloads a changing scene and toggles features for MINUTES under Xvfb with the
# Vulkan validation layers on, then reports memory, frames and messages. Exits non-zero when a
# limit is broken, so it can gate a release.
set -euo pipefail
cd "$(dirname "$0")/../.."

# The limits (issue 12): RSS may not grow by 5% or more after the warm-up.
readonly max_growth_percent=5
# The script's periods, in frames. They divide 240 (the orbit's length): toggles 8 x 30,
# scene edits 3 x 80, resizes 4 x 60. So the whole script repeats every 240 frames and each
# period end finds the viewer in the same state; prism-view compares RSS at period ends only,
# the first one after 20% of the run (the warm-up) with the last one.
readonly toggle_every=30 reload_every=80 resize_every=60
readonly sizes=320x240 cycle=400x300,256x192,480x270,320x240
# An RSS line every this many frames, and a progress line every this many seconds.
readonly report_every=120 progress_seconds=30

usage() {
    cat <<'EOF'
usage: tools/scripts/soak.sh MINUTES [SCENE]

Runs build/bin/prism-view for MINUTES (a number > 0; 10 for a release) under `xvfb-run -a`
with Vulkan validation on (--validation), on a scratch copy of SCENE (default
assets/scenes/cornell.scene; files in assets/ are never written). prism-view is scripted:
  - flies: the camera orbits the scene (a new view every frame, 240-frame loop);
  - resizes the window every 60 frames: 400x300, 256x192, 480x270, 320x240 (starts 320x240);
  - rewrites its scene file every 80 frames with 0, 1 or 2 added spheres and reloads it (new
    grid, new buffers of another size, as after an edit);
  - toggles a tracer feature every 30 frames: shadows, reflection, refraction, grid, and back
    (new pipelines with other specialization constants, as the overlay's checkboxes do).
The whole script repeats every 240 frames. RSS is compared where a period ends, so the
viewer is in the same state: at the first period end after 20% of the run (the warm-up:
allocators settle for a few periods after every state has been met once) and at the last.

It prints a progress line every 30 s and at the end a report: RSS at start, after the
warm-up, at the last period end and at exit, the growth after the warm-up, frames, swapchain rebuilds, reloads, toggles,
validation messages and errors. prism-view's output is kept in build/soak-last.log.

Exit status 0 only if: RSS grew by less than 5% after the warm-up, there was no validation
message and no error (a failed reload or toggle, a prism-view error), the run had a period
end after its warm-up, and prism-view exited 0. 1 otherwise; 2 for a usage error.

If build/bin/prism-view is missing it is built first (cmake --preset release and
cmake --build --preset release); otherwise nothing is built.
Needs xvfb-run (Debian: xvfb, xauth) and vulkan-validationlayers.
EOF
}

if [ $# -ge 1 ] && { [ "$1" = "--help" ] || [ "$1" = "-h" ]; }; then
    usage
    exit 0
fi
if [ $# -lt 1 ] || [ $# -gt 2 ] || ! [[ "$1" =~ ^[0-9]+([.][0-9]+)?$ ]] ||
    ! awk -v m="$1" 'BEGIN { exit !(m > 0) }'; then
    echo "usage: tools/scripts/soak.sh MINUTES [SCENE]  (MINUTES > 0; --help explains)" >&2
    exit 2
fi
minutes=$1
scene=${2:-assets/scenes/cornell.scene}
[ -f "$scene" ] || { echo "soak: no such scene: $scene" >&2; exit 2; }
command -v xvfb-run > /dev/null || { echo "soak: needs xvfb-run (Debian: xvfb xauth)" >&2; exit 2; }
seconds=$(awk -v m="$minutes" 'BEGIN { printf "%d", m * 60 + 0.5 }')
[ "$seconds" -ge 1 ] || seconds=1

view=build/bin/prism-view
if [ ! -x "$view" ]; then
    echo "soak: $view is missing; building it"
    cmake --preset release > /dev/null
    cmake --build --preset release
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/prism-soak.XXXXXX")
runner=""
cleanup() {
    # The run is its own process group (setsid below): Xvfb and prism-view go with xvfb-run.
    if [ -n "$runner" ] && kill -0 "$runner" 2> /dev/null; then
        kill -- "-$runner" 2> /dev/null || true
    fi
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The scratch copy: its mesh, environment, texture and map paths, relative to the scene's
# folder, made absolute so that they still resolve from $work (comment lines are left alone).
scene_dir=$(cd "$(dirname "$scene")" && pwd)
copy=$work/$(basename "$scene")
sed -E -e '/^[[:space:]]*#/b' \
    -e "s#^([[:space:]]*(mesh|environment)[[:space:]]+\"?)([^/\"[:space:]])#\\1$scene_dir/\\3#" \
    -e "s#([[:space:]](texture|norm|bump)[[:space:]]+\"?)([^/\"[:space:]])#\\1$scene_dir/\\3#g" \
    "$scene" > "$copy"

log=build/soak-last.log
status_file=$work/status
# A hang must not outlast the run by much: prism-view is stopped 5 minutes after its time.
limit=$((seconds + 300))
echo "soak: $minutes min of $scene at $sizes under Xvfb, validation on (log: $log)"
# xvfb-run's own status is not prism-view's (it is 5 when its temporary folder cannot be
# removed), so prism-view's is written to a file. The inner script expands its own arguments.
# shellcheck disable=SC2016
PRISM_VALIDATION=1 setsid xvfb-run -a -s "-screen 0 1280x1024x24" \
    bash -c 'log=$1 status=$2; shift 2; "$@" > "$log" 2>&1; echo $? > "$status"' soak \
    "$log" "$status_file" timeout "$limit" "$view" "$copy" --size "$sizes" --vsync off \
    --validation --script-seconds "$seconds" --script-orbit \
    --script-toggle-every "$toggle_every" --script-reload-every "$reload_every" \
    --script-resize-every "$resize_every:$cycle" --report-every "$report_every" &
runner=$!

started=$SECONDS
next=$progress_seconds
while kill -0 "$runner" 2> /dev/null; do
    sleep 1
    if [ $((SECONDS - started)) -ge "$next" ]; then
        next=$((next + progress_seconds))
        last=$(grep -E '^prism-view: frame [0-9]+ ' "$log" 2> /dev/null | tail -n 1 || true)
        echo "soak: ${last#prism-view: } (at $((SECONDS - started)) s of $seconds s)"
    fi
done
wait "$runner" || true
runner=""

exit_status=$(cat "$status_file" 2> /dev/null || echo "none")
summary=$(grep -E '^prism-view: soak ' "$log" | tail -n 1 || true)
# The summary's key=value pairs, by key ("" where missing).
field() { sed -nE "s/.* $1=([^ ]*).*/\\1/p" <<< "$summary"; }
frames=$(field frames) run_seconds=$(field seconds) rebuilds=$(field swapchain_rebuilds)
resizes=$(field resizes) reloads=$(field reloads) toggles=$(field toggles)
script_errors=$(field errors) period=$(field period_frames) warmup=$(field warmup_frames)
rss_start=$(field rss_kib_start) rss_warm=$(field rss_kib_warm) rss_end=$(field rss_kib_end)
rss_peak=$(field rss_kib_peak) rss_exit=$(field rss_kib_exit)
# Every message the layers sent, also any after the summary (at device and instance teardown).
messages=$(grep -c '^prism: Vulkan validation:' "$log" || true)
tool_errors=$(grep -c -E '^prism-view: error:|^prism-view: .* did not converge' "$log" || true)
errors=$(( ${script_errors:-0} + tool_errors ))

growth=""
if [ -n "$rss_warm" ] && [ "$rss_warm" -gt 0 ] && [ -n "$rss_end" ] && [ "$rss_end" -gt 0 ]; then
    growth=$(awk -v w="$rss_warm" -v e="$rss_end" 'BEGIN { printf "%+.2f", (e - w) * 100 / w }')
fi

failures=()
[ "$exit_status" = 0 ] || failures+=("prism-view exited with status $exit_status")
[ -n "$summary" ] || failures+=("no summary line from prism-view")
if [ -n "$summary" ] && [ -z "$growth" ]; then
    failures+=("too short: no period end ($period frames) after the warm-up (20% of the run)")
fi
if [ -n "$growth" ] &&
    awk -v g="$growth" -v max="$max_growth_percent" 'BEGIN { exit !(g >= max) }'; then
    failures+=("RSS grew by $growth% after the warm-up (limit < $max_growth_percent%)")
fi
[ "$messages" -eq 0 ] || failures+=("$messages validation messages")
[ "$errors" -eq 0 ] || failures+=("$errors errors")

echo "soak: report ($scene, $minutes min)"
printf '  %-22s %s\n' \
    "frames" "${frames:-?} in ${run_seconds:-?} s" \
    "swapchain rebuilds" "${rebuilds:-?} (${resizes:-?} resizes asked for)" \
    "scene reloads" "${reloads:-?}" \
    "feature toggles" "${toggles:-?}" \
    "RSS at start" "${rss_start:-?} KiB (before the first frame)" \
    "RSS after warm-up" "${rss_warm:-?} KiB (after frame ${warmup:-?}; period ${period:-?})" \
    "RSS at end" "${rss_end:-?} KiB (last period end; ${rss_exit:-?} at exit)" \
    "RSS peak" "${rss_peak:-?} KiB (after warm-up)" \
    "RSS growth" "${growth:-?}% after warm-up (limit < $max_growth_percent%)" \
    "validation messages" "$messages" \
    "errors" "$errors" \
    "prism-view exit" "$exit_status"
if [ ${#failures[@]} -gt 0 ]; then
    for failure in "${failures[@]}"; do
        echo "soak: FAIL: $failure" >&2
    done
    if [ -z "$summary" ]; then # it stopped early: its last words say why
        tail -n 5 "$log" | sed 's/^/  /' >&2
    fi
    echo "soak: prism-view's output: $log" >&2
    exit 1
fi
echo "soak: PASS"

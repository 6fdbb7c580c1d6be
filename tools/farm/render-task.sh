#!/usr/bin/env bash
# One task of a farm job (prism-slurm, prism-parallel): a chunk of a frame range, or one tile of
# a still, rendered by prism-render. Runs wherever the farm puts it; what it needs is on a
# filesystem every node shares (the scene, its meshes, the outputs' directory, PRISM_BIN).
#
#   render-task.sh frames INDEX SCENE FIRST LAST STEP TASKS PATTERN [prism-render options...]
#       task INDEX of TASKS takes every TASKS-th frame of FIRST-LAST:STEP from its INDEX-th on
#       (FIRST + (INDEX + k*TASKS)*STEP up to LAST), so that each task gets views from all over
#       the range and the tasks cost about the same (a turntable's costly side is not one
#       task's); written to PATTERN (#### or {frame}); frames already written are left out
#       (--skip-existing), so a task that was stopped and runs again finishes its share.
#   render-task.sh tiles INDEX SCENE COUNT PATTERN [prism-render options...]
#       tile INDEX of COUNT (prism-render --tile), written to PATTERN ({tile} = INDEX), unless
#       it is there already.
#
# INDEX may be "slurm": SLURM_ARRAY_TASK_ID. The device is chosen per node: where the task
# was given GPUs (Slurm's --gres=gpu, CUDA_VISIBLE_DEVICES) Prism takes the first discrete GPU
# as it always does; elsewhere lavapipe (--device llvmpipe), so that a CPU node never uses a GPU
# that is some other job's. PRISM_DEVICE overrides both.
set -euo pipefail

die() {
    echo "render-task: $*" >&2
    exit 2
}
[[ $# -ge 3 ]] || die "usage: render-task.sh frames|tiles INDEX SCENE ... (see the header)"
mode=$1
index=$2
scene=$3
shift 3
if [[ $index == slurm ]]; then
    index=${SLURM_ARRAY_TASK_ID:?"render-task: INDEX slurm, but SLURM_ARRAY_TASK_ID is not set"}
fi
[[ $index =~ ^[0-9]+$ ]] || die "INDEX must be a whole number, got '$index'"
bin=${PRISM_BIN:-$(cd "$(dirname "$0")/../../build/bin" 2>/dev/null && pwd || true)}
render=$bin/prism-render
[[ -x $render ]] || die "no prism-render in '$bin': set PRISM_BIN to the directory that holds it"

# lavapipe's threads: the cores Slurm gave the task, not all of the node's (LP_NUM_THREADS set by
# prism-farm --threads wins).
if [[ -z ${LP_NUM_THREADS:-} && -n ${SLURM_CPUS_PER_TASK:-} ]]; then
    export LP_NUM_THREADS=$SLURM_CPUS_PER_TASK
fi

# For the task's log: how many threads lavapipe was given (unset: one a core of the node).
threads_note() {
    [[ -z ${LP_NUM_THREADS:-} ]] || echo ", LP_NUM_THREADS=$LP_NUM_THREADS"
}

device=()
if [[ -n ${PRISM_DEVICE:-} ]]; then
    device=(--device "$PRISM_DEVICE")
elif [[ -z ${SLURM_JOB_GPUS:-} && -z ${CUDA_VISIBLE_DEVICES:-} ]]; then
    device=(--device llvmpipe)
fi

case $mode in
frames)
    [[ $# -ge 5 ]] || die "frames needs FIRST LAST STEP TASKS PATTERN"
    first=$1 last=$2 step=$3 tasks=$4 pattern=$5
    shift 5
    ((index < tasks)) || die "task $index of $tasks: tasks are numbered 0-$((tasks - 1))"
    start=$((first + index * step))
    ((start <= last)) || die "task $index starts past the last frame $last: nothing to render"
    frames="$start-$last:$((tasks * step))"
    echo "render-task: frames $frames of $scene on $(hostname -s)$(threads_note)" >&2
    exec "$render" "$scene" --frames "$frames" --skip-existing -o "$pattern" \
        "${device[@]}" "$@"
    ;;
tiles)
    [[ $# -ge 2 ]] || die "tiles needs COUNT PATTERN"
    count=$1 pattern=$2
    shift 2
    echo "render-task: tile $index/$count of $scene on $(hostname -s)$(threads_note)" >&2
    exec "$render" "$scene" --tile "$index/$count" --skip-existing -o "$pattern" \
        "${device[@]}" "$@"
    ;;
*)
    die "mode must be frames or tiles, got '$mode'"
    ;;
esac

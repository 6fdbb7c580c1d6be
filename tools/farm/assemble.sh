#!/usr/bin/env bash
# The last step of a farm job (prism-slurm, prism-parallel), once every task has finished:
#
#   assemble.sh frames SHEET FRAMES...   a contact sheet (contact_sheet.py) of the frames
#   assemble.sh tiles OUTPUT TILES...    the tiles merged into the still (prism-merge), and a
#                                        PNG of it beside it (OUTPUT with .png) to look at
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=${PRISM_BIN:-$(cd "$here/../../build/bin" 2>/dev/null && pwd || true)}
[[ $# -ge 3 ]] || { echo "usage: assemble.sh frames SHEET FRAMES... | tiles OUTPUT TILES..." >&2; exit 2; }
mode=$1 output=$2
shift 2
case $mode in
frames)
    missing=0
    for f in "$@"; do
        [[ -f $f ]] || { echo "assemble: frame $f is missing" >&2; missing=$((missing + 1)); }
    done
    ((missing == 0)) || { echo "assemble: $missing frames missing: no contact sheet" >&2; exit 1; }
    exec "$here/contact_sheet.py" "$@" -o "$output"
    ;;
tiles)
    [[ -x $bin/prism-merge ]] || { echo "assemble: no prism-merge in '$bin' (PRISM_BIN)" >&2; exit 2; }
    "$bin/prism-merge" "$@" -o "$output"
    if [[ $output == *.exr ]]; then
        "$bin/prism-merge" --quiet "$@" -o "${output%.exr}.png"
    fi
    ;;
*)
    echo "assemble: mode must be frames or tiles, got '$mode'" >&2
    exit 2
    ;;
esac

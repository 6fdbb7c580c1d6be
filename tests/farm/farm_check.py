#!/usr/bin/python3
"""The farm front end (tools/farm/prism-farm) on real engines (issue 32).

    farm_check.py slurm    --bin build/bin   a local Slurm (tools/farm/local-slurm.sh), as root
    farm_check.py parallel --bin build/bin   GNU parallel on this machine (-S :)

slurm: a 24-frame turntable as a job array of 6 chunks, every frame the one-process render's to
the bit, and the contact sheet made by the assembly job; a 16-tile still as 16 tasks, merged bit
for bit the untiled render; a task cancelled mid-way (scancel) leaves no partial or temporary
file, its assembly is cancelled with it, and the same command again completes the range.
parallel: a 4-tile still and a 6-frame range through GNU parallel, bit for bit.

Missing packages or no root is a failure with a message, never a silent skip."""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import OpenImageIO as oiio

ROOT = Path(__file__).resolve().parents[2]
FARM = ROOT / "tools" / "farm"
SCENES = ROOT / "assets" / "scenes"
TURNTABLE = SCENES / "showcase-turntable.scene"
STILL = SCENES / "showcase.scene"


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def pixels(path):
    image = oiio.ImageBuf(str(path))
    check(not image.has_error, f"cannot read {path}: {image.geterror()}")
    return image.get_pixels(oiio.FLOAT)


def same_image(a, b):
    pa, pb = pixels(a), pixels(b)
    return pa.shape == pb.shape and np.array_equal(pa, pb, equal_nan=True)


def run(command, env=None, check_rc=True):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True, env=env)
    if check_rc and result.returncode != 0:
        raise Failure(f"{' '.join(map(str, command))} failed ({result.returncode}):\n"
                      f"{result.stdout}{result.stderr}")
    return result


def farm(engine, args, env, wait=True):
    command = [FARM / "prism-farm", engine] + args[:1] + (["--wait"] if wait and engine == "slurm"
                                                            else []) + args[1:]
    return run(command, env=env)


def one_process_frames(bin_dir, out, frames, size):
    run([bin_dir / "prism-render", TURNTABLE, "--frames", frames, "--size", size, "--quiet",
         "-o", out / "f.####.exr"])


def check_frames(out, reference, first, last):
    for f in range(first, last + 1):
        name = f"turn.{f:04d}.exr"
        check((out / name).exists(), f"frame {f} is missing")
        check(same_image(out / name, reference / f"f.{f:04d}.exr"),
              f"frame {f} differs from the one-process render")


def check_no_temporary_files(directory):
    hidden = [p.name for p in directory.iterdir() if p.name.startswith(".")]
    check(not hidden, f"temporary files left behind: {hidden}")


def slurm_checks(bin_dir, work, env):
    size = ["--size", "48x36", "--quiet"]
    # 24 frames, 6 tasks of 4, then the contact sheet.
    frames_dir = work / "frames"
    reference = work / "reference"
    reference.mkdir()
    one_process_frames(bin_dir, reference, "1-24", "48x36")
    started = time.monotonic()
    result = farm("slurm", [TURNTABLE, "-o", frames_dir / "turn.####.exr", "--frames", "1-24",
                            "--chunk", "4", "--"] + size, env)
    check("24 frames in 6 tasks of up to 4" in result.stderr, result.stderr)
    check_frames(frames_dir, reference, 1, 24)
    sheet = frames_dir / "contact-sheet.png"
    check(sheet.exists(), "no contact sheet")
    spec = oiio.ImageInput.open(str(sheet)).spec()
    check(spec.width > 4 * 160 and spec.height > 4 * 100, f"sheet {spec.width}x{spec.height}")
    logs = sorted(p.name for p in (frames_dir / "logs").iterdir())
    check(len([n for n in logs if re.fullmatch(r"prism-showcase-turntable-\d+_\d\.log", n)]) == 6,
          f"logs named %x-%A_%a: {logs}")
    print(f"slurm: 24 frames in 6 tasks, {time.monotonic() - started:.1f} s", file=sys.stderr)

    # 16 tiles of a still, merged.
    tiles_dir = work / "tiles"
    tiles_dir.mkdir()
    run([bin_dir / "prism-render", STILL, "--size", "64x48", "--spp", "2", "--quiet", "-o",
         tiles_dir / "whole.exr"])
    farm("slurm", [STILL, "-o", tiles_dir / "poster.exr", "--tiles", "16", "--threads", "2",
                   "--", "--size", "64x48", "--spp", "2", "--quiet"], env)
    check(len(list(tiles_dir.glob("poster.tile-*.exr"))) == 16, "16 tiles")
    tile_logs = list((tiles_dir / "logs").glob("*_*.log"))
    check(len(tile_logs) == 16 and all("LP_NUM_THREADS=2" in p.read_text() for p in tile_logs),
          "--threads 2 did not reach every task's lavapipe")
    check(same_image(tiles_dir / "poster.exr", tiles_dir / "whole.exr"),
          "the merged still differs from the untiled render")
    check((tiles_dir / "poster.png").exists(), "no PNG of the merged still")

    # A task cancelled mid-way: frames big enough to take a while, one task of 8.
    kill_dir = work / "kill"
    args = [TURNTABLE, "-o", kill_dir / "turn.####.exr", "--frames", "1-8", "--chunk", "8",
            "--", "--size", "320x240", "--quiet"]
    result = farm("slurm", args, env, wait=False)
    match = re.search(r"job array (\d+), then assembly job (\d+)", result.stderr)
    check(match, result.stderr)
    array, assembly = match.group(1), match.group(2)
    deadline = time.monotonic() + 120
    while len(list(kill_dir.glob("turn.*.exr"))) < 2:
        check(time.monotonic() < deadline, "the task wrote no frames in 120 s")
        time.sleep(0.05)
    run(["scancel", f"{array}_0"], env=env)
    while run(["squeue", "-h", "-j", f"{array},{assembly}"], env=env, check_rc=False).stdout.strip():
        check(time.monotonic() < deadline, "the cancelled jobs did not leave the queue")
        time.sleep(0.5)
    written = sorted(kill_dir.glob("turn.*.exr"))
    check(2 <= len(written) < 8, f"{len(written)} frames after the cancel: not mid-way")
    for frame in written:
        pixels(frame)  # whole: it reads
    check_no_temporary_files(kill_dir)
    check(not (kill_dir / "contact-sheet.png").exists(),
          "the assembly ran although a task was cancelled")
    farm("slurm", args, env)  # the same command again
    check(len(list(kill_dir.glob("turn.*.exr"))) == 8, "the resubmission left frames out")
    check((kill_dir / "contact-sheet.png").exists(), "no contact sheet after the resubmission")
    check_no_temporary_files(kill_dir)
    print(f"slurm: cancelled after {len(written)} of 8 frames, completed on resubmission",
          file=sys.stderr)

    # No task waited for slurmd to read the user's login environment (a login shell before
    # every task: what --export=ALL,VAR=... asks for).
    slurmd_log = (work / "slurm" / "log" / "slurmd.log").read_text()
    check("_get_user_env" not in slurmd_log, "slurmd read the login environment for a task")


def parallel_checks(bin_dir, work, env):
    still = work / "still"
    still.mkdir()
    run([bin_dir / "prism-render", STILL, "--size", "64x48", "--quiet", "-o",
         still / "whole.exr"])
    farm("parallel", [STILL, "-o", still / "poster.exr", "--tiles", "4", "--jobs", "2", "--",
                      "--size", "64x48", "--quiet"], env)
    check(same_image(still / "poster.exr", still / "whole.exr"),
          "the merged still differs from the untiled render")
    frames_dir = work / "frames"
    reference = work / "reference"
    reference.mkdir()
    one_process_frames(bin_dir, reference, "1-6", "48x36")
    farm("parallel", [TURNTABLE, "-o", frames_dir / "turn.####.exr", "--frames", "1-6",
                      "--chunk", "2", "--jobs", "2", "--", "--size", "48x36", "--quiet"], env)
    check_frames(frames_dir, reference, 1, 6)
    check((frames_dir / "contact-sheet.png").exists(), "no contact sheet")
    # Bad input: a clear message, no jobs.
    bad = run([FARM / "prism-farm", "parallel", STILL, "-o", still / "x.exr", "--frames", "5-1"],
              env=env, check_rc=False)
    check(bad.returncode == 2 and "runs backwards" in bad.stderr, bad.stderr)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("engine", choices=["slurm", "parallel"])
    parser.add_argument("--bin", required=True, type=Path)
    args = parser.parse_args()
    env = dict(os.environ, PRISM_BIN=str(args.bin.resolve()))
    env.pop("SLURM_CONF", None)
    needed = ["parallel"] if args.engine == "parallel" else ["sbatch", "squeue", "scancel"]
    missing = [p for p in needed if not shutil.which(p)]
    if missing:
        print(f"farm_check: {' '.join(missing)} missing: install Debian's "
              f"{'parallel' if args.engine == 'parallel' else 'slurm-wlm and munge'} "
              "(tools/scripts/install-deps.sh does)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory(prefix=f"prism-farm-{args.engine}-") as tmp:
        work = Path(tmp)
        try:
            if args.engine == "parallel":
                parallel_checks(args.bin, work, env)
            else:
                if os.geteuid() != 0:
                    print("farm_check: the local Slurm runs its daemons as root: run the tests "
                          "as root", file=sys.stderr)
                    return 1
                slurm = work / "slurm"
                env["PRISM_SLURM_PORT"] = env.get("PRISM_SLURM_PORT", "16817")
                line = run([FARM / "local-slurm.sh", "start", slurm], env=env).stdout
                env["SLURM_CONF"] = line.strip().split("=", 1)[1]
                try:
                    slurm_checks(args.bin, work, env)
                finally:
                    run([FARM / "local-slurm.sh", "stop", slurm], env=env, check_rc=False)
        except Failure as failure:
            print(f"farm_check {args.engine}: FAILED: {failure}", file=sys.stderr)
            return 1
    print(f"farm_check {args.engine}: passed", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())

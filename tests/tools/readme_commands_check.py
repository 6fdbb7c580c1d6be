#!/usr/bin/env python3
"""Every command the README shows runs as a newcomer would type it (issue 35's docs test).

What counts as a command: each line of a ```sh block, each inline `build/bin/...` span with
arguments, and the scene of the unlabelled block that starts with `camera` (saved and rendered).
Synopsis blocks (a tool's name and its [options]) are docs_options_check.py's; the ```python
block is tests/python's (test_examples.py). A command is run from the repository root with its
output paths moved to a temporary folder, and must exit 0 and write what it says; prism-view,
which opens a window until closed, must still be running under Xvfb after a few seconds. A few
commands are not run here, each for a reason given in EXEMPT; a command the README gains that
this check neither runs nor exempts fails it, so that nothing shown goes untried.
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

EXEMPT = {
    "tools/scripts/setup.sh": "installs packages and builds the release tree this test runs in; "
                              ".ci/run runs test.sh, which does the same, and the newcomer check "
                              "before every landing runs setup.sh itself",
    "tools/scripts/test.sh": "runs this whole suite (this test included)",
}


def commands(readme):
    """(kind, text) for everything the README offers to run."""
    found = []
    for lang, body in re.findall(r"```(\w*)\n(.*?)```", readme, re.S):
        lines = [line.split("  #")[0].strip() for line in body.splitlines()]
        lines = [line for line in lines if line and not line.startswith("#")]
        if lang == "sh":
            found += [("shell", line) for line in lines]
        elif lang == "" and lines and lines[0].startswith("camera "):
            found.append(("scene", "\n".join(lines) + "\n"))
    for span in re.findall(r"`(build/bin/[^`]+ [^`]+)`", readme):
        found.append(("shell", span))
    return list(dict.fromkeys(found))  # each once, in the README's order


# Validation layers on, as in every test (a message fails prism-render; prism-view's is looked
# for in its output).
ENV = {**os.environ, "PRISM_VALIDATION": "1"}


def run_shell(command, bin_dir, tmp):
    words = shlex.split(command)
    if not words[0].startswith("build/bin/"):
        return f"`{command}`: neither run nor exempted by this check (add it to one or the other)"
    tool = Path(bin_dir) / Path(words[0]).name
    args = words[1:]
    if "-o" in args:  # the output goes to the temporary folder, and must be written there
        i = args.index("-o") + 1
        out = Path(tmp) / Path(args[i]).name
        args[i] = str(out)
    else:
        out = None
    if tool.name == "prism-view":
        if shutil.which("xvfb-run") is None:
            return f"`{command}`: xvfb-run is missing (Debian: xvfb), so it cannot be tried"
        # A window stays open until closed: alive after 8 s means it started and renders.
        done = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "timeout", "8",
                               str(tool), *args], cwd=ROOT, env=ENV, capture_output=True,
                              text=True)
        if done.returncode != 124:
            return f"`{command}`: exited {done.returncode} within 8 s:\n{done.stderr}"
        if "validation" in done.stderr.lower():
            return f"`{command}`: validation messages:\n{done.stderr}"
        return None
    done = subprocess.run([str(tool), *args], cwd=ROOT, env=ENV, capture_output=True, text=True)
    if done.returncode != 0:
        return f"`{command}`: exit {done.returncode}:\n{done.stderr}"
    if out is not None and not (out.is_file() and out.stat().st_size > 0):
        return f"`{command}`: exit 0 but {out.name} was not written"
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--readme", default=str(ROOT / "README.md"))
    args = parser.parse_args()
    problems, ran = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        for kind, text in commands(Path(args.readme).read_text()):
            if kind == "scene":
                scene = Path(tmp) / "example.scene"
                scene.write_text(text)
                text = f"build/bin/prism-render {scene} -o example.png --size 160x120"
            first = text.split()[0]
            if first in EXEMPT:
                print(f"readme_commands: not run: {text} ({EXEMPT[first]})")
                continue
            problem = run_shell(text, args.bin, tmp)
            ran += 1
            if problem:
                problems.append(problem)
            print(f"readme_commands: {'FAILED' if problem else 'ok'}: {text}")
    if ran < 3:
        problems.append(f"only {ran} commands found in the README: has its layout changed?")
    for p in problems:
        print("readme_commands:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Where lavapipe's machine code spends a frame: perf on the JIT-compiled tracer.

lavapipe compiles the shader with LLVM into anonymous executable memory, which perf samples
but cannot name. This script runs prism-bench on one scene for long enough, records it with
perf, copies the executable mapping that holds most samples out of the live process (gdb),
disassembles it (objdump) and prints:
  - the loops (backward jumps) with their instruction counts and share of samples,
  - the out-of-line helpers gallivm calls (texel fetches), how many call sites, their share,
  - lane-by-lane loops (gallivm's storage-buffer reads: a loop of 8 with a branch per lane),
  - the straight-line code of the main function (what every SIMD group runs once).
With --annotate FILE it also writes the whole listing with samples per instruction.

Needs perf, gdb and objdump (Debian: linux-perf, gdb, binutils) and permission to attach
(run as root, or with kernel.perf_event_paranoid <= 1 and ptrace allowed).

  tools/scripts/perf_jit.py assets/scenes/bunny.scene
  tools/scripts/perf_jit.py --bench build/bin/prism-bench --variant auto+no-cull --depth 1 \\
      assets/scenes/teapot.scene --annotate /tmp/teapot.ann
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time


def fail(message):
    print(f"perf_jit: {message}", file=sys.stderr)
    sys.exit(1)


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene", nargs="?", help="scene file")
    p.add_argument("--selftest", action="store_true",
                   help="check the analysis on a made-up listing (no perf needed) and exit")
    p.add_argument("--bench", default="build/bin/prism-bench", help="prism-bench binary")
    p.add_argument("--variant", default="auto", help="prism-bench variant (default auto)")
    p.add_argument("--depth", type=int, default=1, help="ray depth (default 1)")
    p.add_argument("--size", default="1024x768", help="image size (default 1024x768)")
    p.add_argument("--warmup", type=float, default=6.0,
                   help="seconds to wait before recording (scene load, compile)")
    p.add_argument("--seconds", type=float, default=4.0, help="seconds to record")
    p.add_argument("--annotate", help="write the listing with samples per instruction here")
    return p.parse_args()


def record(args, workdir):
    for tool in ("perf", "gdb", "objdump"):
        if not shutil.which(tool):
            fail(f"{tool} not found (Debian: linux-perf, gdb, binutils)")
    if not os.path.exists(args.bench):
        fail(f"{args.bench}: no such binary (build first, or pass --bench)")
    bench = subprocess.Popen(
        [args.bench, "--depth", str(args.depth), "--size", args.size, "--runs", "1000",
         "--variants", args.variant, args.scene],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        time.sleep(args.warmup)
        if bench.poll() is not None:
            fail(f"prism-bench exited early: {bench.stderr.read().strip()}")
        data = os.path.join(workdir, "perf.data")
        subprocess.run(["perf", "record", "-F", "4000", "-p", str(bench.pid), "-o", data,
                        "--", "sleep", str(args.seconds)],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(f"/proc/{bench.pid}/maps") as f:
            maps = f.read().splitlines()
        script = subprocess.run(["perf", "script", "-i", data, "-F", "ip"], check=True,
                                capture_output=True, text=True).stdout
        samples = {}
        for line in script.split():
            ip = int(line, 16)
            samples[ip] = samples.get(ip, 0) + 1
        region = busiest_mapping(maps, samples)
        dump = os.path.join(workdir, "jit.bin")
        subprocess.run(["gdb", "-p", str(bench.pid), "-batch", "-ex",
                        f"dump memory {dump} {region[0]:#x} {region[1]:#x}"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    finally:
        bench.send_signal(signal.SIGTERM)
        bench.wait()
    listing = subprocess.run(["objdump", "-D", "-b", "binary", "-mi386:x86-64",
                              f"--adjust-vma={region[0]:#x}", dump],
                             check=True, capture_output=True, text=True).stdout
    return samples, region, listing


def busiest_mapping(maps, samples):
    best, best_count = None, 0
    for line in maps:
        fields = line.split()
        if len(fields) < 2 or "x" not in fields[1]:
            continue
        lo, hi = (int(x, 16) for x in fields[0].split("-"))
        count = sum(c for ip, c in samples.items() if lo <= ip < hi)
        if count > best_count:
            best, best_count = (lo, hi), count
    if best is None:
        fail("no samples in executable memory")
    return best


def instructions(listing):
    rows = []
    for line in listing.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+((?:[0-9a-f]{2} )+)\s*(.*)", line)
        if m and m.group(3).strip():
            rows.append((int(m.group(1), 16), m.group(3).strip()))
    return rows


def report(samples, region, rows, annotate=None):
    """Prints the analysis; returns its figures (loops, functions, lane share) for selftest."""
    total = sum(samples.get(a, 0) for a, _ in rows)
    everywhere = sum(samples.values())
    if total == 0:
        fail("the dumped region holds no samples")
    share = lambda n: 100.0 * n / total
    span = lambda lo, hi: sum(samples.get(a, 0) for a, _ in rows if lo <= a <= hi)
    print(f"{total} samples in the JIT region {region[0]:#x}-{region[1]:#x} "
          f"({100.0 * total / everywhere:.0f}% of all), {len(rows)} instructions")

    # Helpers: targets of `movabs $addr, %reg` inside the region, each up to its first ret.
    calls = {}
    for _, ins in rows:
        m = re.match(r"movabs \$0x([0-9a-f]+),%r", ins)
        if m and region[0] <= int(m.group(1), 16) < region[1]:
            t = int(m.group(1), 16)
            calls[t] = calls.get(t, 0) + 1
    functions = []
    for t in sorted(calls):
        end = next((a for a, ins in rows if a >= t and ins.startswith("ret")), None)
        if end is not None:
            n = sum(1 for a, _ in rows if t <= a <= end)
            functions.append((t, end, n, calls[t]))
    # The tracer itself: the largest function called (the helpers are small).
    main_start, main_end = (functions and max(functions, key=lambda f: f[2])[:2]) or \
        (rows[0][0], rows[-1][0])

    print("\nloops (backward jumps), innermost first by size:")
    loops = []
    for a, ins in rows:
        m = re.match(r"(j\w+)\s+0x([0-9a-f]+)", ins)
        if m and int(m.group(2), 16) < a:
            loops.append((int(m.group(2), 16), a))
    for lo, hi in sorted(set(loops), key=lambda l: l[1] - l[0]):
        n = sum(1 for a, _ in rows if lo <= a <= hi)
        s = span(lo, hi)
        if share(s) >= 0.5:
            print(f"  {lo:#x}-{hi:#x}: {n:5d} instructions, {share(s):5.1f}% of samples")

    print("\nout-of-line helpers (gallivm's texel fetches):")
    for t, end, n, sites in functions:
        print(f"  {t:#x}: {n:3d} instructions, {sites} call sites, "
              f"{share(span(t, end)):5.1f}% of samples")

    lane = 0
    for i, (a, ins) in enumerate(rows):
        if re.match(r"cmpl\s+\$0x0,0x[0-9a-f]+\(%rsp,%r\w+,4\)", ins) or \
           re.match(r"testb\s+\$0x1,0x[0-9a-f]+\(%rsp,%r\w+,2\)", ins):
            lane += sum(samples.get(rows[j][0], 0) for j in range(max(0, i - 8),
                                                                  min(len(rows), i + 12)))
    print(f"\nlane-by-lane loops (storage-buffer reads, atomics; approximate): "
          f"{share(lane):.1f}% of samples")

    in_loop = lambda a: any(lo <= a <= hi for lo, hi in loops)
    straight = [(a, ins) for a, ins in rows if main_start <= a <= main_end and not in_loop(a)]
    print(f"straight-line code of the main function: {len(straight)} instructions, "
          f"{share(sum(samples.get(a, 0) for a, _ in straight)):.1f}% of samples")
    divs = sum(1 for _, ins in rows if re.match(r"i?div[lq]?\s", ins))
    print(f"scalar integer divisions anywhere: {divs}")

    result = {"loops": sorted(set(loops)), "functions": functions, "lane": share(lane),
              "straight": len(straight), "divs": divs}
    if annotate:
        with open(annotate, "w") as f:
            for a, ins in rows:
                c = samples.get(a, 0)
                f.write(f"{c:6d} {share(c):5.2f}% {a:x}: {ins}\n")
        print(f"\nlisting with samples: {annotate}")
    return result


def selftest():
    """A made-up listing: a main function with a loop that calls a helper, a lane-by-lane
    loop, a division, and the helper; every figure the report gives must come out."""
    listing = """
  1000:\t48 b8 00 20 00 00 00 \tmovabs $0x2000,%rax
  1008:\t90                   \tnop
  1010:\tff d0                \tcall   *%rax
  1012:\t90                   \tnop
  1014:\t75 fa                \tjne    0x1010
  1020:\t83 7c 8c 10 00       \tcmpl   $0x0,0x10(%rsp,%rcx,4)
  1025:\t74 f9                \tje     0x1020
  1030:\tf7 f1                \tdiv    %ecx
  1032:\tc3                   \tret
  2000:\t90                   \tnop
  2001:\tc3                   \tret
"""
    rows = instructions(listing)
    samples = {0x1010: 10, 0x1012: 10, 0x1020: 5, 0x1030: 5, 0x2000: 20}
    r = report(samples, (0x1000, 0x3000), rows)
    ok = (r["loops"] == [(0x1010, 0x1014), (0x1020, 0x1025)] and
          r["functions"] == [(0x2000, 0x2001, 2, 1)] and r["divs"] == 1 and r["lane"] > 0)
    print("selftest", "passed" if ok else f"FAILED: {r}")
    return 0 if ok else 1


def main():
    args = parse_args()
    if args.selftest:
        sys.exit(selftest())
    if not args.scene:
        fail("give a scene file (or --selftest)")
    with tempfile.TemporaryDirectory() as workdir:
        samples, region, listing = record(args, workdir)
    report(samples, region, instructions(listing), args.annotate)


if __name__ == "__main__":
    main()

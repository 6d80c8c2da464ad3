#!/usr/bin/env python3
"""Process time (user + sys of /usr/bin/time) of commands, runs interleaved.

Usage: process_time.py N LABEL=COMMAND [LABEL=COMMAND ...]
Each COMMAND runs N times, in turn with the others, from the current
directory; the word OUT in it becomes a fresh temporary directory (give it
to --output-directory). Prints the median and range of the process and wall
times of each, and the load average after each round. Example, main's
binary against a branch's (doc/performance.md, "Start-up"):

  bench/startup/process_time.py 15 \\
    "main=/path/to/main/build/contact_fem prm/hertz.prm --output-directory OUT" \\
    "branch=build/contact_fem prm/hertz.prm --output-directory OUT"
"""
import os
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile


def main():
    runs = int(sys.argv[1])
    commands = [argument.split("=", 1) for argument in sys.argv[2:]]
    process = {label: [] for label, _ in commands}
    wall = {label: [] for label, _ in commands}
    loads = []
    for _ in range(runs):
        for label, command in commands:
            out = tempfile.mkdtemp()
            words = [out if word == "OUT" else word for word in shlex.split(command)]
            result = subprocess.run(["/usr/bin/time", "-f", "%U %S %e"] + words,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                    text=True)
            shutil.rmtree(out, ignore_errors=True)
            if result.returncode != 0:
                sys.exit(f"{label}: exit code {result.returncode}\n{result.stderr[-2000:]}")
            user, system, elapsed = map(float, result.stderr.strip().splitlines()[-1].split())
            process[label].append(user + system)
            wall[label].append(elapsed)
        loads.append(os.getloadavg()[0])
    for label, _ in commands:
        p, w = sorted(process[label]), sorted(wall[label])
        print(f"{label}: process time median {statistics.median(p):.3f} s "
              f"({p[0]:.2f}-{p[-1]:.2f}), wall median {statistics.median(w):.2f} s "
              f"({w[0]:.2f}-{w[-1]:.2f}); runs: {' '.join(f'{x:.2f}' for x in process[label])}")
    print("load average after each round:", " ".join(f"{x:.1f}" for x in loads))


if __name__ == "__main__":
    main()

"""The run of one contact_fem command in a bench script: timed, its console
output kept beside the run's files (out/console.txt), so that a failed or
surprising run can be read afterwards."""

import os
import subprocess
import sys
import time


def run_logged(command, out, env=None):
    """Runs command, writes its stdout and stderr to out/console.txt;
    returns the completed process and the wall time in seconds."""
    os.makedirs(out, exist_ok=True)
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.time() - start
    with open(os.path.join(out, "console.txt"), "w") as f:
        f.write(result.stdout + result.stderr)
    return result, wall


def run_or_exit(command, out, env=None):
    """run_logged(), stopping the bench with the command and the end of its
    output when it fails; returns the stdout and the wall time."""
    result, wall = run_logged(command, out, env)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({result.returncode}):\n"
                 f"{result.stdout[-3000:]}{result.stderr[-3000:]}")
    return result.stdout, wall

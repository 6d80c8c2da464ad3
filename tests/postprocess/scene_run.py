"""Running contact_fem (or a tool) from the postprocess test scripts."""
import os
import subprocess
import sys

# Open MPI refuses to run as root unless told (containers, CI).
ENVIRONMENT = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(command):
    """Runs command; stops the test with its output if it fails; returns its stdout."""
    result = subprocess.run(command, env=ENVIRONMENT, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def run_scene(contact_fem, scene, *settings, launcher=()):
    """Runs contact_fem on scene with each 'Section/Key=value' of settings
    (under the MPI launcher command, if given)."""
    command = [*launcher, contact_fem, scene]
    for setting in settings:
        command += ["--set", setting]
    return run(command)

"""Running contact_fem (or a tool) from the postprocess test scripts."""
import csv
import os
import re
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


def prints_stored_output(output, twin):
    """A scene's perturbed twin, run inside a postprocess test: output (the
    scene as it is, on DoFs renumbered by seed 1) against the scene test's
    stored output, filtered and compared as tests/run_perturbed.sh does;
    twin is (EXPECTED, NUMDIFF, NORMALIZE_PL). Writes output, expected,
    compared and diff into the working directory; True if they agree."""
    expected, numdiff, normalize = twin
    with open("output", "w") as f:
        f.write(output)
    filters = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "output_filters.sh")
    result = subprocess.run(
        ["sh", "-c", f'perl -pi "{normalize}" output && . "{filters}" && '
         f'strip_krylov_counts "{expected}" > expected && strip_krylov_counts output > compared '
         f'&& numdiff_outputs "{numdiff}" expected compared diff', "twin"])
    return result.returncode == 0


def twin_renumbering(twin):
    """The setting of the twin's run: seed 1, unless the environment's seed
    renumbers every run already (perturbation())."""
    return ("Finite element/DoF renumbering seed=1",) if twin and not perturbation() else ()


def perturbation():
    """The setting that renumbers the DoFs by CONTACT_FEM_PERTURBATION_SEED
    (as tests/run_perturbed.sh does), if that is set: a script run with
    seeds 1-3 shows whether what it checks hangs on round-off."""
    seed = os.environ.get("CONTACT_FEM_PERTURBATION_SEED")
    return (f"Finite element/DoF renumbering seed={seed}",) if seed else ()


ROW = re.compile(r"^\s*\|\s*(\d+)\s*\|\s*([^|]+)\|[^|]+\|\s*([^|]+)\|[^|]+\|\s*([^|]+)\|")


def newton_ratios(output):
    """newton_table() of the steps that converged (a step whose first
    iterate inverts an element is split and tried again)."""
    return [ratios for ratios, converged in newton_table(output) if converged]


def newton_table(output):
    """Per load step attempt: the displacement ratio of each Newton iteration (None
    where the table shows no number, or where the iteration changed the
    active set: a kink the tangent cannot see, or where the multipliers
    are still far: ratio above 0.1), and whether it converged."""
    steps = []
    for line in output.splitlines():
        if line.strip().startswith("Load step"):
            steps.append(([], False))
        if line.rstrip().endswith("| converged") and steps:
            steps[-1] = (steps[-1][0], True)
        match = ROW.match(line)
        if match and steps:
            text, changes = match.group(2).strip(), match.group(4).strip()
            try:
                value = float(text)
            except ValueError:
                value = None
            if changes not in ("0", "-"):
                value = None
            # Multipliers still far from theirs (a step's first iterate
            # after the tangential predictor): the displacement ratio alone
            # does not measure the distance to the solution there.
            try:
                if float(match.group(3)) > 0.1:
                    value = None
            except ValueError:
                pass
            steps[-1][0].append(value)
    return steps


SETS = re.compile(r"^\s*\|[^|]*(?:\|[^|]*){5}\|\s*(\d+)\s*\|\s*(\d+)\s*\|\s*(\d+)\s*\|[^|]*\|\s*converged")


def converged_sets(output):
    """(active, stick, slip) of the converged iterate of every step (the
    Newton table of a frictional formulation)."""
    return [tuple(int(g) for g in m.groups()) for m in map(SETS.match, output.splitlines()) if m]


def check_quadratic(name, output, bound):
    steps = newton_ratios(output)
    worst = 0.0
    for ratios in steps:
        for previous, current in zip(ratios, ratios[1:]):
            if previous is not None and current is not None and previous <= 0.1:
                worst = max(worst, current / previous**2)
    iterations = [len(r) - 1 for r in steps]
    ok = worst <= bound and len(steps) > 0
    print(f"{name}: {len(steps)} converged load steps, Newton iterations {iterations}; "
          f"quadratic rate "
          f"r_k <= {bound} r_(k-1)^2: {'ok' if ok else f'FAILED (largest ratio {worst:.3g})'}")
    return ok


def csv_numbers(name):
    """The rows of the CSV file name (a run's forces.csv or
    pressure_profile.csv), each a dict of its columns as numbers."""
    with open(name) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]

#!/usr/bin/env python3
"""Chooses which shared libraries contact_fem names first (cmake/loader_order.txt).

The dynamic loader resolves every symbol reference of the ~200 libraries that
deal.II pulls in by searching the global scope (the executable, then the
libraries breadth-first in DT_NEEDED order) until a library defines the
symbol: a lookup costs one hash check per library before the one that defines
it. Libraries that receive many lookups (gmsh's and OpenCASCADE's references
to their own symbols, Teuchos, ...) sit at positions 30-190. Naming them in
contact_fem's own DT_NEEDED, after its direct dependencies, moves them to the
front of the scope.

A library may only move if no symbol of any library in the scope then has
another first definition than before, except for vague-linkage copies (template instances, inline
functions, typeinfo: weak or unique in both libraries, the same source by the
one-definition rule). So BLAS/LAPACK (libopenblas.so.0 defines what
libblas.so.3 and liblapack.so.3 provide) stay where they are.

Usage: loader_order.py CONTACT_FEM PRM  (run from the source directory, on a
contact_fem built with -DCONTACT_FEM_LOADER_ORDER=OFF) prints the list on stdout:
contact_fem's own dependencies but libcontact_fem_lib.so, then the moved ones, the estimated cost (sum of the scope positions of
all lookups) on stderr. See doc/performance.md, "Start-up".
"""
import collections
import glob
import os
import re
import subprocess
import sys
import tempfile

VAGUE = set("WVu")  # nm -D types of weak and unique (vague-linkage) definitions


def loader_trace(binary, prm):
    """The global scope and the number of lookups bound to each library."""
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, LD_DEBUG="bindings,scopes", LD_DEBUG_OUTPUT=tmp + "/ld")
        subprocess.run([binary, prm, "--output-directory", tmp + "/out"], env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        # One file per process; the largest is contact_fem's own.
        trace = max(glob.glob(tmp + "/ld.*"), key=os.path.getsize)
        scope, bound = None, collections.Counter()
        binding = re.compile(r"binding file \S+ \[\d+\] to (\S+) \[\d+\]: normal symbol `([^']+)'")
        for line in open(trace):
            if scope is None and "scope 0:" in line:
                scope = line.split("scope 0:")[1].split()
            m = binding.search(line)
            if m:
                bound[m.group(1)] += 1
    return scope, bound


def definitions(path):
    """Exported symbols of a library and their nm types."""
    out = subprocess.run(["nm", "-D", "--defined-only", path], capture_output=True,
                         text=True).stdout
    result = {}
    for line in out.splitlines():
        fields = line.split()
        if len(fields) >= 2:
            result[fields[-1].split("@")[0]] = fields[-2]
    return result


def main():
    binary, prm = sys.argv[1], sys.argv[2]
    scope, bound = loader_trace(binary, prm)
    scope = [os.path.realpath(binary) if p.startswith("./") or p == binary else p
             for p in scope]
    bound = {os.path.realpath(k) if k.startswith("./") else k: v for k, v in bound.items()}
    types = {lib: definitions(lib) for lib in scope if os.path.exists(lib)}
    definers = collections.defaultdict(list)
    # Every exported symbol, looked up in this run or not (another scene may
    # call what this one does not); 'A' are version names, not symbols.
    for lib in scope:
        for s, kind in types.get(lib, {}).items():
            if kind != "A":
                definers[s].append(lib)
    shared = {s: libs for s, libs in definers.items() if len(libs) > 1}
    by_lib = collections.defaultdict(set)
    for s, libs in shared.items():
        for lib in libs:
            by_lib[lib].add(s)

    fixed = 1 + sum(1 for _ in direct_needed(binary))  # the executable and its DT_NEEDED

    def order(front):
        return scope[:fixed] + front + [l for l in scope[fixed:] if l not in front]

    def cost(libs):
        return sum(bound.get(l, 0) * i for i, l in enumerate(libs))

    def winners(libs):
        position = {l: i for i, l in enumerate(libs)}
        return lambda s: min(shared[s], key=position.__getitem__)

    before = winners(scope)

    def same_code(s, a, b):
        return a == b or (types[a].get(s) in VAGUE and types[b].get(s) in VAGUE)

    front = []
    candidates = sorted((l for l in scope[fixed:] if l in types),
                        key=lambda l: -bound.get(l, 0))
    for lib in candidates:
        if bound.get(lib, 0) < 50:
            break
        trial = front + [lib]
        after = winners(order(trial))
        touched = set().union(*(by_lib[l] for l in trial))
        if all(same_code(s, after(s), before(s)) for s in touched) and \
                cost(order(trial)) < cost(order(front)):
            front = trial
    print(f"lookups {sum(bound.values())}, scope positions summed: "
          f"{cost(scope)} before, {cost(order(front))} after", file=sys.stderr)
    # contact_fem's own dependencies keep their places (the linker would
    # otherwise put the C++ and C libraries after the list).
    for lib in direct_needed(binary)[1:] + [os.path.basename(l) for l in front]:
        print(lib)


def direct_needed(binary):
    out = subprocess.run(["readelf", "-d", binary], capture_output=True, text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


if __name__ == "__main__":
    main()

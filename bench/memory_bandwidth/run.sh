#!/usr/bin/env bash
# Memory bandwidth of one core alone and of both cores at once (triad.c):
# the ceiling of the 2-rank speed-up of bandwidth-bound sparse kernels.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binary=$(mktemp)
gcc -O2 "$here/triad.c" -o "$binary"
echo "one core:";   taskset -c 0 "$binary"
echo "two cores:";  taskset -c 0 "$binary" & taskset -c 1 "$binary"; wait
rm -f "$binary"

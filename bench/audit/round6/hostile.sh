#!/bin/bash
# Round 6: hostile values in a .prm file (blocks2d.prm with one --set each,
# written into an included file so the line is named). Each must stop with
# exit 1, a message naming the key and what was expected, and leave no
# result file behind.
B=${B:-../../../build/contact_fem}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
W=${OUT:-/tmp/a6}/hostile; rm -rf $W; mkdir -p $W
while IFS='|' read -r section key value; do
  [ -z "$section" ] && continue
  f=$W/case.prm
  { echo "include $PWD/blocks2d.prm"; echo "subsection $section" | sed 's#/#\nsubsection #g';
    echo "set $key = $value"; n=$(echo "$section" | tr -cd / | wc -c);
    for ((i = 0; i <= n; ++i)); do echo end; done; } > $f
  rm -rf $W/out
  msg=$(timeout 120 $B $f --output-directory $W/out 2>&1 >/dev/null | tail -2 | tr '\n' ' ')
  rc=$?
  rc=$(timeout 120 $B $f --output-directory $W/out >/dev/null 2>&1; echo $?)
  left=$( [ -d $W/out ] && ls $W/out | tr '\n' ' ')
  echo "[$section/$key = $value] rc=$rc files=[${left}] ${msg:0:330}"
done < "${1:-hostile_cases.txt}"

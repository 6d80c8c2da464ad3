# Sourced by the scripts that compare one scene's outputs across DoF
# numberings (run_perturbed.sh, compare_mpi_outputs.sh).
#
# strip_krylov_counts FILE: FILE without the Newton table's last column
# ('lin. it') when it has one. An iterative solve's multigrid aggregates
# follow the DoF numbering, so its Krylov counts change with the numbering
# by design, not by round-off.
strip_krylov_counts() {
  if grep -q "lin. it |" "$1"; then
    sed -E '/^    \| +[0-9]+ \|/ s/ +[-0-9]+ \|( converged.*)?$/ |\1/' "$1"
  else
    cat "$1"
  fi
}

# numdiff_outputs NUMDIFF EXPECTED COMPARED DIFF: deal.II's run_test.sh
# comparison (the tolerances and separators of deal_ii_pickup_tests).
numdiff_outputs() {
  "$1" -a 1e-6 -r 1e-8 -s ' \t\r\n=,:;<>[](){}^' "$2" "$3" > "$4"
}

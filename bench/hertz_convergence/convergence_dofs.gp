# convergence_dofs.gp - error against DoFs (energy and p_max), one line per
# strategy and degree. gnuplot -e "datadir='...'; outfile='...'" convergence_dofs.gp
xcol = 1
slopes = 1
xlabel_text = 'DoFs N'
load 'convergence_common.gp'

# convergence_time.gp - error against cumulative wall time (energy and p_max).
# gnuplot -e "datadir='...'; outfile='...'" convergence_time.gp
xcol = 2
slopes = 0
xlabel_text = 'cumulative wall time [s] (all cycles up to this one)'
load 'convergence_common.gp'

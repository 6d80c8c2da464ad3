# convergence_common.gp - shared part of convergence_dofs.gp and
# convergence_time.gp (loaded by them; not run on its own).
# Needs: datadir, outfile, xcol (column of the x value), xlabel_text.
# Data: <datadir>/q<degree>-<strategy>.dat from analyse.py, columns
#   1 dofs, 2 cumulative wall time, 3 relative energy error, 4 relative p_max
#   error (against the reference), 5 eta relative, 6 |p_max error vs Hertz|,
#   7 Pi_h < Pi_ref (1/0), 8 reference-limited (1/0).
load datadir.'/reference.gp'

set terminal pngcairo size 1500,620 enhanced font 'DejaVu Sans,11'
set output outfile
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key top right font ',9' spacing 1.1 box opaque

strategies = 'global kelly spr spr-contact'
labels     = 'global kelly spr spr\ contact'
colors     = '#555555 #e6862a #2c7fb8 #d7301f'
file(d, i) = sprintf('%s/q%d-%s.dat', datadir, d, word(strategies, i))
label(d, i) = sprintf('Q%d %s', d, i == 4 ? 'spr contact' : word(strategies, i))
color(i) = word(colors, i)
# filled circles Q1, filled squares Q2; open ones where Pi_h < Pi_ref
pt_full(d) = d == 1 ? 7 : 5
pt_open(d) = d == 1 ? 6 : 4
dash(d) = d == 1 ? 1 : 2

set multiplot layout 1,2
set xlabel xlabel_text
set ylabel 'relative energy error  (2|Π_h - Π_{ref}|)^{1/2} / |u|_E'
set title 'Energy error'
set yrange [5e-4:1]
plot for [d=1:2] for [i=1:4] file(d, i) using xcol:3 with lines lw 2 dt dash(d) lc rgb color(i) title label(d, i), \
     for [d=1:2] for [i=1:4] file(d, i) using xcol:($7 == 0 ? $3 : 1/0) with points pt pt_full(d) ps 0.9 lc rgb color(i) notitle, \
     for [d=1:2] for [i=1:4] file(d, i) using xcol:($7 == 1 ? $3 : 1/0) with points pt pt_open(d) ps 1.0 lc rgb color(i) notitle, \
     (slopes ? 4.0 * x**-0.5 : 1/0) with lines lw 1 lc rgb 'black' title (slopes ? 'N^{-1/2}' : ''), \
     (slopes ? 40.0 / x : 1/0) with lines lw 1 dt 3 lc rgb 'black' title (slopes ? 'N^{-1}' : '')
set ylabel '|p_{max,h} - p_{max,ref}| / p_{max,ref}'
set yrange [1e-5:1]
set title sprintf('p_{max} error (reference p_{max} lies %.2f %% above Hertz)', 100 * p_gap)
plot for [d=1:2] for [i=1:4] file(d, i) using xcol:4 with linespoints lw 2 dt dash(d) pt pt_full(d) ps 0.8 lc rgb color(i) title label(d, i), \
     p_res with lines lw 1 dt 4 lc rgb '#999999' title 'p_{max} reference resolution', \
     (slopes ? 1.0 * x**-0.5 : 1/0) with lines lw 1 lc rgb 'black' title (slopes ? 'N^{-1/2}' : ''), \
     (slopes ? 10.0 / x : 1/0) with lines lw 1 dt 3 lc rgb 'black' title (slopes ? 'N^{-1}' : '')
unset multiplot

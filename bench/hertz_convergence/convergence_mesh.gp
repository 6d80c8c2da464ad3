# convergence_mesh.gp - last meshes of the Q1 and Q2 'spr contact' mesh runs
# (cell outlines from analyse.py): whole domain and the contact zone.
# gnuplot -e "datadir='...'; outfile='...'" convergence_mesh.gp
load datadir.'/reference.gp'
set terminal pngcairo size 1400,1000 enhanced font 'DejaVu Sans,11'
set output outfile
set size ratio -1
unset key
set multiplot layout 2,2
do for [d=1:2] {
  f = sprintf('%s/mesh-q%d.dat', datadir, d)
  set title sprintf('Q%d spr contact: whole model', d)
  set xrange [-10.5:10.5]; set yrange [-0.5:9.5]
  plot f with lines lw 0.4 lc rgb '#202020'
  set title sprintf('Q%d spr contact: right half of the contact zone (dashed: x = a)', d)
  set xrange [-0.02:0.52]; set yrange [0.97:1.24]
  set arrow 2 from a_hertz, 0.97 to a_hertz, 1.24 nohead dt 2 lc rgb '#d7301f' lw 1.5 front
  plot f with lines lw 0.5 lc rgb '#202020'
  unset arrow 2
}
unset multiplot

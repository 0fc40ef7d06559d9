# anvil chart 'accuracy': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > accuracy.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set title 'Error of each output against wall time' noenhanced
set xlabel 'wall time (s)'
set ylabel 'relative error'
set grid
set key top right box opaque
set logscale xy
set format y '10^{%L}'
set label 1 'draft' at 0.01,0.048951 offset char 0.6,0.8 noenhanced
set label 2 'fine' at 0.4,0.001 offset char 0.6,0.8 noenhanced
set label 3 'reference' at 3.2,0.0001 offset char 0.6,0.8 noenhanced
$d1 << EOD
0.01 0.048951
0.4 0.001
3.2 0.0001
EOD
$d2 << EOD
0.01 0.000666445
0.4 8.33125e-05
3.2 9.9975e-06
EOD
$d3 << EOD
3.2 1e-05
EOD
plot $d1 using 1:2 with linespoints lw 1.5 pt 7 ps 1 lc rgb '#0072b2' title 'P_{max}', \
     $d2 using 1:2 with linespoints lw 1.5 pt 7 ps 1 lc rgb '#d55e00' title 't_s', \
     $d3 using 1:2 with linespoints lw 1.5 pt 7 ps 1 lc rgb '#009e73' title 'R_f'

# anvil chart 'accuracy': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > accuracy.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set label 1001 'Error of each output against cold wall time' at screen 0.5, screen 0.965 center font ',13'
set label 1003 'error: change to the next finer level; the finest: its own estimate' at screen 0.99, screen 0.01 right font ',9' tc rgb '#555555'
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.2833
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key at screen 0.5, screen 0.03467 center bottom horizontal maxcols 5 width -3 Left reverse box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
0.005 0.01
12.8 0.01
EOD
$d2 << EOD
0.005 0.001
12.8 0.001
EOD
$d3 << EOD
0.005 0.0001
12.8 0.0001
EOD
$d4 << EOD
0.005 1e-05
12.8 1e-05
EOD
$d5 << EOD
0.01 0.048951
EOD
$d6 << EOD
0.4 0.001
EOD
$d7 << EOD
3.2 0.0001
EOD
$d8 << EOD
0.01 0.000666445
EOD
$d9 << EOD
0.4 8.33125e-05
EOD
$d10 << EOD
3.2 9.9975e-06
EOD
$d11 << EOD
3.2 1e-05
EOD
set xlabel 'wall time, cold cache (s)'
set ylabel 'relative error'
set logscale xy
set format y '10^{%L}'
set format x '%g'
plot $d1 using 1:2 with lines lw 1.2 dt 1 lc rgb '#0072b2' notitle, \
     $d2 using 1:2 with lines lw 1.2 dt 1 lc rgb '#d55e00' notitle, \
     $d3 using 1:2 with lines lw 1.2 dt 1 lc rgb '#009e73' notitle, \
     $d4 using 1:2 with lines lw 1.2 dt 1 lc rgb '#cc79a7' notitle, \
     $d5 using 1:2 with points ps 1.6 lc rgb '#0072b2' pt 13 notitle, \
     $d6 using 1:2 with points ps 1.6 lc rgb '#009e73' pt 13 notitle, \
     $d7 using 1:2 with points ps 1.6 lc rgb '#cc79a7' pt 13 notitle, \
     $d8 using 1:2 with points ps 1.6 lc rgb '#0072b2' pt 7 notitle, \
     $d9 using 1:2 with points ps 1.6 lc rgb '#009e73' pt 7 notitle, \
     $d10 using 1:2 with points ps 1.6 lc rgb '#cc79a7' pt 7 notitle, \
     $d11 using 1:2 with points ps 1.6 lc rgb '#cc79a7' pt 5 notitle, \
     keyentry with lines lw 1.2 dt 1 lc rgb '#0072b2' title 'draft: target 0.01', \
     keyentry with lines lw 1.2 dt 1 lc rgb '#d55e00' title 'normal: target 0.001', \
     keyentry with lines lw 1.2 dt 1 lc rgb '#009e73' title 'fine: target 0.0001', \
     keyentry with lines lw 1.2 dt 1 lc rgb '#cc79a7' title 'reference: target 1e-05', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 13 title 'P_{max}', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 7 title 't_s', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 5 title 'R_f'

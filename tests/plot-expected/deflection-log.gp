# anvil chart 'deflection': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > deflection.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set label 1001 'Deflection w(t) of the layer under the impactor, V_0 = 5 m/s' at screen 0.5, screen 0.965 center font ',13'
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.19
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key at screen 0.5, screen 0.008 center bottom horizontal maxcols 5 width -3 Left reverse box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
0 0
10 0.0005
20 0
30 0.0005
40 0.00025
EOD
$d2 << EOD
0 0
10 1
20 2
30 3
40 4
EOD
set xlabel 't (µs)'
set ylabel 'deflection |w| (mm), log scale'
set xrange [0:*]
set autoscale fix
set offsets 0, graph 0.03, graph 0.05, graph 0.05
set yrange [0:*]
set logscale y
set yrange [5e-06:6]
set format y '10^{%L}'
plot $d1 using 1:2 with lines lw 6 dt 1 lc rgb '#8c8c8c' notitle, \
     $d2 using 1:2 with lines lw 2 dt 1 lc rgb '#0072b2' notitle, \
     keyentry with lines lw 2 dt 1 lc rgb '#0072b2' title 'h = 0.1 r_0', \
     keyentry with lines lw 6 dt 1 lc rgb '#8c8c8c' title 'half-space, h = ∞', \
     keyentry with lines lw 2 dt 1 lc rgb '#000000' title 'layer (transform)', \
     keyentry with lines lw 2.5 dt (1,4) lc rgb '#000000' title 'Hertz, rigid: w = 0, not drawn'

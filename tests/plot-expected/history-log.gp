# anvil chart 'history': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > history.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,1000 enhanced
} else {
	set terminal png size 800,1000 enhanced
}
set label 1001 'Contact force, impactor velocity and deflection, V_0 = 5 m/s' at screen 0.5, screen 0.965 center font ',13'
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.114
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key at screen 0.5, screen 0.008 center bottom horizontal maxcols 5 width -3 Left reverse box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
0 0
10 270
20 360
30 270
40 0
EOD
$d2 << EOD
0 10
10 6
20 2
30 -2
40 -6
EOD
$d3 << EOD
0 0
10 1
20 2
30 3
40 4
EOD
$d4 << EOD
0 0
10 3
20 4
30 3
40 0
EOD
$d5 << EOD
0 10
10 6
20 2
30 -2
40 -6
EOD
$d6 << EOD
0 0
10 1
20 2
30 3
40 4
EOD
$d7 << EOD
0 0
10 300
20 400
30 300
40 0
EOD
$d8 << EOD
0 10
10 6
20 2
30 -2
40 -6
EOD
set multiplot
# panel 1: force
set tmargin at screen 0.9
set bmargin at screen 0.651333
set ylabel 'P (kN), log'
set xrange [0:*]
set autoscale fix
set offsets 0, graph 0.03, graph 0.05, graph 0.05
set yrange [0:*]
set logscale y
set yrange [0.04:600]
set format y '10^{%L}'
set format x ''
unset xlabel
set key off
plot $d1 using 1:2 with lines lw 6 dt 1 lc rgb '#8c8c8c' notitle, \
     $d4 using 1:2 with lines lw 2 dt 1 lc rgb '#0072b2' notitle, \
     $d7 using 1:2 with lines lw 2.5 dt (1,4) lc rgb '#000000' notitle
unset logscale y
set format y '%g'
unset offsets
unset xzeroaxis
set autoscale y
# panel 2: velocity
set tmargin at screen 0.631333
set bmargin at screen 0.382667
unset label
set ylabel 'v (m/s)'
set xrange [0:*]
set autoscale fix
set offsets 0, graph 0.03, graph 0.05, graph 0.05
set xzeroaxis lt -1 lw 1
set format x ''
unset xlabel
set key off
plot $d2 using 1:2 with lines lw 6 dt 1 lc rgb '#8c8c8c' notitle, \
     $d5 using 1:2 with lines lw 2 dt 1 lc rgb '#0072b2' notitle, \
     $d8 using 1:2 with lines lw 2.5 dt (1,4) lc rgb '#000000' notitle
unset offsets
unset xzeroaxis
set autoscale y
# panel 3: deflection
set tmargin at screen 0.362667
set bmargin at screen 0.114
unset label
set ylabel 'w (µm)'
set xrange [0:*]
set autoscale fix
set offsets 0, graph 0.03, graph 0.05, graph 0.05
set yrange [0:*]
set format x '%g'
set xlabel 't (µs)'
set key on
plot $d3 using 1:2 with lines lw 6 dt 1 lc rgb '#8c8c8c' notitle, \
     $d6 using 1:2 with lines lw 2 dt 1 lc rgb '#0072b2' notitle, \
     keyentry with lines lw 2 dt 1 lc rgb '#0072b2' title 'h = 0.1 r_0', \
     keyentry with lines lw 6 dt 1 lc rgb '#8c8c8c' title 'half-space, h = ∞', \
     keyentry with lines lw 2 dt 1 lc rgb '#000000' title 'layer (transform)', \
     keyentry with lines lw 2.5 dt (1,4) lc rgb '#000000' title 'Hertz, rigid layer (w = 0)'
unset offsets
unset xzeroaxis
set autoscale y
unset multiplot

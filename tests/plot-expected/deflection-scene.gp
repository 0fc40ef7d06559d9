# anvil chart 'deflection': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > deflection.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 640,400 enhanced font 'Serif,9'''
} else {
	set terminal png size 640,400 enhanced font 'Serif,9'''
}
set label 1001 'it''s "x" system("touch /tmp/pwned") `touch /tmp/pwned` @GPVAL ^_{}\' at screen 0.5, screen 0.965 center font ',13' noenhanced
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.335
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key at screen 0.5, screen 0.008 center bottom horizontal maxcols 5 width -3 Left reverse box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
0 0
11 1.1
22 2.2
33 3.3
44 4.4
EOD
$d2 << EOD
0 0
8 0.8
16 1.6
24 2.4
32 3.2
EOD
$d3 << EOD
0 0
9 0.9
18 1.8
27 2.7
36 3.6
EOD
set xlabel 't (µs)'
set ylabel 'deflection w (µm), + into the layer'
set xrange [0:*]
set autoscale fix
set offsets 0, graph 0.03, graph 0.05, graph 0.05
set yrange [0:*]
plot $d1 using 1:2 with lines lw 6 dt 1 lc rgb '#8c8c8c' notitle, \
     $d2 using 1:2 with lines lw 2 dt 1 lc rgb '#009e73' notitle, \
     $d3 using 1:2 with lines lw 2 dt (9,5) lc rgb '#0072b2' notitle, \
     keyentry with lines lw 2 dt 1 lc rgb '#009e73' title 'h = 5 r_0', \
     keyentry with lines lw 6 dt 1 lc rgb '#8c8c8c' title 'half-space, h = ∞', \
     keyentry with lines lw 2 dt 1 lc rgb '#0072b2' title 'h = 1 r_0', \
     keyentry with lines lw 2 dt 1 lc rgb '#000000' title 'layer (transform)', \
     keyentry with lines lw 2 dt (9,5) lc rgb '#000000' title 'Zener''s plate', \
     keyentry with lines lw 2.5 dt (1,4) lc rgb '#000000' title 'Hertz, rigid: w = 0, not drawn'

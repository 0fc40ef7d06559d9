# anvil chart 'force': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > force.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set title 'Contact force, V0 = 10 m/s' noenhanced
set xlabel 't (µs)'
set ylabel 'P (kN)'
set grid
set key top right box opaque
set xrange [0:*]
set yrange [0:*]
set offsets 0, 0, graph 0.2, 0
$d1 << EOD
0 0
10 3
20 4
30 3
40 0
EOD
$d2 << EOD
0 0
8 2.4
16 3.2
24 2.4
32 0
EOD
$d3 << EOD
0 0
11 3.3
22 4.4
33 3.3
44 0
EOD
$d4 << EOD
0 0
9 2.7
18 3.6
27 2.7
36 0
EOD
$d5 << EOD
0 0
12 3.6
24 4.8
36 3.6
48 0
EOD
plot $d1 using 1:2 with lines lw 2 lc rgb '#0072b2' title 'layer, h = 1 r_0', \
     $d2 using 1:2 with lines lw 2 lc rgb '#d55e00' title 'layer, h = 5 r_0', \
     $d3 using 1:2 with lines lw 2 lc rgb '#009e73' title 'half-space', \
     $d4 using 1:2 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'Zener, h = 1 r_0', \
     $d5 using 1:2 with lines lw 1 lc rgb '#808080' title 'quasi-static Hertz'

# anvil chart 'deflection': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > deflection.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 640,400 enhanced font 'Serif,9'''
} else {
	set terminal png size 640,400 enhanced font 'Serif,9'''
}
set title 'it''s "x" system("touch /tmp/pwned") `touch /tmp/pwned` @GPVAL ^_{}\' noenhanced
set xlabel 't (µs)'
set ylabel 'w (µm)'
set grid
set key top left box opaque
set xrange [0:*]
set offsets 0, 0, graph 0.2, 0
$d1 << EOD
0 0
8 0.8
16 1.6
24 2.4
32 3.2
EOD
$d2 << EOD
0 0
11 1.1
22 2.2
33 3.3
44 4.4
EOD
$d3 << EOD
0 0
9 0.9
18 1.8
27 2.7
36 3.6
EOD
$d4 << EOD
0 0
12 1.2
24 2.4
36 3.6
48 4.8
EOD
plot $d1 using 1:2 with lines lw 2 lc rgb '#0072b2' title 'layer', \
     $d2 using 1:2 with lines lw 2 lc rgb '#d55e00' title 'half-space', \
     $d3 using 1:2 with lines lw 1.5 dt 2 lc rgb '#009e73' title 'Zener', \
     $d4 using 1:2 with lines lw 1 lc rgb '#808080' title 'quasi-static Hertz, w = 0'

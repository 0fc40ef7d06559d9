# anvil chart 'restitution-thickness': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > restitution-thickness.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set title 'Coefficient of restitution against layer thickness' noenhanced
set xlabel 'h / r_0'
set ylabel 'R_f'
set grid
set key bottom right box opaque
set logscale x
set xrange [0.5:20]
set xtics (0.5, 1, 2, 5, 10, 20)
set yrange [0:1.05]
$d1 << EOD
1 0.344
2 0.77
EOD
$d2 << EOD
0.5 0.02
1 0.34
2 0.76
5 0.96
20 0.997
EOD
$d3 << EOD
1 0.177
2 0.657
EOD
$d4 << EOD
0.5 0.991
20 0.991
EOD
$d5 << EOD
0.5 0.003
1 0.18
2 0.65
5 0.93
20 0.995
EOD
plot $d1 using 1:2 with linespoints lw 1.5 pt 7 ps 1 lc rgb '#0072b2' title 'layer, V_0 = 10 m/s', \
     $d2 using 1:2 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'Zener R_f^*, V_0 = 10 m/s', \
     $d3 using 1:2 with linespoints lw 1.5 pt 7 ps 1 lc rgb '#d55e00' title 'layer, V_0 = 100 m/s', \
     $d4 using 1:2 with lines lw 1.5 dt 3 lc rgb '#d55e00' title 'half-space, V_0 = 100 m/s', \
     $d5 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'Zener R_f^*, V_0 = 100 m/s'

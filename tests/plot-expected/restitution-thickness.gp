# anvil chart 'restitution-thickness': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > restitution-thickness.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set label 1001 'Coefficient of restitution R_f against layer thickness h' at screen 0.5, screen 0.965 center font ',13'
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.1067
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key inside bottom right vertical Left reverse width 1 box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
1 0.344
1.5 0.6
2 0.77
EOD
$d2 << EOD
1 0.344
2 0.77
EOD
$d3 << EOD
0.5 0.02
1 0.34
2 0.76
5 0.96
20 0.997
EOD
$d4 << EOD
1 0.177
2 0.657
EOD
$d5 << EOD
0.5 0.991
45 0.991
EOD
$d6 << EOD
0.5 0.003
1 0.18
2 0.65
5 0.93
20 0.995
EOD
$d7 << EOD
1 0.344
EOD
$d8 << EOD
30 0
30 1.05
EOD
set xlabel 'layer thickness h / r_0'
set ylabel 'coefficient of restitution R_f'
set logscale x
set xrange [0.5:20]
set xtics (0.5, 1, 2, 5, 10, 20)
set yrange [0:1.05]
set xrange [0.5:45]
set tmargin at screen 0.78
set x2tics (2, 5, 10, 20, 50, 100) nomirror
set logscale x2
set x2range [2:180]
set xtics nomirror
set border 7
set x2label 'h (mm), with r_0 = 4 mm'
set label 1 'this scene: h = 30 r_0' at 30,0.5 right offset char -0.7,0.8 font ',9' tc rgb '#cc79a7' front
plot $d1 using 1:2 with lines lw 2 dt 1 lc rgb '#000000' notitle, \
     $d2 using 1:2 with points ps 1.6 lc rgb '#000000' pt 13 notitle, \
     $d3 using 1:2 with lines lw 2 dt (9,5) lc rgb '#000000' notitle, \
     $d4 using 1:2 with linespoints lw 1.2 ps 1.3 lc rgb '#000000' pt 7 notitle, \
     $d5 using 1:2 with lines lw 2.5 dt (1,4) lc rgb '#000000' notitle, \
     $d6 using 1:2 with lines lw 2 dt (9,5) lc rgb '#000000' notitle, \
     $d7 using 1:2 with points ps 2.3 lw 1.5 lc rgb '#0072b2' pt 12 notitle, \
     $d8 using 1:2 with lines lw 1.2 dt 1 lc rgb '#cc79a7' notitle, \
     keyentry with lines lw 2 dt 1 lc rgb '#000000' title 'layer, through anvil''s points', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 13 title 'V_0 = 10 m/s (anvil)', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 7 title 'V_0 = 100 m/s (anvil)', \
     keyentry with lines lw 2 dt (9,5) lc rgb '#000000' title 'Zener''s R_f^* = exp(-1.7191 λ^*), eq. (54)', \
     keyentry with lines lw 2.5 dt (1,4) lc rgb '#000000' title 'half-space (h = ∞)', \
     keyentry with points ps 2.3 lw 1.5 lc rgb '#000000' pt 12 title 'paper''s printed values (Tables 2-3)'

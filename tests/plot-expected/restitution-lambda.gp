# anvil chart 'restitution-lambda': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > restitution-lambda.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set label 1001 'Coefficient of restitution R_f against Zener''s λ^* (the paper''s Fig. 9)' at screen 0.5, screen 0.965 center font ',13'
set label 1003 'markers coloured and labelled by h / r_0; λ^* on a log axis' at screen 0.99, screen 0.01 right font ',9' tc rgb '#555555'
set lmargin at screen 0.11
set rmargin at screen 0.965
set tmargin at screen 0.9
set bmargin at screen 0.1333
set grid lc rgb '#dddddd'
set tics out nomirror
set border 3
set key inside bottom left vertical Left reverse width 1 box lc rgb '#bbbbbb' lw 1 opaque samplen 3.5 spacing 1.1 font ',10'
$d1 << EOD
0.001 0.998282
0.00109274 0.998123
0.00119407 0.997949
0.0013048 0.997759
0.00142581 0.997552
0.00155803 0.997325
0.00170251 0.997077
0.0018604 0.996807
0.00203292 0.996511
0.00222145 0.996188
0.00242745 0.995836
0.00265257 0.99545
0.00289855 0.995029
0.00316735 0.99457
0.00346108 0.994068
0.00378204 0.993519
0.00413277 0.992921
0.00451603 0.992267
0.00493483 0.991552
0.00539246 0.990773
0.00589254 0.989921
0.00643898 0.988992
0.00703611 0.987977
0.0076886 0.986869
0.00840161 0.985661
0.00918074 0.984341
0.0100321 0.982902
0.0109625 0.981331
0.0119791 0.979617
0.01309 0.977748
0.0143039 0.97571
0.0156303 0.973488
0.0170798 0.971065
0.0186637 0.968424
0.0203945 0.965547
0.0222858 0.962413
0.0243525 0.959
0.0266109 0.955284
0.0290786 0.95124
0.0317753 0.94684
0.034722 0.942056
0.0379419 0.936856
0.0414605 0.931206
0.0453054 0.925071
0.0495068 0.918414
0.0540978 0.911194
0.0591146 0.903369
0.0645967 0.894896
0.0705871 0.885727
0.077133 0.875816
0.084286 0.865112
0.0921023 0.853565
0.100643 0.841124
0.109977 0.827736
0.120175 0.81335
0.13132 0.797916
0.143498 0.781385
0.156805 0.763712
0.171347 0.744857
0.187237 0.724786
0.2046 0.703471
0.223574 0.680896
0.244307 0.657054
0.266963 0.631955
0.291721 0.605624
0.318773 0.578103
0.348335 0.549458
0.380638 0.519777
0.415937 0.489174
0.454509 0.457789
0.496658 0.425792
0.542716 0.393378
0.593045 0.360774
0.648042 0.328227
0.708138 0.29601
0.773808 0.26441
0.845568 0.233724
0.923982 0.204249
1.00967 0.176273
1.1033 0.150066
EOD
$d2 << EOD
0.001 1
0.5 0.43
1.1 0.16
EOD
$d3 << EOD
0.633 0.344
EOD
$d4 << EOD
0.158 0.768
EOD
$d5 << EOD
0.025 0.965
EOD
$d6 << EOD
0.0063 0.998
EOD
$d7 << EOD
0.001 1
EOD
$d8 << EOD
1.003 0.177
EOD
$d9 << EOD
0.251 0.657
EOD
$d10 << EOD
0.04 0.935
EOD
$d11 << EOD
0.01 0.986
EOD
$d12 << EOD
0.001 0.991
EOD
$d13 << EOD
0.1582 0.768
EOD
set xlabel 'Zener''s inelasticity parameter λ^*'
set ylabel 'coefficient of restitution R_f'
set yrange [0:1.08]
set logscale x
set xrange [0.001:1.1033]
set format x '%g'
set label 1 '1 r_0' at 0.633,0.344 left offset char 0.7,0.8 font ',9' tc rgb '#0072b2' front
set label 2 '2 r_0' at 0.158,0.768 left offset char 0.7,0.8 font ',9' tc rgb '#d55e00' front
set label 3 '5 r_0' at 0.025,0.965 left offset char 0.7,0.8 font ',9' tc rgb '#009e73' front
set label 4 '10 r_0' at 0.0063,0.998 left offset char 0.7,0.8 font ',9' tc rgb '#cc79a7' front
set label 5 '1 r_0' at 1.003,0.177 left offset char 0.7,-0.9 font ',9' tc rgb '#0072b2' front
set label 6 '2 r_0' at 0.251,0.657 left offset char 0.7,-0.9 font ',9' tc rgb '#d55e00' front
set label 7 '5 r_0' at 0.04,0.935 left offset char 0.7,-0.9 font ',9' tc rgb '#009e73' front
set label 8 '10 r_0' at 0.01,0.986 left offset char 0.7,-0.9 font ',9' tc rgb '#cc79a7' front
set label 9 'half-space, λ^* = 0' at 0.001,0.9 left offset char 0.7,0.8 font ',9' tc rgb '#000000' front
plot $d1 using 1:2 with lines lw 2 dt 1 lc rgb '#000000' notitle, \
     $d2 using 1:2 with lines lw 1.5 dt (12,4,2,4) lc rgb '#000000' notitle, \
     $d3 using 1:2 with points ps 1.6 lc rgb '#0072b2' pt 13 notitle, \
     $d4 using 1:2 with points ps 1.6 lc rgb '#d55e00' pt 13 notitle, \
     $d5 using 1:2 with points ps 1.6 lc rgb '#009e73' pt 13 notitle, \
     $d6 using 1:2 with points ps 1.6 lc rgb '#cc79a7' pt 13 notitle, \
     $d7 using 1:2 with points ps 1.6 lc rgb '#000000' pt 13 notitle, \
     $d8 using 1:2 with points ps 1.6 lc rgb '#0072b2' pt 7 notitle, \
     $d9 using 1:2 with points ps 1.6 lc rgb '#d55e00' pt 7 notitle, \
     $d10 using 1:2 with points ps 1.6 lc rgb '#009e73' pt 7 notitle, \
     $d11 using 1:2 with points ps 1.6 lc rgb '#cc79a7' pt 7 notitle, \
     $d12 using 1:2 with points ps 1.6 lc rgb '#000000' pt 7 notitle, \
     $d13 using 1:2 with points ps 2.3 lw 1.5 lc rgb '#d55e00' pt 12 notitle, \
     keyentry with lines lw 2 dt 1 lc rgb '#000000' title 'Zener''s fit R_f^* = exp(-1.7191 λ^*), eq. (54)', \
     keyentry with lines lw 1.5 dt (12,4,2,4) lc rgb '#000000' title 'Zener''s ODE (49), solved', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 13 title 'V_0 = 10 m/s (anvil)', \
     keyentry with points ps 1.6 lc rgb '#000000' pt 7 title 'V_0 = 100 m/s (anvil)', \
     keyentry with points ps 2.3 lw 1.5 lc rgb '#000000' pt 12 title 'paper''s printed values (Tables 2-3)'

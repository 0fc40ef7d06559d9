# anvil chart 'restitution-lambda': a gnuplot script with its data inline.
# Render with: gnuplot THIS_FILE > restitution-lambda.png
set encoding utf8
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
	set terminal pngcairo size 800,600 enhanced
} else {
	set terminal png size 800,600 enhanced
}
set title 'Coefficient of restitution against Zener''s λ*' noenhanced
set xlabel 'λ^*'
set ylabel 'R_f'
set grid
set key top right box opaque
set xrange [0:*]
set yrange [0:1.05]
$d1 << EOD
0 1
0.02 0.966202
0.04 0.933547
0.06 0.901995
0.08 0.87151
0.1 0.842055
0.12 0.813595
0.14 0.786098
0.16 0.75953
0.18 0.733859
0.2 0.709057
0.22 0.685092
0.24 0.661938
0.26 0.639566
0.28 0.61795
0.3 0.597065
0.32 0.576885
0.34 0.557388
0.36 0.538549
0.38 0.520348
0.4 0.502761
0.42 0.485769
0.44 0.469351
0.46 0.453488
0.48 0.438161
0.5 0.423353
0.52 0.409044
0.54 0.395219
0.56 0.381862
0.58 0.368956
0.6 0.356486
0.62 0.344438
0.64 0.332797
0.66 0.321549
0.68 0.310681
0.7 0.300181
0.72 0.290035
0.74 0.280233
0.76 0.270762
0.78 0.261611
0.8 0.252769
0.82 0.244226
0.84 0.235972
0.86 0.227996
0.88 0.220291
0.9 0.212845
0.92 0.205652
0.94 0.198701
0.96 0.191985
0.98 0.185497
1 0.179227
1.02 0.17317
1.04 0.167317
1.06 0.161662
1.08 0.156198
1.1 0.150919
EOD
$d2 << EOD
0 1
0.5 0.43
1.1 0.16
EOD
$d3 << EOD
0.633 0.344
0.158 0.768
0.025 0.965
0.0063 0.998
0 1
EOD
$d4 << EOD
1.003 0.177
0.251 0.657
0.04 0.935
0.01 0.986
0 0.991
EOD
plot $d1 using 1:2 with lines lw 2 lc rgb '#000000' title 'Zener''s fit R_f^* = exp(-1.7191 λ^*), eq. (54)', \
     $d2 using 1:2 with lines lw 1 lc rgb '#808080' title 'Zener''s ODE (49)', \
     $d3 using 1:2 with points pt 13 ps 1.8 lc rgb '#0072b2' title 'layer and half-space, V_0 = 10 m/s', \
     $d4 using 1:2 with points pt 7 ps 1.5 lc rgb '#d55e00' title 'layer and half-space, V_0 = 100 m/s'

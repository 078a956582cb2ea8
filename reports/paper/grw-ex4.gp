# gdsmc 0.3.0 verify: scene verify/scenes/grw-ex4.ini, seed 20030329, n = 64, 256, 1024, 4096, 16384 (by row), N = 10000 ensembles, 81 outputs on [0, 8]
# grw-ex4: paper A Table 2 reproduced (paper sizes): gnuplot /tmp/paper-run/out/grw-ex4.gp
set terminal pngcairo size 1200,900 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/grw-ex4.png'
set datafile separator ','
set xrange [2:*]
set xlabel 't'
set ylabel 'T_raw'
set key top right
set multiplot layout 2,2 title 'grw-ex4: paper A Table 2 reproduced (paper sizes)'
set title 'n = 64'
plot '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_exact', '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:($3-$4):($3+$4) with filledcurves fs transparent solid 0.25 lc 1 title 'n = 64: mean ± c'
set title 'n = 256'
plot '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_exact', '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:($5-$6):($5+$6) with filledcurves fs transparent solid 0.25 lc 2 title 'n = 256: mean ± c'
set title 'n = 1024'
plot '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_exact', '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:($7-$8):($7+$8) with filledcurves fs transparent solid 0.25 lc 3 title 'n = 1024: mean ± c'
set title 'n = 4096'
plot '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_exact', '/tmp/paper-run/out/grw-ex4-curves.csv' skip 1 using 1:($9-$10):($9+$10) with filledcurves fs transparent solid 0.25 lc 4 title 'n = 4096: mean ± c'
unset multiplot

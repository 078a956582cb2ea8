# gdsmc 0.3.0 verify: scene verify/scenes/brs-ex3.ini, seed 20100403, n = 4, 16, 64, 256, 1024 (by row), N = 64, 256, 1024, 4096, 16384 ensembles (by row), 513 outputs on [0, 1]
# brs-ex3: paper B Maxwell kernels, relaxation (paper sizes): gnuplot /tmp/paper-run/out/brs-ex3-uy.gp
set terminal pngcairo size 1200,900 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/brs-ex3-uy.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'uy'
set key top right
set multiplot layout 2,2 title 'brs-ex3: paper B Maxwell kernels, relaxation (paper sizes)'
set title 'n = 4'
plot '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'uy_exact', '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:($3-$4):($3+$4) with filledcurves fs transparent solid 0.25 lc 1 title 'n = 4: mean ± c'
set title 'n = 16'
plot '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'uy_exact', '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:($5-$6):($5+$6) with filledcurves fs transparent solid 0.25 lc 2 title 'n = 16: mean ± c'
set title 'n = 64'
plot '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'uy_exact', '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:($7-$8):($7+$8) with filledcurves fs transparent solid 0.25 lc 3 title 'n = 64: mean ± c'
set title 'n = 256'
plot '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'uy_exact', '/tmp/paper-run/out/brs-ex3-uy-curves.csv' skip 1 using 1:($9-$10):($9+$10) with filledcurves fs transparent solid 0.25 lc 4 title 'n = 256: mean ± c'
unset multiplot

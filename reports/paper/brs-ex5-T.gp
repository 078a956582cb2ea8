# gdsmc 0.3.0 verify: scene verify/scenes/brs-ex5.ini, seed 20101436, 20102436, 20103436 (by row), n = 64, 256, 1024 (by row), N = 1024, 256, 64 ensembles (by row), 513 outputs on [0, 2]
# brs-ex5: paper B, hard spheres, steady temperature (paper sizes): gnuplot /tmp/paper-run/out/brs-ex5-T.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/brs-ex5-T.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'T'
set key top right
set title 'brs-ex5: paper B, hard spheres, steady temperature (paper sizes)'
plot '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_le', '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:3 with lines dt 2 lw 2 title 'T_grad', '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc 1 title 'n = 64: mean ± c', '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc 2 title 'n = 256: mean ± c', '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc 3 title 'n = 1024: mean ± c', '/tmp/paper-run/out/brs-ex5-T-curves.csv' skip 1 using 1:($10-$11):($10+$11) with filledcurves fs transparent solid 0.25 lc 4 title 'n = infinity (O(1/n) extrapolation) ± c'

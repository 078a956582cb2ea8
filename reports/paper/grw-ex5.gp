# gdsmc 0.3.0 verify: scene verify/scenes/grw-ex5.ini, seed 20030330, n = 64, 256, 1024, 4096 (by row), N = 1000 ensembles, 81 outputs on [0, 4]
# grw-ex5: paper A Ex 5, heated hard spheres (paper sizes): gnuplot /tmp/paper-run/out/grw-ex5.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/grw-ex5.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'T'
set key top right
set title 'grw-ex5: paper A Ex 5, heated hard spheres (paper sizes)'
plot '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 title 'T_maxwell_closure', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:3 with lines dt 2 lw 2 title 'T_sonine_closure', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc 1 title 'n = 64: mean ± c', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc 2 title 'n = 256: mean ± c', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc 3 title 'n = 1024: mean ± c', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:($10-$11):($10+$11) with filledcurves fs transparent solid 0.25 lc 4 title 'n = 4096: mean ± c', '/tmp/paper-run/out/grw-ex5-curves.csv' skip 1 using 1:($12-$13):($12+$13) with filledcurves fs transparent solid 0.25 lc 5 title 'n = infinity (O(1/n) extrapolation) ± c'

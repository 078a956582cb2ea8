# gdsmc 0.3.0 verify: scene verify/cases/scenes/grw-ex5.ini, seed 20030330, n = 64, 256, 1024, 4096 (by row), N = 1000 ensembles, 81 outputs on [0, 4]
# grw-ex5: paper A Ex 5, heated hard spheres (paper sizes): gnuplot reports/paper/grw-ex5.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output 'reports/paper/grw-ex5.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'T'
set key below
set title 'grw-ex5: paper A Ex 5, heated hard spheres (paper sizes)'
plot 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_maxwell_closure', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:3 with lines dt 3 lw 2 lc rgb '#000000' title 'T_sonine_closure', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc rgb '#0072b2' title 'n = 64: mean ± 3.2 standard errors', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:4 with lines lw 1 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc rgb '#d55e00' title 'n = 256: mean ± 3.2 standard errors', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:6 with lines lw 1 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc rgb '#cc79a7' title 'n = 1024: mean ± 3.2 standard errors', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:8 with lines lw 1 dt 1 lc rgb '#cc79a7' notitle, 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:($10-$11):($10+$11) with filledcurves fs transparent solid 0.25 lc rgb '#e69f00' title 'n = 4096: mean ± 3.2 standard errors', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:10 with lines lw 1 dt 1 lc rgb '#e69f00' notitle, 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:($12-$13):($12+$13) with filledcurves fs transparent solid 0.25 lc rgb '#56b4e9' title 'n = infinity (O(1/n) extrapolation) ± 3.2 standard errors', 'reports/paper/grw-ex5-curves.csv' skip 1 using 1:12 with lines lw 1 dt 1 lc rgb '#56b4e9' notitle

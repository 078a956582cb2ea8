# gdsmc 0.3.0 verify: scene verify/cases/scenes/brs-ex5.ini, seed 20101436, 20102436, 20103436 (by row), n = 64, 256, 1024 (by row), N = 1024, 256, 64 ensembles (by row), 513 outputs on [0, 2]
# brs-ex5: T(t), each n and n = infinity, beside the closures (paper sizes): gnuplot reports/paper/brs-ex5-T.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output 'reports/paper/brs-ex5-T.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'T'
set key below
set title 'brs-ex5: T(t), each n and n = infinity, beside the closures (paper sizes)'
plot 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:2 with lines dt 2 lw 2 lc rgb '#000000' title 'T_le', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:3 with lines dt 3 lw 2 lc rgb '#000000' title 'T_grad', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc rgb '#0072b2' title 'n = 64: mean ± 3.2 standard errors', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:4 with lines lw 1 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc rgb '#d55e00' title 'n = 256: mean ± 3.2 standard errors', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:6 with lines lw 1 dt 1 lc rgb '#d55e00' notitle, 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc rgb '#cc79a7' title 'n = 1024: mean ± 3.2 standard errors', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:8 with lines lw 1 dt 1 lc rgb '#cc79a7' notitle, 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:($10-$11):($10+$11) with filledcurves fs transparent solid 0.25 lc rgb '#e69f00' title 'n = infinity (O(1/n) extrapolation) ± 3.2 standard errors', 'reports/paper/brs-ex5-T-curves.csv' skip 1 using 1:10 with lines lw 1 dt 1 lc rgb '#e69f00' notitle

# gdsmc 0.3.0 verify: scene verify/cases/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-sonine: Sonine coefficients b'_k against alpha (paper D Fig. 4): gnuplot reports/paper/msg-sonine.gp
set terminal pngcairo size 1200,650 font ',10'
set termoption noenhanced
set output 'reports/paper/msg-sonine.png'
set datafile separator ','
set title 'msg-sonine: Sonine coefficients b''_k against alpha (paper D Fig. 4)'
set xlabel 'alpha'
set ylabel 'b''_k'
set key outside right top
set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
plot 'reports/paper/msg-sonine-points.csv' skip 1 using 1:2:3 with yerrorbars pt 7 lc rgb '#0072b2' title 'b''_1 (eps* 0.025) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:4:5 with yerrorbars pt 6 lc rgb '#0072b2' title 'b''_1 (eps* 0.05) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:6:7 with yerrorbars pt 7 lc rgb '#d55e00' title 'b''_2 (eps* 0.025) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:8:9 with yerrorbars pt 6 lc rgb '#d55e00' title 'b''_2 (eps* 0.05) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:10:11 with yerrorbars pt 7 lc rgb '#cc79a7' title 'b''_3 (eps* 0.025) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:12:13 with yerrorbars pt 6 lc rgb '#cc79a7' title 'b''_3 (eps* 0.05) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:14:15 with yerrorbars pt 7 lc rgb '#009e73' title 'b''_2 from c_x (eps* 0.025) ± 3.2 standard errors', 'reports/paper/msg-sonine-points.csv' skip 1 using 1:16:17 with yerrorbars pt 6 lc rgb '#009e73' title 'b''_2 from c_x (eps* 0.05) ± 3.2 standard errors'

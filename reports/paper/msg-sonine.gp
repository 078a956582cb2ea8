# gdsmc 0.3.0 verify: scene verify/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-sonine: Sonine coefficients b'_k against alpha (paper D Fig. 4): gnuplot /tmp/paper-run/out/msg-sonine.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/msg-sonine.png'
set datafile separator ','
set title 'msg-sonine: Sonine coefficients b''_k against alpha (paper D Fig. 4)'
set xlabel 'alpha'
set ylabel 'b''_k'
set key top right
plot '/tmp/paper-run/out/msg-sonine-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title 'b''_1 ± c', '/tmp/paper-run/out/msg-sonine-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 title 'b''_2 ± c', '/tmp/paper-run/out/msg-sonine-points.csv' skip 1 using 1:6:7 with yerrorbars pt 9 title 'b''_3 ± c', '/tmp/paper-run/out/msg-sonine-points.csv' skip 1 using 1:8:9 with yerrorbars pt 11 title 'b''_2 from c_x ± c'

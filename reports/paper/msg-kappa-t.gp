# gdsmc 0.3.0 verify: scene verify/scenes/msg.ini, seed 20070301, n = 200000, N = 16 ensembles, 201 outputs on [0, 40]
# msg-kappa: kappa'(t)/kappa0 (paper D Fig. 1), rows in order: gnuplot /tmp/paper-run/out/msg-kappa-t.gp
set terminal pngcairo size 1200,700 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/msg-kappa-t.png'
set datafile separator ','
set xrange [0:*]
set xlabel 't'
set ylabel 'kappa''/kappa0'
set key top right
set title 'msg-kappa: kappa''(t)/kappa0 (paper D Fig. 1), rows in order'
plot '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($2-$3):($2+$3) with filledcurves fs transparent solid 0.25 lc 1 title 'alpha = 0.3, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($4-$5):($4+$5) with filledcurves fs transparent solid 0.25 lc 2 title 'alpha = 0.3, eps* = 0.05: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($6-$7):($6+$7) with filledcurves fs transparent solid 0.25 lc 3 title 'alpha = 0.4, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($8-$9):($8+$9) with filledcurves fs transparent solid 0.25 lc 4 title 'alpha = 0.5, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($10-$11):($10+$11) with filledcurves fs transparent solid 0.25 lc 5 title 'alpha = 0.6, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($12-$13):($12+$13) with filledcurves fs transparent solid 0.25 lc 6 title 'alpha = 0.7, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($14-$15):($14+$15) with filledcurves fs transparent solid 0.25 lc 7 title 'alpha = 0.8, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($16-$17):($16+$17) with filledcurves fs transparent solid 0.25 lc 8 title 'alpha = 0.9, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($18-$19):($18+$19) with filledcurves fs transparent solid 0.25 lc 9 title 'alpha = 1.0, eps* = 0.025: mean ± c', '/tmp/paper-run/out/msg-kappa-t-curves.csv' skip 1 using 1:($20-$21):($20+$21) with filledcurves fs transparent solid 0.25 lc 10 title 'alpha = 1.0, eps* = 0.05: mean ± c'

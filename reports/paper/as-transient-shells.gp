# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 701 outputs on [0, 700], 321 outputs on [0, 16], 701 outputs on [0, 700] (by row)
# paper E Fig. 13: the shell ratios R0..R3 against s at a tau0 = 4 (EHS: s'/beta): gnuplot /tmp/paperfix/as-transient-shells.gp
set terminal pngcairo size 1000,1380 font ',10'
set termoption noenhanced
set output '/tmp/paperfix/as-transient-shells.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 4,1 title 'paper E Fig. 13: the shell ratios R0..R3 against s at a tau0 = 4 (EHS: s''/beta)'
set logscale x
set key outside right top
set grid
set xlabel 's'
set ylabel 'R0'
plot '/tmp/paperfix/as-transient-shells-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'ihs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'ehs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'ihs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 1 lc 4 title 'ehs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc 5 title 'ihs alpha=0.9 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc 6 title 'ehs alpha=0.9 a_tau0=4'
set xlabel 's'
set ylabel 'R1'
plot '/tmp/paperfix/as-transient-shells-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc 1 title 'ihs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc 2 title 'ehs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc 3 title 'ihs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 1 lc 4 title 'ehs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc 5 title 'ihs alpha=0.9 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 1 lc 6 title 'ehs alpha=0.9 a_tau0=4'
set xlabel 's'
set ylabel 'R2'
plot '/tmp/paperfix/as-transient-shells-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc 1 title 'ihs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc 2 title 'ehs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc 3 title 'ihs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 1 lc 4 title 'ehs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 4 using 1:6 with lines lw 1.5 dt 1 lc 5 title 'ihs alpha=0.9 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc 6 title 'ehs alpha=0.9 a_tau0=4'
set xlabel 's'
set ylabel 'R3'
plot '/tmp/paperfix/as-transient-shells-curves.csv' index 0 using 1:8 with lines lw 1.5 dt 1 lc 1 title 'ihs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 1 using 1:8 with lines lw 1.5 dt 1 lc 2 title 'ehs alpha=0.5 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 2 using 1:8 with lines lw 1.5 dt 1 lc 3 title 'ihs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 3 using 1:8 with lines lw 1.5 dt 1 lc 4 title 'ehs alpha=0.7 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 4 using 1:8 with lines lw 1.5 dt 1 lc 5 title 'ihs alpha=0.9 a_tau0=4', '/tmp/paperfix/as-transient-shells-curves.csv' index 5 using 1:8 with lines lw 1.5 dt 1 lc 6 title 'ehs alpha=0.9 a_tau0=4'
unset multiplot

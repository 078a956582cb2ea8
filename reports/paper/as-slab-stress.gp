# gdsmc 0.3.0 verify: scene verify/cases/scenes/as-slab.ini, seed 20050502, n = 10000, N = 6 ensembles, 1401 outputs on [0, 14]
# paper E Fig. 4: T/T0 and the reduced stresses against s (EHS: s'/beta): gnuplot reports/paper/as-slab-stress.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output 'reports/paper/as-slab-stress.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 4: T/T0 and the reduced stresses against s (EHS: s''/beta)'
set logscale x
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 's'
set ylabel 'T/T0 (T0 the initial temperature)'
plot 'reports/paper/as-slab-stress-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6)', 'reports/paper/as-slab-stress-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6)'
set xlabel 's'
set ylabel '-Pxy/nT'
plot 'reports/paper/as-slab-stress-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6)', 'reports/paper/as-slab-stress-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6)'
set xlabel 's'
set ylabel '(Pxx - Pyy)/nT'
plot 'reports/paper/as-slab-stress-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5)', 'reports/paper/as-slab-stress-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6)', 'reports/paper/as-slab-stress-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6)'
unset multiplot

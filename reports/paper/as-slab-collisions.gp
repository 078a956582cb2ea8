# gdsmc 0.3.0 verify: scene verify/cases/scenes/as-slab.ini, seed 20050502, n = 10000, N = 6 ensembles, 1401 outputs on [0, 14]
# paper E Fig. 1: collisions per particle s (EHS: s'/beta) against t, and s'/s: gnuplot reports/paper/as-slab-collisions.gp
set terminal pngcairo size 1000,720 font ',10'
set termoption noenhanced
set output 'reports/paper/as-slab-collisions.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 2,1 title 'paper E Fig. 1: collisions per particle s (EHS: s''/beta) against t, and s''/s'
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 't/tau0'
set ylabel 's, s''/beta'
plot 'reports/paper/as-slab-collisions-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5)', 'reports/paper/as-slab-collisions-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5)', 'reports/paper/as-slab-collisions-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6)', 'reports/paper/as-slab-collisions-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6)'
set xlabel 't/tau0'
set ylabel 's''/s'
plot 'reports/paper/as-slab-collisions-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5)', 'reports/paper/as-slab-collisions-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6)'
unset multiplot

# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, verify/cases/scenes/as-slab.ini, verify/cases/scenes/as-slab.ini (by row), seed 20050501, 20050502, 20050502 (by row), n = 10000, N = 8, 6, 6 ensembles (by row), 241 outputs on [0, 24], 1401 outputs on [0, 14], 1401 outputs on [0, 14] (by row)
# paper E Fig. 9: T/T0 and the reduced stresses against s, IHS at alpha = 0.9, a tau0 = 4: homogeneous and the slab: gnuplot reports/paper/as-slab-vs-homogeneous-stress.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output 'reports/paper/as-slab-vs-homogeneous-stress.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 9: T/T0 and the reduced stresses against s, IHS at alpha = 0.9, a tau0 = 4: homogeneous and the slab'
set logscale x
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 's'
set ylabel 'T/T0'
plot 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
set xlabel 's'
set ylabel '-Pxy/nT'
plot 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
set xlabel 's'
set ylabel '(Pxx - Pyy)/nT'
plot 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', 'reports/paper/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
unset multiplot

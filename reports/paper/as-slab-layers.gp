# gdsmc 0.3.0 verify: scene verify/cases/scenes/as-slab.ini, seed 20050502, n = 10000, N = 6 ensembles, 1401 outputs on [0, 14]
# paper E Fig. 3: u_x/(U/2), n_I/n and T_I/T of the central and the top layers against s (EHS: s'/beta): gnuplot reports/paper/as-slab-layers.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output 'reports/paper/as-slab-layers.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 3: u_x/(U/2), n_I/n and T_I/T of the central and the top layers against s (EHS: s''/beta)'
set logscale x
set key outside right top
set grid
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 's'
set ylabel 'u_x/(U/2) (U = aL)'
plot 'reports/paper/as-slab-layers-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc rgb '#56b4e9' title 'ihs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 2 lc rgb '#56b4e9' title 'ehs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc rgb '#e69f00' title 'ihs from E Eq. (3.6) top', 'reports/paper/as-slab-layers-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 7 using 1:2 with lines lw 1.5 dt 2 lc rgb '#e69f00' title 'ehs from E Eq. (3.6) top'
set xlabel 's'
set ylabel 'n_I/n (n the mean density)'
plot 'reports/paper/as-slab-layers-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc rgb '#56b4e9' title 'ihs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 2 lc rgb '#56b4e9' title 'ehs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 1 lc rgb '#e69f00' title 'ihs from E Eq. (3.6) top', 'reports/paper/as-slab-layers-curves.csv' index 6 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 7 using 1:4 with lines lw 1.5 dt 2 lc rgb '#e69f00' title 'ehs from E Eq. (3.6) top'
set xlabel 's'
set ylabel 'T_I/T (T the slab''s temperature)'
plot 'reports/paper/as-slab-layers-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'ihs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc rgb '#56b4e9' title 'ihs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 2 lc rgb '#0072b2' title 'ehs from E Eq. (3.5) centre', 'reports/paper/as-slab-layers-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 2 lc rgb '#56b4e9' title 'ehs from E Eq. (3.5) top', 'reports/paper/as-slab-layers-curves.csv' index 4 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'ihs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc rgb '#e69f00' title 'ihs from E Eq. (3.6) top', 'reports/paper/as-slab-layers-curves.csv' index 6 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' title 'ehs from E Eq. (3.6) centre', 'reports/paper/as-slab-layers-curves.csv' index 7 using 1:6 with lines lw 1.5 dt 2 lc rgb '#e69f00' title 'ehs from E Eq. (3.6) top'
unset multiplot

# gdsmc 0.3.0 verify: scene verify/scenes/as-slab.ini, seed 20050502, n = 10000, N = 6 ensembles, 1401 outputs on [0, 14]
# paper E Fig. 3: u_x/(U/2), n/n and T/T of the central and the top layers against s (EHS: s'/beta): gnuplot /tmp/paper-run/out/as-slab-layers.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/as-slab-layers.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 3: u_x/(U/2), n/n and T/T of the central and the top layers against s (EHS: s''/beta)'
set logscale x
set key outside right top
set grid
set xlabel 's'
set ylabel 'u_x/(U/2)'
plot '/tmp/paper-run/out/as-slab-layers-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'ihs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'ihs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'ehs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 1 lc 4 title 'ehs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc 5 title 'ihs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc 6 title 'ihs (3.6) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 1 lc 7 title 'ehs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 7 using 1:2 with lines lw 1.5 dt 1 lc 8 title 'ehs (3.6) top'
set xlabel 's'
set ylabel 'n/n'
plot '/tmp/paper-run/out/as-slab-layers-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc 1 title 'ihs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc 2 title 'ihs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc 3 title 'ehs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 1 lc 4 title 'ehs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc 5 title 'ihs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 1 lc 6 title 'ihs (3.6) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 6 using 1:4 with lines lw 1.5 dt 1 lc 7 title 'ehs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 7 using 1:4 with lines lw 1.5 dt 1 lc 8 title 'ehs (3.6) top'
set xlabel 's'
set ylabel 'T/T'
plot '/tmp/paper-run/out/as-slab-layers-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc 1 title 'ihs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc 2 title 'ihs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc 3 title 'ehs (3.5) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 1 lc 4 title 'ehs (3.5) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 4 using 1:6 with lines lw 1.5 dt 1 lc 5 title 'ihs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc 6 title 'ihs (3.6) top', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 6 using 1:6 with lines lw 1.5 dt 1 lc 7 title 'ehs (3.6) centre', '/tmp/paper-run/out/as-slab-layers-curves.csv' index 7 using 1:6 with lines lw 1.5 dt 1 lc 8 title 'ehs (3.6) top'
unset multiplot

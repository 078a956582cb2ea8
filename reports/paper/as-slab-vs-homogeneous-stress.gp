# gdsmc 0.3.0 verify: scene verify/scenes/as.ini, verify/scenes/as-slab.ini, verify/scenes/as-slab.ini (by row), seed 20050501, 20050502, 20050502 (by row), n = 10000, N = 8, 6, 6 ensembles (by row), 241 outputs on [0, 24], 1401 outputs on [0, 14], 1401 outputs on [0, 14] (by row)
# paper E Fig. 9: T/T0 and the reduced stresses against s, IHS at alpha = 0.9, a tau0 = 4: homogeneous and the slab: gnuplot /tmp/paper-run/out/as-slab-vs-homogeneous-stress.gp
set terminal pngcairo size 1000,1050 font ',10'
set termoption noenhanced
set output '/tmp/paper-run/out/as-slab-vs-homogeneous-stress.png'
set datafile separator ','
set datafile missing ''
set multiplot layout 3,1 title 'paper E Fig. 9: T/T0 and the reduced stresses against s, IHS at alpha = 0.9, a tau0 = 4: homogeneous and the slab'
set logscale x
set key outside right top
set grid
set xlabel 's'
set ylabel 'T/T0'
plot '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
set xlabel 's'
set ylabel '-Pxy/nT'
plot '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
set xlabel 's'
set ylabel '(Pxx - Pyy)/nT'
plot '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc 1 title 'homogeneous', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc 2 title 'slab (3.5)', '/tmp/paper-run/out/as-slab-vs-homogeneous-stress-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc 3 title 'slab (3.6)'
unset multiplot

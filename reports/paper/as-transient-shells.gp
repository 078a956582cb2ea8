# gdsmc 0.3.0 verify: scene verify/cases/scenes/as.ini, seed 20050501, n = 10000, N = 8 ensembles, 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 601 outputs on [0, 300], 321 outputs on [0, 16], 701 outputs on [0, 700], 321 outputs on [0, 16], 701 outputs on [0, 700] (by row)
# paper E Fig. 13: the shell ratios R0..R3 against s at a tau0 = 4 (EHS: s'/beta): gnuplot reports/paper/as-transient-shells.gp
set terminal pngcairo size 1220,1320 font ',10'
set termoption noenhanced
set output 'reports/paper/as-transient-shells.png'
set datafile separator ','
set datafile missing ''
set multiplot title 'paper E Fig. 13: the shell ratios R0..R3 against s at a tau0 = 4 (EHS: s''/beta)'
set logscale x
set key off
set grid
set yrange [0.979004:1.31199]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.9150
set bmargin at screen 0.7600
set title 'alpha = 0.5'
set xlabel ''
set ylabel 'R0'
plot 'reports/paper/as-transient-shells-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.9150
set bmargin at screen 0.7600
set title 'alpha = 0.7'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.9150
set bmargin at screen 0.7600
set title 'alpha = 0.9'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set yrange [0.668709:1.02061]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.6950
set bmargin at screen 0.5400
set title ''
set xlabel ''
set ylabel 'R1'
plot 'reports/paper/as-transient-shells-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.6950
set bmargin at screen 0.5400
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.6950
set bmargin at screen 0.5400
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set yrange [0.965056:1.73535]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.4750
set bmargin at screen 0.3200
set title ''
set xlabel ''
set ylabel 'R2'
plot 'reports/paper/as-transient-shells-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.4750
set bmargin at screen 0.3200
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.4750
set bmargin at screen 0.3200
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 4 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set yrange [-0.110833:27.9613]
set lmargin at screen 0.0650
set rmargin at screen 0.3483
set tmargin at screen 0.2550
set bmargin at screen 0.1000
set title ''
set xlabel 's'
set ylabel 'R3'
plot 'reports/paper/as-transient-shells-curves.csv' index 0 using 1:8 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 1 using 1:8 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.3833
set rmargin at screen 0.6667
set tmargin at screen 0.2550
set bmargin at screen 0.1000
set title ''
set xlabel 's'
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 2 using 1:8 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 3 using 1:8 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.7017
set rmargin at screen 0.9850
set tmargin at screen 0.2550
set bmargin at screen 0.1000
set title ''
set xlabel 's'
set ylabel ''
plot 'reports/paper/as-transient-shells-curves.csv' index 4 using 1:8 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-transient-shells-curves.csv' index 5 using 1:8 with lines lw 1.5 dt 1 lc rgb '#d55e00' notitle
set lmargin at screen 0.065
set rmargin at screen 0.985
set bmargin at screen 0
set tmargin at screen 0.04
unset title
unset xlabel
unset ylabel
unset border
unset tics
unset grid
unset logscale
set xrange [0:1]
set yrange [0:1]
set key on center center horizontal samplen 4
plot NaN with lines lw 1.5 dt 1 lc rgb '#0072b2' title 'IHS a_tau0=4', NaN with lines lw 1.5 dt 1 lc rgb '#d55e00' title 'EHS a_tau0=4'
unset multiplot

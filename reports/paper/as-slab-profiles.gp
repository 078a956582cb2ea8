# gdsmc 0.3.0 verify: scene verify/cases/scenes/as-slab.ini, seed 20050502, n = 10000, N = 6 ensembles, 1401 outputs on [0, 14]
# paper E Fig. 2: the profiles at t/tau0 = 0.13, 0.5, 1, 1.5, 2; E Eq. (3.5): uniform, at rest; E Eq. (3.6): a shell with density and flow waves: gnuplot reports/paper/as-slab-profiles.gp
set terminal pngcairo size 1580,1020 font ',10'
set termoption noenhanced
set output 'reports/paper/as-slab-profiles.png'
set datafile separator ','
set datafile missing ''
set multiplot title 'paper E Fig. 2: the profiles at t/tau0 = 0.13, 0.5, 1, 1.5, 2; E Eq. (3.5): uniform, at rest; E Eq. (3.6): a shell with density and flow waves'
set key off
set grid
set yrange [-2.11653:1.18817]
set lmargin at screen 0.0650
set rmargin at screen 0.2687
set tmargin at screen 0.9150
set bmargin at screen 0.6867
set title 'IHS from E Eq. (3.5)'
set xlabel ''
set ylabel 'u_x/(U/2) (U = aL)'
plot 'reports/paper/as-slab-profiles-curves.csv' index 0 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 1 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 2 using 1:2 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 3 using 1:2 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 4 using 1:2 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.3037
set rmargin at screen 0.5075
set tmargin at screen 0.9150
set bmargin at screen 0.6867
set title 'EHS from E Eq. (3.5)'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 5 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 6 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 7 using 1:2 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 8 using 1:2 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 9 using 1:2 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.5425
set rmargin at screen 0.7462
set tmargin at screen 0.9150
set bmargin at screen 0.6867
set title 'IHS from E Eq. (3.6)'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 10 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 11 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 12 using 1:2 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 13 using 1:2 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 14 using 1:2 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.7812
set rmargin at screen 0.9850
set tmargin at screen 0.9150
set bmargin at screen 0.6867
set title 'EHS from E Eq. (3.6)'
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 15 using 1:2 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 16 using 1:2 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 17 using 1:2 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 18 using 1:2 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 19 using 1:2 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set yrange [0.45775:1.55225]
set lmargin at screen 0.0650
set rmargin at screen 0.2687
set tmargin at screen 0.6217
set bmargin at screen 0.3933
set title ''
set xlabel ''
set ylabel 'n_I/n (n the mean density)'
plot 'reports/paper/as-slab-profiles-curves.csv' index 0 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 1 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 2 using 1:4 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 3 using 1:4 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 4 using 1:4 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.3037
set rmargin at screen 0.5075
set tmargin at screen 0.6217
set bmargin at screen 0.3933
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 5 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 6 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 7 using 1:4 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 8 using 1:4 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 9 using 1:4 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.5425
set rmargin at screen 0.7462
set tmargin at screen 0.6217
set bmargin at screen 0.3933
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 10 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 11 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 12 using 1:4 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 13 using 1:4 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 14 using 1:4 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.7812
set rmargin at screen 0.9850
set tmargin at screen 0.6217
set bmargin at screen 0.3933
set title ''
set xlabel ''
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 15 using 1:4 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 16 using 1:4 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 17 using 1:4 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 18 using 1:4 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 19 using 1:4 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set yrange [0.0218844:7.23512]
set lmargin at screen 0.0650
set rmargin at screen 0.2687
set tmargin at screen 0.3283
set bmargin at screen 0.1000
set title ''
set xlabel 'y/L'
set ylabel 'T_I/T (T the slab''s temperature)'
plot 'reports/paper/as-slab-profiles-curves.csv' index 0 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 1 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 2 using 1:6 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 3 using 1:6 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 4 using 1:6 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.3037
set rmargin at screen 0.5075
set tmargin at screen 0.3283
set bmargin at screen 0.1000
set title ''
set xlabel 'y/L'
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 5 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 6 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 7 using 1:6 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 8 using 1:6 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 9 using 1:6 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.5425
set rmargin at screen 0.7462
set tmargin at screen 0.3283
set bmargin at screen 0.1000
set title ''
set xlabel 'y/L'
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 10 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 11 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 12 using 1:6 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 13 using 1:6 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 14 using 1:6 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
set lmargin at screen 0.7812
set rmargin at screen 0.9850
set tmargin at screen 0.3283
set bmargin at screen 0.1000
set title ''
set xlabel 'y/L'
set ylabel ''
plot 'reports/paper/as-slab-profiles-curves.csv' index 15 using 1:6 with lines lw 1.5 dt 1 lc rgb '#0072b2' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 16 using 1:6 with lines lw 1.5 dt 2 lc rgb '#d55e00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 17 using 1:6 with lines lw 1.5 dt 3 lc rgb '#000000' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 18 using 1:6 with lines lw 1.5 dt 4 lc rgb '#e69f00' notitle, 'reports/paper/as-slab-profiles-curves.csv' index 19 using 1:6 with lines lw 1.5 dt 5 lc rgb '#56b4e9' notitle
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
plot NaN with lines lw 1.5 dt 1 lc rgb '#0072b2' title 't/tau0 = 0.13', NaN with lines lw 1.5 dt 2 lc rgb '#d55e00' title 't/tau0 = 0.5', NaN with lines lw 1.5 dt 3 lc rgb '#000000' title 't/tau0 = 1', NaN with lines lw 1.5 dt 4 lc rgb '#e69f00' title 't/tau0 = 1.5', NaN with lines lw 1.5 dt 5 lc rgb '#56b4e9' title 't/tau0 = 2'
unset multiplot

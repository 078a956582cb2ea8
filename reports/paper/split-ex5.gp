# split-ex5: gnuplot reports/paper/split-ex5.gp
set terminal pngcairo size 900,650 font ',10'
set termoption noenhanced
set output 'reports/paper/split-ex5.png'
set datafile separator ','
set title 'split-ex5: |time-step - jump| in the time-averaged T'
set xlabel 'h'
set ylabel '|difference in T|'
set logscale xy
set key top left
plot 'reports/paper/split-ex5-points.csv' skip 1 using 1:2:3 with yerrorbars pt 5 title 'Euler ± c', 'reports/paper/split-ex5-points.csv' skip 1 using 1:4:5 with yerrorbars pt 7 title 'Strang ± c', 0.265253*(x/1.6) with lines dt 2 title 'slope 1', 0.0653392*(x/1.6)**2 with lines dt 3 title 'slope 2'

set terminal pngcairo size 900,600 font ',11'
set output 'doc/accuracy/accuracy.png'
set datafile separator ','
set logscale xy
set grid
set xlabel 'time (ms, device, grid build + render)'
set ylabel 'relative RMSE against the reference'
set key top right
plot 'doc/accuracy/accuracy.csv' skip 1 using 4:7 with points pt 7 ps 1.2 title 'settings', \
     '' skip 1 using ($11 == 1 ? $4 : 1/0):7 with linespoints lw 2 pt 6 ps 2 title 'Pareto front', \
     '' skip 1 using 4:7:1 with labels offset 0,1 font ',9' notitle

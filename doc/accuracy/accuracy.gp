set terminal pngcairo size 900,600 font ',11'
set output 'doc/accuracy/accuracy.png'
set datafile separator ','
set logscale xy
set grid
set xlabel 'time (ms, device: grid, voxel hierarchy, render)'
set ylabel 'relative RMSE against the reference'
set key top right
plot 'doc/accuracy/accuracy.csv' skip 1 using 5:8 with points pt 7 ps 1.2 title 'settings', \
     '' skip 1 using ($12 == 1 ? $5 : 1/0):8 with linespoints lw 2 pt 6 ps 2 title 'Pareto front', \
     '' skip 1 using 5:8:1 with labels offset 0,1 font ',7' notitle

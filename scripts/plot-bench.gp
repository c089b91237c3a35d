# plot-bench.gp -- the plots of `fp3 bench` (make bench, make bench-model):
# reads a sweep CSV, writes the work-precision plot (error at t_end against
# the engine's cycles to t_end) and the error-against-h plot, one line per
# integrator, log-log.
# Usage: gnuplot -e "dir='build/bench'" scripts/plot-bench.gp
#          (DIR/sweep.csv -> DIR/work-precision.png, DIR/error-vs-h.png)
#        gnuplot -e "csv='F.csv'; png='W.png'; hpng='H.png'" scripts/plot-bench.gp
#
# CSV columns: 1 model, 2 integrator, 3 h, 4 steps, 5 t_end,
# 6 insns_per_step, 7 cycles_per_step, 8 work_cycles, 9 engine_mismatches,
# 10 error_max, then each state variable and its reference.

if (!exists("dir")) dir = 'build/bench'
if (!exists("csv")) csv = dir.'/sweep.csv'
if (!exists("png")) png = dir.'/work-precision.png'
if (!exists("hpng")) hpng = dir.'/error-vs-h.png'
set datafile separator ','
set datafile missing 'nan'
set key outside right top noenhanced
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set terminal pngcairo size 1100,620 font ',11'
model = system("sed -n 2p '".csv."' | cut -d, -f1")
tend = system("sed -n 2p '".csv."' | cut -d, -f5")
# errors of 0 drawn at the floor; diverged rows (inf, nan) left out
floor = 1e-12
sel(name) = (strcol(2) eq name && column(10) < 1e30) ? \
            (column(10) > floor ? column(10) : floor) : NaN
# every integrator the CSV has, in its order
names = system("tail -n +2 '".csv."' | cut -d, -f2 | awk '!seen[$0]++' | tr '\\n' ' '")

set output png
set title sprintf("Work-precision, model %s (t_end = %s s)", model, tend) noenhanced
set xlabel 'engine cycles to t_end (one object: cycles per integration x integrations)' noenhanced
set ylabel 'largest |state - GSL rk8pd| at t_end' noenhanced
plot for [n in names] csv skip 1 using 8:(sel(n)) with linespoints pointsize 0.8 title n

set output hpng
set title sprintf("Error against the step, model %s (binary32 golden model)", model) noenhanced
set xlabel 'h [s]'
plot for [n in names] csv skip 1 using 3:(sel(n)) with linespoints pointsize 0.8 title n

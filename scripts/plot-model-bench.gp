# plot-model-bench.gp -- the work-precision plot of `fp3 bench --model`
# (make bench-model): reads CSV, writes PNG (error at t_end against RTL
# cycles of one object's run, one line per integrator, log-log).
# Usage: gnuplot -e "csv='build/bench/model-spring.csv'; png='build/bench/model-spring.png'" \
#          scripts/plot-model-bench.gp
#
# CSV columns: 1 model, 2 integrator, 3 h, 4 steps, 5 t_end,
# 6 insns_per_step, 7 cycles_per_step, 8 work_cycles, 9 engine_mismatches,
# 10 error_max, then each state variable and its reference.

if (!exists("csv")) csv = 'build/bench/model-spring.csv'
if (!exists("png")) png = 'build/bench/model-spring.png'
set datafile separator ','
set datafile missing 'nan'
set key outside right top noenhanced
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set terminal pngcairo size 1000,600 font ',11'
set output png
set xlabel 'RTL cycles to t_end (one object, cycles per integration x integrations)'
set ylabel 'largest |state - GSL rk8pd| at t_end'
floor = 1e-12
sel(name) = (strcol(2) eq name) ? (column(10) > floor ? column(10) : floor) : NaN
# every integrator the CSV has, in its order
names = system("tail -n +2 '".csv."' | cut -d, -f2 | awk '!seen[$0]++' | tr '\\n' ' '")
plot for [n in names] csv skip 1 using 8:(sel(n)) with linespoints title n

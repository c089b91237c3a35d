# plot-bench.gp -- plots of `fp3 bench` (make bench): reads DIR/sweep.csv,
# writes DIR/work-precision.png (error against RTL cycles) and
# DIR/error-vs-h.png (error against h/tau, with GSL's double-precision
# steppers).  Usage: gnuplot -e "dir='build/bench'" scripts/plot-bench.gp
#
# sweep.csv columns: 1 integrator, 2 kind, 3 h_over_tau, 4 h, 5 steps,
# 6 t_end, 7 cycles_first, 8 cycles_per_integration, 9 total_cycles,
# 10 ns_at_paper_clock, 11 cpu_ns_per_step, 12 cpu_ns_total,
# 13 v_final_abs, 14 v_final_rel, 15 v_max_abs, 16 s_final_abs,
# 17 s_final_rel, 18 s_max_abs, 19 err_norm, 20 diverged

if (!exists("dir")) dir = 'build/bench'
csv = dir.'/sweep.csv'
set datafile separator ','
set datafile missing 'NaN'
set key outside right top noenhanced
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set terminal pngcairo size 1100,620 font ',11'

fp3 = 'euler symeuler verlet rk2 rk4 rk4vs rk4comp rk4vscomp'
gsl = 'gsl_rk4 gsl_rkf45 gsl_rk8pd'

# keep only the rows of one integrator that did not diverge; errors of 0
# are drawn at the floor
floor = 1e-12
sel(name, col) = (strcol(1) eq name && column(20) == 0) ? \
                 (column(col) > floor ? column(col) : floor) : NaN

set output dir.'/work-precision.png'
set title "Work-precision on the ship (end time 6 tau): error against RTL cost"
set xlabel 'RTL cycles to the end time (ADD\_LATENCY 4, MUL\_LATENCY 3)'
set ylabel 'max_t |error| / max_t |value|, worse of v and s'
set yrange [1e-12:10]
plot for [n in fp3] csv using (strcol(1) eq n ? column(9) : NaN):(sel(n, 19)) \
     every ::1 with linespoints pointsize 0.8 title n

set output dir.'/error-vs-h.png'
set title "Error against the step (binary32 programs and GSL in double)"
set xlabel 'h / tau'
set ylabel 'max_t |error| / max_t |value|, worse of v and s'
set yrange [1e-16:10]
floor = 1e-16
plot for [n in fp3] csv using (strcol(1) eq n ? column(3) : NaN):(sel(n, 19)) \
     every ::1 with linespoints pointsize 0.8 title n, \
     for [n in gsl] csv using (strcol(1) eq n ? column(3) : NaN):(sel(n, 19)) \
     every ::1 with lines dashtype 2 lw 2 title n.' (double)'

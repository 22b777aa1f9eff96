# Contact-point error against CPU per simulated second, one panel per scene (peer_bench).
# Run from the repository root: gnuplot docs/peers/peers.gp
set terminal pngcairo size 1800,900 font ',10'
set termoption noenhanced
set output 'docs/peers/peers.png'
set logscale xy
set format x '1e%L'
set format y '1e%L'
set xlabel 'CPU time per simulated second [s]'
set ylabel 'max contact-point error [m]'
set key bottom left font ',8'
set grid
set multiplot layout 2,3
set title 'free_light (0.3 s)'
plot 'docs/peers/peers_free_light.dat' index 0 using 1:2 with linespoints pointsize 0.8 lc rgb '#000000' pt 1 title 'hemiroll rk4', \
     'docs/peers/peers_free_light.dat' index 1 using 1:2 with linespoints pointsize 0.8 lc rgb '#555555' pt 2 title 'hemiroll dop853', \
     'docs/peers/peers_free_light.dat' index 2 using 1:2 with linespoints pointsize 0.8 lc rgb '#1f77b4' pt 3 title 'mujoco default', \
     'docs/peers/peers_free_light.dat' index 3 using 1:2 with linespoints pointsize 0.8 lc rgb '#6baed6' pt 4 title 'mujoco tuned', \
     'docs/peers/peers_free_light.dat' index 4 using 1:2 with linespoints pointsize 0.8 lc rgb '#08306b' pt 5 title 'mujoco tuned_rk4', \
     'docs/peers/peers_free_light.dat' index 5 using 1:2 with linespoints pointsize 0.8 lc rgb '#d62728' pt 6 title 'bullet default', \
     'docs/peers/peers_free_light.dat' index 6 using 1:2 with linespoints pointsize 0.8 lc rgb '#fc9272' pt 7 title 'bullet tuned', \
     'docs/peers/peers_free_light.dat' index 7 using 1:2 with linespoints pointsize 0.8 lc rgb '#2ca02c' pt 8 title 'ode default', \
     'docs/peers/peers_free_light.dat' index 8 using 1:2 with linespoints pointsize 0.8 lc rgb '#74c476' pt 9 title 'ode tuned', \
     'docs/peers/peers_free_light.dat' index 9 using 1:2 with linespoints pointsize 0.8 lc rgb '#00441b' pt 10 title 'ode tuned_pyramid'
set title 'free_heavy (1.1 s)'
plot 'docs/peers/peers_free_heavy.dat' index 0 using 1:2 with linespoints pointsize 0.8 lc rgb '#000000' pt 1 title 'hemiroll rk4', \
     'docs/peers/peers_free_heavy.dat' index 1 using 1:2 with linespoints pointsize 0.8 lc rgb '#555555' pt 2 title 'hemiroll dop853', \
     'docs/peers/peers_free_heavy.dat' index 2 using 1:2 with linespoints pointsize 0.8 lc rgb '#1f77b4' pt 3 title 'mujoco default', \
     'docs/peers/peers_free_heavy.dat' index 3 using 1:2 with linespoints pointsize 0.8 lc rgb '#6baed6' pt 4 title 'mujoco tuned', \
     'docs/peers/peers_free_heavy.dat' index 4 using 1:2 with linespoints pointsize 0.8 lc rgb '#08306b' pt 5 title 'mujoco tuned_rk4', \
     'docs/peers/peers_free_heavy.dat' index 5 using 1:2 with linespoints pointsize 0.8 lc rgb '#d62728' pt 6 title 'bullet default', \
     'docs/peers/peers_free_heavy.dat' index 6 using 1:2 with linespoints pointsize 0.8 lc rgb '#fc9272' pt 7 title 'bullet tuned', \
     'docs/peers/peers_free_heavy.dat' index 7 using 1:2 with linespoints pointsize 0.8 lc rgb '#2ca02c' pt 8 title 'ode default', \
     'docs/peers/peers_free_heavy.dat' index 8 using 1:2 with linespoints pointsize 0.8 lc rgb '#74c476' pt 9 title 'ode tuned', \
     'docs/peers/peers_free_heavy.dat' index 9 using 1:2 with linespoints pointsize 0.8 lc rgb '#00441b' pt 10 title 'ode tuned_pyramid'
set title 'rocking (10 s)'
plot 'docs/peers/peers_rocking.dat' index 0 using 1:2 with linespoints pointsize 0.8 lc rgb '#000000' pt 1 title 'hemiroll rk4', \
     'docs/peers/peers_rocking.dat' index 1 using 1:2 with linespoints pointsize 0.8 lc rgb '#555555' pt 2 title 'hemiroll dop853', \
     'docs/peers/peers_rocking.dat' index 2 using 1:2 with linespoints pointsize 0.8 lc rgb '#1f77b4' pt 3 title 'mujoco default', \
     'docs/peers/peers_rocking.dat' index 3 using 1:2 with linespoints pointsize 0.8 lc rgb '#6baed6' pt 4 title 'mujoco tuned', \
     'docs/peers/peers_rocking.dat' index 4 using 1:2 with linespoints pointsize 0.8 lc rgb '#08306b' pt 5 title 'mujoco tuned_rk4', \
     'docs/peers/peers_rocking.dat' index 5 using 1:2 with linespoints pointsize 0.8 lc rgb '#d62728' pt 6 title 'bullet default', \
     'docs/peers/peers_rocking.dat' index 6 using 1:2 with linespoints pointsize 0.8 lc rgb '#fc9272' pt 7 title 'bullet tuned', \
     'docs/peers/peers_rocking.dat' index 7 using 1:2 with linespoints pointsize 0.8 lc rgb '#2ca02c' pt 8 title 'ode default', \
     'docs/peers/peers_rocking.dat' index 8 using 1:2 with linespoints pointsize 0.8 lc rgb '#74c476' pt 9 title 'ode tuned', \
     'docs/peers/peers_rocking.dat' index 9 using 1:2 with linespoints pointsize 0.8 lc rgb '#00441b' pt 10 title 'ode tuned_pyramid'
set title 'tether (3 s)'
plot 'docs/peers/peers_tether.dat' index 0 using 1:2 with linespoints pointsize 0.8 lc rgb '#000000' pt 1 title 'hemiroll rk4', \
     'docs/peers/peers_tether.dat' index 1 using 1:2 with linespoints pointsize 0.8 lc rgb '#555555' pt 2 title 'hemiroll dop853', \
     'docs/peers/peers_tether.dat' index 2 using 1:2 with linespoints pointsize 0.8 lc rgb '#6baed6' pt 4 title 'mujoco tuned', \
     'docs/peers/peers_tether.dat' index 3 using 1:2 with linespoints pointsize 0.8 lc rgb '#08306b' pt 5 title 'mujoco tuned_rk4', \
     'docs/peers/peers_tether.dat' index 4 using 1:2 with linespoints pointsize 0.8 lc rgb '#fc9272' pt 7 title 'bullet tuned', \
     'docs/peers/peers_tether.dat' index 5 using 1:2 with linespoints pointsize 0.8 lc rgb '#2ca02c' pt 8 title 'ode default', \
     'docs/peers/peers_tether.dat' index 6 using 1:2 with linespoints pointsize 0.8 lc rgb '#74c476' pt 9 title 'ode tuned', \
     'docs/peers/peers_tether.dat' index 7 using 1:2 with linespoints pointsize 0.8 lc rgb '#00441b' pt 10 title 'ode tuned_pyramid'
set title 'rose (10 s)'
plot 'docs/peers/peers_rose.dat' index 0 using 1:2 with linespoints pointsize 0.8 lc rgb '#000000' pt 1 title 'hemiroll rk4', \
     'docs/peers/peers_rose.dat' index 1 using 1:2 with linespoints pointsize 0.8 lc rgb '#555555' pt 2 title 'hemiroll dop853', \
     'docs/peers/peers_rose.dat' index 2 using 1:2 with linespoints pointsize 0.8 lc rgb '#1f77b4' pt 3 title 'mujoco default', \
     'docs/peers/peers_rose.dat' index 3 using 1:2 with linespoints pointsize 0.8 lc rgb '#6baed6' pt 4 title 'mujoco tuned', \
     'docs/peers/peers_rose.dat' index 4 using 1:2 with linespoints pointsize 0.8 lc rgb '#08306b' pt 5 title 'mujoco tuned_rk4', \
     'docs/peers/peers_rose.dat' index 5 using 1:2 with linespoints pointsize 0.8 lc rgb '#fc9272' pt 7 title 'bullet tuned', \
     'docs/peers/peers_rose.dat' index 6 using 1:2 with linespoints pointsize 0.8 lc rgb '#2ca02c' pt 8 title 'ode default', \
     'docs/peers/peers_rose.dat' index 7 using 1:2 with linespoints pointsize 0.8 lc rgb '#74c476' pt 9 title 'ode tuned', \
     'docs/peers/peers_rose.dat' index 8 using 1:2 with linespoints pointsize 0.8 lc rgb '#00441b' pt 10 title 'ode tuned_pyramid'
unset multiplot

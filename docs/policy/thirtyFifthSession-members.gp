# The shipped policy's three members (docs/policy.md "The shipped policy"): each the
# two-stage recipe with its seed. Left: the validation mean reward (200 passages, the
# noise-free actor; stage 2's episodes drawn after stage 1's 124736; B continues A's
# curve). Right: stage 1's training reward (mean of the last 1000 episodes, with
# exploration noise). gnuplot docs/policy/thirtyFifthSession-members.gp (from the
# repository root).
set terminal pngcairo size 1400,560 font ",11"
set output 'docs/policy/thirtyFifthSession-members.png'
set datafile separator ','
set multiplot layout 1,2
set grid
set key bottom right
set xlabel 'episode'
set ylabel 'validation mean reward (invalid mesh = -1)'
set yrange [0.2:0.6]
v(seed, stage) = sprintf('docs/policy/%s-seed%dcritic2-%s-validation.csv', seed == 2 ? 'thirtySecondSession' : 'thirtyThirdSession', seed, stage)
v2(stage) = 'docs/policy/thirtySecondSession-criticUpdates2-'.stage.'-validation.csv'
plot for [s in "1 3"] v(s + 0, 'stage1') every ::1 using 1:2 with linespoints pt 7 title 'seed '.s.', stage 1', \
     v2('stage1') every ::1 using 1:2 with linespoints pt 7 title 'seed 2, stage 1', \
     for [s in "1 3"] v(s + 0, 'stage2B') every ::1 using ($1 + 124736):2 with linespoints pt 6 title 'seed '.s.', stage 2 (A, B)', \
     v2('stage2B') every ::1 using ($1 + 124736):2 with linespoints pt 6 title 'seed 2, stage 2 (A, B)', \
     0.583419 with lines dt 2 lc rgb 'black' title 'the ensemble (shipped)', \
     0.27451249811340689 with lines dt 3 lw 2 lc rgb 'gray40' title 'defaults'
set ylabel 'training reward, stage 1 (mean of the last 1000 episodes)'
set yrange [-0.6:0.6]
plot for [s in "1 2 3"] 'docs/policy/thirtyFifthSession-seed'.s.'critic2-stage1-learning.csv' every ::1 using 1:2 with lines lw 2 title 'seed '.s
unset multiplot

# Validation of the ten-action runs started from seed 3's policy (docs/policy.md "Ten
# actions"): gnuplot docs/policy/twentyFifthSession-splits.gp (from the repository root).
set terminal pngcairo size 900,520
set output 'docs/policy/twentyFifthSession-splits.png'
set datafile separator ','
set key bottom right
set grid
set xlabel 'episode'
set ylabel 'validation mean reward (200 passages)'
set yrange [0.44:0.59]
d = 'docs/policy/twentyFifthSession-'
plot d.'warmStartLr1e-4-validation.csv' using 1:2 with linespoints title 'all weights learn, actor lr 1e-4', \
     d.'warmStartLr1e-5-validation.csv' using 1:2 with linespoints title 'all weights learn, actor lr 1e-5', \
     d.'splitsA-validation.csv' using 1:2 with linespoints lw 2 title 'A: only the splits'' rows learn', \
     d.'splitsB-validation.csv' using ($1 > 24416 ? $1 : 1/0):2 with linespoints lw 2 title 'B: A continued (24416 on), wide noise on the splits', \
     0.5577 with lines dt 2 lc rgb 'black' title 'seed 3 (the start)', \
     0.5583 with lines dt 3 lc rgb 'gray40' title 'ensemble shipped before (seed 1, seed 3)'

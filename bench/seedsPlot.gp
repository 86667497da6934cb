# docs/policy/seeds.png: the validation curves of three training seeds of the shipped dict
# (docs/policy-history.md "Three training seeds"). Run from the repository root:
#   gnuplot bench/seedsPlot.gp
# Seed 1 is the shipped run (docs/policy/validation.csv); seeds 2 and 3 ran the same dict
# (tutorials/policyTrain) with <seed> 2 or 3 and <episodes>40000</episodes>.
set terminal pngcairo size 1000,600 font ",11"
set output "docs/policy/seeds.png"
set datafile separator ","
set key bottom right
set grid
set xlabel "episode"
set ylabel "validation mean reward (200 passages; invalid mesh = -1)"
set title "policyTrain, the shipped dict (split critic, barrier 0.1), three seeds"
set xrange [0:40000]
set yrange [0:0.6]
defaults = 0.24561639143366187  # the defaults on the same 200 passages (policyTrain's log)
plot "docs/policy/validation.csv" every ::1 using 1:2 with linespoints pt 7 title "seed 1 (the shipped run)", \
     "docs/policy/seed2-validation.csv" every ::1 using 1:2 with linespoints pt 5 title "seed 2", \
     "docs/policy/seed3-validation.csv" every ::1 using 1:2 with linespoints pt 9 title "seed 3", \
     defaults with lines dt 3 lw 2 lc rgb "black" title "defaults"

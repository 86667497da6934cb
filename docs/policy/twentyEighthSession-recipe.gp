# The shipped member's two-stage recipe run again with today's code (docs/policy.md "The
# two-stage recipe in one command"; the runs in docs/policy-history.md): gnuplot docs/policy/twentyEighthSession-recipe.gp (from the
# repository root). Stage 2's episodes are drawn after stage 1's 124736.
set terminal pngcairo size 1000,560 font ",11"
set output 'docs/policy/twentyEighthSession-recipe.png'
set datafile separator ','
set key bottom right
set grid
set xlabel 'episode'
set ylabel 'validation mean reward (200 passages; invalid mesh = -1)'
set yrange [0.2:0.6]
d = 'docs/policy/twentyEighthSession-'
plot 'docs/policy/twentiethSession-seed3-validation.csv' every ::1 using 1:2 with linespoints pt 7 title 'seed 3, stage 1 as shipped (eight output rows, meshes as policyMesh builds them)', \
     d.'stage1-seed3-validation.csv' every ::1 using 1:2 with linespoints pt 5 title 'seed 3, stage 1 today (ten rows, splits held, as-asked meshes)', \
     d.'stage1-seed1-validation.csv' every ::1 using 1:2 with linespoints pt 9 title 'seed 1, stage 1 today', \
     d.'stage2A-seed3-validation.csv' every ::1 using ($1 + 124736):2 with linespoints pt 6 title 'seed 3 today, stage 2 A (the splits learn)', \
     d.'stage2B-seed3-validation.csv' every ::1 using ($1 > 24416 ? $1 + 124736 : 1/0):2 with linespoints pt 4 title 'seed 3 today, stage 2 B', \
     d.'stage2A-seed1-validation.csv' every ::1 using ($1 + 124736):2 with linespoints pt 10 title 'seed 1 today, stage 2 A', \
     d.'stage2B-seed1-validation.csv' every ::1 using ($1 > 24416 ? $1 + 124736 : 1/0):2 with linespoints pt 8 title 'seed 1 today, stage 2 B', \
     'docs/policy/twentyNinthSession-stage1-seed2-validation.csv' every ::1 using 1:2 with linespoints pt 13 title 'seed 2, stage 1 today (twenty-ninth session)', \
     'docs/policy/twentyNinthSession-stage2B-seed2-validation.csv' every ::1 using ($1 + 124736):2 with linespoints pt 12 title 'seed 2, stage 2 A and B', \
     0.5741 with lines dt 2 lc rgb 'black' title 'seed3splits (the shipped member)', \
     0.27451249811340689 with lines dt 3 lw 2 lc rgb 'gray40' title 'defaults'

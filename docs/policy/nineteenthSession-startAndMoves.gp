# Validation mean of six retraining runs on the mesher of the seventeenth session (docs/policy-history.md
# "Retraining on this mesher"): where the actor starts and what the mesher's parameter moves
# aim at in training. Run from docs/policy: gnuplot nineteenthSession-startAndMoves.gp
set terminal pngcairo size 1000,600
set output 'nineteenthSession-startAndMoves.png'
set datafile separator ','
set key bottom right
set grid
set xlabel 'episodes'
set ylabel 'validation mean reward (200 passages, invalid = -1)'
set title "Retraining on today's mesher: actor start x the parameter moves' target (seed 1 unless said)" font ',11'
set yrange [0.2:0.55]
set xrange [0:90000]
plot 'eighteenthSession-retrain-validation.csv' every ::1 using 1:2 with linespoints title "A: today's start, today's moves", \
     'eighteenthSession-noMovesInTraining-validation.csv' every ::1 using 1:2 with linespoints title "B: today's start, no moves in training", \
     'eighteenthSession-oldDefaultsStart-validation.csv' every ::1 using 1:2 with linespoints title "C: old start, moves to old defaults", \
     'nineteenthSession-oldStartOldMovesSeed2-validation.csv' every ::1 using 1:2 with linespoints title "C, seed 2", \
     'nineteenthSession-oldStartTodaysMoves-validation.csv' every ::1 using 1:2 with linespoints title "D: old start, today's moves", \
     'nineteenthSession-oldStartTodaysMovesSeed2-validation.csv' every ::1 using 1:2 with linespoints title "D, seed 2", \
     'nineteenthSession-todaysStartOldMoves-validation.csv' every ::1 using 1:2 with linespoints title "E: today's start, moves to old defaults", \
     0.541849 with lines dashtype 2 lc rgb 'black' title 'shipped policy on this mesher'

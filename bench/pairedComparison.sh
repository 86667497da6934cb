#!/bin/bash
# Paired comparison of two policies' one-shot Q on the same passages, from two CSVs that
# bench/policyEvaluation wrote (same SEED, COUNT and EDGE_RADII): the mean of the
# per-passage differences (second file minus first; an invalid mesh counts -1) with its
# standard error, and the same over the passages both mesh validly, with how often each
# is better. docs/policy.md: a candidate replaces the shipped policy only when it is
# ahead by more than two standard errors.
#   bench/pairedComparison.sh SHIPPED.csv CANDIDATE.csv
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: bench/pairedComparison.sh SHIPPED.csv CANDIDATE.csv" >&2; exit 2; }
[ "$(wc -l < "$1")" -eq "$(wc -l < "$2")" ] || { echo "pairedComparison: $1 and $2 hold different passage counts" >&2; exit 1; }
paste -d, "$1" "$2" | awk -F, '
  NR > 1 {
    if ($1 != $5) { print "pairedComparison: passage " $1 " beside passage " $5 > "/dev/stderr"; exit 1 }
    d = $6 - $2; n++; s += d; ss += d * d
    if ($2 > -1 && $6 > -1) { m++; t += d; tt += d * d; if (d > 0) better++; if (d < 0) worse++ }
  }
  END {
    if (n < 2 || m < 2) { print "pairedComparison: too few passages" > "/dev/stderr"; exit 1 }
    mu = s / n; se = sqrt((ss / n - mu * mu) / (n - 1))
    nu = t / m; te = sqrt((tt / m - nu * nu) / (m - 1))
    printf "all %d passages: mean difference %+.4f, standard error %.4f\n", n, mu, se
    printf "both valid on %d: mean difference %+.4f, standard error %.4f; candidate better on %d, shipped on %d\n", m, nu, te, better, worse
  }'

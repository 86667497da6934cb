#!/bin/bash
# Wall time and share of the cores busy of policyTrain under each <learnerSchedule>, the
# runs alternating (docs/benchmarks.md "Policy training"). The dict is seed 3's run's
# (bench/learnerScheduleBenchmarkDict.xml) with the twenty-sixth session's as-asked
# ten-action keys, run from the defaults to EPISODES; with CHECKPOINT set, each run starts
# from that checkpoint (-startFrom) and runs to EPISODES (above the checkpoint's count).
#   bench/learnerScheduleBenchmark.sh [ROUNDS [EPISODES]]      (tools on PATH; both cores)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rounds="${1:-2}"
episodes="${2:-2016}"
from=()
[ -z "${CHECKPOINT:-}" ] || from=(-startFrom "$(realpath "$CHECKPOINT")")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "round,schedule,episodes,wallSeconds,userSeconds,busyShare"
for round in $(seq 1 "$rounds"); do
  for schedule in afterRollouts duringNextRollouts; do
    case="$work/$schedule-$round"
    mkdir -p "$case/system"
    sed -e "s|<episodes>[0-9]*</episodes>|<episodes>$episodes</episodes>|" \
        -e "s|<validationEvery>[0-9]*</validationEvery>|<validationEvery>100000000</validationEvery>|" \
        -e "s|</policyTrainDict>|  <wideNoiseShare>0.3</wideNoiseShare><wideNoiseSigma>0.6</wideNoiseSigma><wideNoiseActions>splitIn splitOut</wideNoiseActions><trainingMeshes>asAsked</trainingMeshes><learnerSchedule>$schedule</learnerSchedule>\n</policyTrainDict>|" \
        "$root/bench/learnerScheduleBenchmarkDict.xml" > "$case/system/policyTrainDict.xml"
    /usr/bin/time -f "%e %U" -o "$case/time" policyTrain -case "$case" -threads 2 "${from[@]}" > "$case/log" 2>&1
    read -r wall user < "$case/time"
    echo "$round,$schedule,$episodes,$wall,$user,$(awk -v w="$wall" -v u="$user" 'BEGIN { printf "%.3f", u / (2 * w) }')"
  done
done

#!/bin/bash
# tutorials/policyTrainTwoStage/Allrun on a copy whose three dicts ask for a few batches
# (the recipe's settings otherwise): the three stages run in order, each from the one
# before (-actorFrom stage 1's policy, -startFrom A's checkpoint), and a second Allrun
# trains nothing; a stage with a checkpoint but no `finished` mark is resumed.
#   runPolicyTrainTwoStage.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
. "$(dirname "$0")/tutorialWorkspace.sh" "$1" "$2"
copyTutorial policyTrainTwoStage
case="$work/tutorials/policyTrainTwoStage"
shrink() {  # shrink STAGE EPISODES: a few batches, validation on 4 passages every batch
  sed -i -e "s#<episodes>[0-9]*</episodes>#<episodes>$2</episodes>#" \
    -e "s#<validationEvery>[0-9]*</validationEvery>#<validationEvery>32</validationEvery>#" \
    -e "s#<validationPassages>[0-9]*</validationPassages>#<validationPassages>4</validationPassages>#" \
    -e "s#<checkpointEvery>[0-9]*</checkpointEvery>#<checkpointEvery>32</checkpointEvery>#" \
    -e "s#<actorUpdatesFrom>[0-9]*</actorUpdatesFrom>#<actorUpdatesFrom>32</actorUpdatesFrom>#" \
    "$case/$1/system/policyTrainDict.xml"
}
shrink stage1 96
shrink stage2A 64
shrink stage2B 128
fail() { echo "runPolicyTrainTwoStage: $*"; exit 1; }

"$case/Allrun" > "$work/first.out" 2>&1 || { cat "$work/first.out"; fail "Allrun failed"; }
for stage in stage1 stage2A stage2B; do
  [ -f "$case/$stage/finished" ] || fail "$stage has no finished mark"
  [ -f "$case/$stage/policy/checkpoint.pt" ] || fail "$stage wrote no checkpoint"
done
for stage in stage1 stage2A; do [ -f "$case/$stage/policy/policy.xml" ] || fail "$stage wrote no policy"; done
result="$(sed -n 's#^Allrun: the policy is \([^ ]*\) .*#\1#p' "$work/first.out")"
[ -f "$case/$result" ] || { cat "$work/first.out"; fail "Allrun names no policy that exists: '$result'"; }
grep -q "the actor starts as stage1/policy/policy.xml's (10 actions" "$case/stage2A/log.policyTrain" ||
  fail "stage 2A did not start from stage 1's policy"
grep -q "started at episode 64 from stage2A/policy/checkpoint.pt" "$case/stage2B/log.policyTrain" ||
  fail "stage 2B did not continue A's checkpoint"
grep -q "last validation (episode 128)" "$case/stage2B/log.policyTrain" || fail "stage 2B did not end at 128"

# Again: nothing to train, nothing rewritten.
before="$(md5sum "$case/stage2B/policy/checkpoint.pt")"
"$case/Allrun" > "$work/second.out" 2>&1 || { cat "$work/second.out"; fail "the second Allrun failed"; }
[ "$(grep -c "has finished" "$work/second.out")" = 3 ] || { cat "$work/second.out"; fail "a finished stage ran again"; }
[ "$before" = "$(md5sum "$case/stage2B/policy/checkpoint.pt")" ] || fail "the second Allrun rewrote B's checkpoint"

# A stage with a checkpoint and no mark (stopped by Ctrl-C) is resumed, not started anew.
rm "$case/stage2B/finished"
"$case/Allrun" > "$work/third.out" 2>&1 || { cat "$work/third.out"; fail "the resuming Allrun failed"; }
grep -q "policyTrain -case stage2B -resume" "$work/third.out" || { cat "$work/third.out"; fail "stage 2B was not resumed"; }
grep -q "resumed at episode 128" "$case/stage2B/log.policyTrain" || fail "stage 2B did not resume at 128"
echo "runPolicyTrainTwoStage: three stages in order, finished ones kept, a stopped one resumed"

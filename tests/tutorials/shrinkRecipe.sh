# Sourced by the tests of the training recipes (runPolicyTrainTwoStage.sh,
# runPolicyTrainEnsemble.sh): shrinkStages CASE makes a copy of tutorials/policyTrainTwoStage
# ask for a few batches per stage, the recipe's settings otherwise.
# shrink STAGE EPISODES CASE: a few batches, validation on 4 passages every batch, a
# minibatch of 16 so that the learner updates before the tournament's trial ends (else the
# comparison of the chosen seed with a straight run below would test nothing)
shrink() {
  sed -i -e "s#<episodes>[0-9]*</episodes>#<episodes>$2</episodes>#" \
    -e "s#<validationEvery>[0-9]*</validationEvery>#<validationEvery>32</validationEvery>#" \
    -e "s#<validationPassages>[0-9]*</validationPassages>#<validationPassages>4</validationPassages>#" \
    -e "s#<checkpointEvery>[0-9]*</checkpointEvery>#<checkpointEvery>32</checkpointEvery>#" \
    -e "s#<minibatch>[0-9]*</minibatch>#<minibatch>16</minibatch>#" \
    -e "s#<actorUpdatesFrom>[0-9]*</actorUpdatesFrom>#<actorUpdatesFrom>32</actorUpdatesFrom>#" \
    "$3/$1/system/policyTrainDict.xml"
}
shrinkStages() {  # shrinkStages CASE: stage 1 96 episodes, A 64, B on to 128
  shrink stage1 96 "$1"
  shrink stage2A 64 "$1"
  shrink stage2B 128 "$1"
}

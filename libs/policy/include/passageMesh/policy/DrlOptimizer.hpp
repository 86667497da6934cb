#pragma once
// iterOptimize -method drl: the paper's iterative baseline (method.md section 6), the
// single-step actor-critic loop with the condition fixed, as an optimiser method
// (Optimizer.hpp's registerOptimizerMethod). The state is constant, so the actor learns
// one action: the point it proposes, plus exploration noise, is what gets evaluated.
// Settings are the paper's (PolicyTrainOptions' defaults) with two changes for a budget
// of about 1000 meshes: the sigma = 1 phase is the first tenth of the budget (the paper's
// 1000 episodes would be all of it), and the actor starts at the optimiser's start point.
namespace passageMesh {

// Registers "drl" with the optimiser library (call once, before optimising).
void registerDrlOptimizer();

}  // namespace passageMesh

#include "passageMesh/policy/ActorCritic.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "passageMesh/policy/PolicyNetworks.hpp"
#include "passageMesh/quality/MeshQuality.hpp"
#include "TorchTensors.hpp"

namespace passageMesh {

std::string NetworkLayout::hiddenText() const {
  std::ostringstream text;
  for (std::size_t k = 0; k < hidden.size(); ++k) text << (k ? " " : "") << hidden[k];
  return text.str();
}

struct ActorCritic::Networks {
  Networks(const NetworkLayout& l, const LearningRates& rates)
      : layout(l),
        actor(makeActor(l)),
        critic(makeCritic(l)),
        actorOptimizer(actor->parameters(), torch::optim::AdamOptions(rates.actor)),
        criticOptimizer(critic->parameters(), torch::optim::AdamOptions(rates.critic)) {
    if (hasValidity(l.critic)) {
      // Built after the critic, so `reward` runs start from the same weights as before
      // the model existed; it learns at the critic's rate, being a critic too.
      validity = makeCritic(l);
      validityOptimizer =
          std::make_unique<torch::optim::Adam>(validity->parameters(), torch::optim::AdamOptions(rates.critic));
    }
  }

  // q(s, a) of a valid mesh (with `validity`), or the reward (without).
  torch::Tensor quality(const torch::Tensor& input) {
    const torch::Tensor out = critic->forward(input);
    return layout.critic == CriticModel::validityAndBoundedQuality ? torch::sigmoid(out) : out;
  }

  // The critic's estimate of the expected reward of each row of [s, a].
  torch::Tensor expectedReward(const torch::Tensor& input) {
    if (!validity) return critic->forward(input);
    const torch::Tensor p = torch::sigmoid(validity->forward(input));
    return p * (quality(input) + 1.0) - 1.0;  // p q + (1 - p)(-1)
  }

  NetworkLayout layout;
  FullyConnected actor;
  FullyConnected critic;  // Q(s, a), or q(s, a) of a valid mesh with `validity`
  torch::optim::Adam actorOptimizer;
  torch::optim::Adam criticOptimizer;
  std::vector<int> trainedActorOutputs;  // empty: all (trainActorOutputsOnly)
  std::vector<int> heldActorOutputs;     // (holdActorOutputs)
  FullyConnected validity{nullptr};  // the logit of p(s, a) (hasValidity(layout.critic))
  std::unique_ptr<torch::optim::Adam> validityOptimizer;
  FullyConnected averaged{nullptr};  // the Polyak-averaged actor (averageActor)
  double averageDecay = 0;

  // The averaged actor set to the actor's weights.
  void restartAverage() {
    torch::NoGradGuard noGrad;
    const auto from = actor->parameters();
    auto to = averaged->parameters();
    for (std::size_t k = 0; k < to.size(); ++k) to[k].copy_(from[k]);
  }
  // One averaging step. Written as a + (1 - d)(p - a) so that a weight the actor no longer
  // moves (a held output) stays bit for bit where it is.
  void stepAverage() {
    torch::NoGradGuard noGrad;
    const auto from = actor->parameters();
    auto to = averaged->parameters();
    for (std::size_t k = 0; k < to.size(); ++k) to[k].add_((from[k] - to[k]) * (1.0 - averageDecay));
  }
  FullyConnected& delivered() { return averaged ? averaged : actor; }
};

ActorCritic::ActorCritic(const NetworkLayout& layout, const LearningRates& rates, std::uint64_t seed,
                         const std::vector<double>& startAction) {
  // The networks are built right after seeding LibTorch's generator, so their first
  // weights depend on the seed only.
  torch::manual_seed(seed);
  networks_ = std::make_unique<Networks>(layout, rates);
  if (!startAction.empty()) networks_->actor->startAt(startAction, 0.1);
}

ActorCritic::~ActorCritic() = default;
ActorCritic::ActorCritic(ActorCritic&&) noexcept = default;
ActorCritic& ActorCritic::operator=(ActorCritic&&) noexcept = default;

const NetworkLayout& ActorCritic::layout() const { return networks_->layout; }

namespace {

void checkActorOutputs(const std::vector<int>& outputs, int actionSize) {
  for (int o : outputs)
    if (o < 0 || o >= actionSize)
      throw std::invalid_argument("the actor has no output " + std::to_string(o) + " (it has " +
                                  std::to_string(actionSize) + ")");
}

}  // namespace

void ActorCritic::trainActorOutputsOnly(const std::vector<int>& outputs) {
  checkActorOutputs(outputs, networks_->layout.actionSize);
  networks_->trainedActorOutputs = outputs;
}

void ActorCritic::holdActorOutputs(const std::vector<int>& outputs) {
  checkActorOutputs(outputs, networks_->layout.actionSize);
  networks_->actor->makeOutputsConstant(outputs);
  if (networks_->averaged) networks_->averaged->makeOutputsConstant(outputs);
  networks_->heldActorOutputs = outputs;
}

void ActorCritic::averageActor(double decay) {
  if (!(decay > 0 && decay < 1))
    throw std::invalid_argument("the actor's average keeps a share in (0, 1) at each step, not " +
                                std::to_string(decay));
  Networks& n = *networks_;
  if (!n.averaged) {
    // Built without touching LibTorch's generator (its first weights are overwritten at
    // once): a run with averaging learns exactly as one without.
    auto generator = at::detail::getDefaultCPUGenerator();  // (get_state and set_state lock it)
    const torch::Tensor state = generator.get_state();
    n.averaged = makeActor(n.layout);
    generator.set_state(state);
  }
  n.averageDecay = decay;
  n.restartAverage();
}

bool ActorCritic::averagesActor() const { return static_cast<bool>(networks_->averaged); }

PolicyBatch ActorCritic::act(const PolicyBatch& states) const {
  torch::NoGradGuard noGrad;
  return batchOf(networks_->actor->forward(tensorOf(states)));
}

PolicyBatch ActorCritic::actDelivered(const PolicyBatch& states) const {
  torch::NoGradGuard noGrad;
  return batchOf(networks_->delivered()->forward(tensorOf(states)));
}

Eigen::VectorXd ActorCritic::value(const PolicyBatch& states, const PolicyBatch& actions) const {
  torch::NoGradGuard noGrad;
  const torch::Tensor q =
      networks_->expectedReward(torch::cat({tensorOf(states), tensorOf(actions)}, 1));
  return batchOf(q).col(0);
}

double ActorCritic::updateCritic(const PolicyBatch& states, const PolicyBatch& actions,
                                 const Eigen::VectorXd& rewards) {
  Networks& n = *networks_;
  const torch::Tensor input = torch::cat({tensorOf(states), tensorOf(actions)}, 1);
  const torch::Tensor target = tensorOf(PolicyBatch(rewards));
  if (!n.validity) {
    n.criticOptimizer.zero_grad();
    torch::Tensor loss = torch::mse_loss(n.critic->forward(input), target);
    loss.backward();
    n.criticOptimizer.step();
    return loss.item<double>();
  }
  // Valid meshes have Q in [0, 1]; an invalid one gets invalidMeshQuality (-1).
  const torch::Tensor valid = (target > invalidMeshQuality).to(torch::kFloat32);
  n.validityOptimizer->zero_grad();
  const torch::Tensor logit = n.validity->forward(input);
  torch::binary_cross_entropy_with_logits(logit, valid).backward();
  n.validityOptimizer->step();
  n.criticOptimizer.zero_grad();
  const torch::Tensor q = n.quality(input);
  ((q - target).pow(2) * valid).sum().div(valid.sum().clamp_min(1.0)).backward();
  n.criticOptimizer.step();
  // Reported: the expected reward's squared error before the steps, comparable with
  // `reward`'s loss.
  const torch::Tensor expected = torch::sigmoid(logit.detach()) * (q.detach() + 1.0) - 1.0;
  return torch::mse_loss(expected, target).item<double>();
}

double ActorCritic::updateActor(const PolicyBatch& states, double boundPenalty, double validityBarrier,
                                const Imitation& imitation) {
  Networks& n = *networks_;
  const torch::Tensor s = tensorOf(states);
  n.actorOptimizer.zero_grad();
  const torch::Tensor u = n.actor->beforeOutput(s);
  const torch::Tensor input = torch::cat({s, torch::tanh(u)}, 1);
  torch::Tensor q, loss;
  if (n.validity && validityBarrier > 0) {
    // q + lambda log p: the quality of a valid mesh, with a barrier that only pushes where
    // failures are likely (docs/policy.md).
    q = n.quality(input).mean();
    loss = -q - validityBarrier * torch::log_sigmoid(n.validity->forward(input)).mean();
  } else {
    q = n.expectedReward(input).mean();
    loss = -q;
  }
  if (boundPenalty > 0) {
    const double edge = std::atanh(0.95);
    loss = loss + boundPenalty * torch::relu(u.abs() - edge).pow(2).mean();
  }
  if (imitation.weight > 0 && imitation.states.rows() > 0) {
    // Measured before the tanh, to targets at most 95 % of the half-range out: a target
    // on the bound (CMA-ES's bests often are) would drive the output to infinity, and a
    // distance after the tanh has no gradient left once the output saturates. With the
    // distance after the tanh a training's actor ended on its bounds for every state,
    // every mesh invalid (docs/policy.md).
    const torch::Tensor target = torch::atanh(tensorOf(imitation.actions).clamp(-0.95, 0.95));
    const torch::Tensor distance =
        (n.actor->beforeOutput(tensorOf(imitation.states)) - target).pow(2).sum(1);
    loss = loss + imitation.weight * distance.mean();
  }
  loss.backward();
  if (!n.trainedActorOutputs.empty()) n.actor->keepOutputGradients(n.trainedActorOutputs);
  if (!n.heldActorOutputs.empty()) n.actor->dropOutputGradients(n.heldActorOutputs);
  n.actorOptimizer.step();
  if (n.averaged) n.stepAverage();
  // The backward pass also left gradients in the critic (and validity); their own steps
  // clear them first.
  return q.item<double>();
}

void ActorCritic::save(torch::serialize::OutputArchive& archive) const {
  const Networks& n = *networks_;
  torch::serialize::OutputArchive actor, critic, actorOptimizer, criticOptimizer;
  n.actor->save(actor);
  n.critic->save(critic);
  n.actorOptimizer.save(actorOptimizer);
  n.criticOptimizer.save(criticOptimizer);
  archive.write("actor", actor);
  archive.write("critic", critic);
  archive.write("actorOptimizer", actorOptimizer);
  archive.write("criticOptimizer", criticOptimizer);
  if (n.validity) {
    torch::serialize::OutputArchive validity, validityOptimizer;
    n.validity->save(validity);
    n.validityOptimizer->save(validityOptimizer);
    archive.write("validity", validity);
    archive.write("validityOptimizer", validityOptimizer);
  }
  if (n.averaged) {
    torch::serialize::OutputArchive averaged;
    n.averaged->save(averaged);
    archive.write("averagedActor", averaged);
  }
}

void ActorCritic::load(torch::serialize::InputArchive& archive) {
  Networks& n = *networks_;
  torch::serialize::InputArchive actor, critic, actorOptimizer, criticOptimizer;
  archive.read("actor", actor);
  archive.read("critic", critic);
  archive.read("actorOptimizer", actorOptimizer);
  archive.read("criticOptimizer", criticOptimizer);
  n.actor->load(actor);
  n.critic->load(critic);
  n.actorOptimizer.load(actorOptimizer);
  n.criticOptimizer.load(criticOptimizer);
  if (n.validity) {
    torch::serialize::InputArchive validity, validityOptimizer;
    archive.read("validity", validity);
    archive.read("validityOptimizer", validityOptimizer);
    n.validity->load(validity);
    n.validityOptimizer->load(validityOptimizer);
  }
  if (n.averaged) {
    torch::serialize::InputArchive averaged;
    if (archive.try_read("averagedActor", averaged))
      n.averaged->load(averaged);
    else
      n.restartAverage();
  }
  if (const std::string problem = nonFiniteWeightProblem(); !problem.empty()) throw std::runtime_error(problem);
}

std::string ActorCritic::nonFiniteWeightProblem() const {
  const Networks& n = *networks_;
  const std::pair<const char*, const FullyConnected*> networks[] = {
      {"actor", &n.actor}, {"critic", &n.critic}, {"validity", &n.validity}, {"averaged actor", &n.averaged}};
  for (const auto& [what, network] : networks) {
    if (!*network) continue;
    if (std::string problem = passageMesh::nonFiniteWeightProblem(*network, what); !problem.empty()) return problem;
  }
  return "";
}

void ActorCritic::startActorFrom(const std::filesystem::path& actorFile, const NetworkLayout& fileLayout) {
  const NetworkLayout& mine = networks_->layout;
  if (fileLayout.stateSize != mine.stateSize || fileLayout.hidden != mine.hidden ||
      fileLayout.actionSize > mine.actionSize || fileLayout.leakySlope != mine.leakySlope)
    throw std::invalid_argument("the start actor's layout (" + std::to_string(fileLayout.stateSize) + " -> [" +
                                fileLayout.hiddenText() + "] -> " + std::to_string(fileLayout.actionSize) +
                                ") does not fit this run's (" + std::to_string(mine.stateSize) + " -> [" +
                                mine.hiddenText() + "] -> " + std::to_string(mine.actionSize) + ")");
  FullyConnected start = makeActor(fileLayout);
  torch::serialize::InputArchive archive;
  archive.load_from(actorFile.string());
  start->load(archive);
  networks_->actor->startFrom(*start);
  if (networks_->averaged) networks_->restartAverage();
}

std::string ActorCritic::stateBytes() const {
  torch::serialize::OutputArchive archive;
  save(archive);
  std::ostringstream bytes;
  archive.save_to(bytes);
  return bytes.str();
}

void ActorCritic::loadStateBytes(const std::string& bytes) {
  std::istringstream in(bytes);
  torch::serialize::InputArchive archive;
  archive.load_from(in);
  load(archive);
}

void ActorCritic::saveActor(const std::filesystem::path& file) const {
  saveModuleAtomically(*networks_->delivered(), file);
}

}  // namespace passageMesh

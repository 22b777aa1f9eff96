#include "engine/task/ProtocolDef.h"

#include <algorithm>
#include <charconv>
#include <filesystem>

namespace hemiroll::task {

physics::CouplingDef overriddenCoupling(const TrialOverrides& o, const physics::CouplingDef& level) {
  physics::CouplingDef c = level;
  if (o.method) {
    // The loader accepts only these four names.
    c.visualOnly = *o.method == "visual";
    c.method = *o.method == "M1"   ? physics::ForceMethod::M1
               : *o.method == "M2" ? physics::ForceMethod::M2
                                   : physics::ForceMethod::M3;
  }
  c.stiffness = o.stiffness.value_or(c.stiffness);
  c.damping = o.damping.value_or(c.damping);
  c.alpha = o.alpha.value_or(c.alpha);
  return c;
}

void applyTrialOverrides(const TrialOverrides& overrides, LevelDef& level) {
  level.coupling = overriddenCoupling(overrides, level.coupling);
  level.task.timeLimit = overrides.timeLimit.value_or(level.task.timeLimit);
}

bool isFolderName(const std::string& id) {
  if (id.empty() || id.size() > 64) return false;
  for (const char c : id)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'))
      return false;
  return true;
}

std::string couplingMethodName(const physics::CouplingDef& coupling) {
  return coupling.visualOnly ? "visual" : physics::forceMethodName(coupling.method);
}

}  // namespace hemiroll::task

namespace hemiroll::task {

double GuidanceSpec::fadeAt(int trialInBlock) const {
  if (fade.overTrials <= 1 || trialInBlock >= fade.overTrials) return fade.to;
  const double progress = static_cast<double>(std::max(trialInBlock, 1) - 1) / (fade.overTrials - 1);
  return fade.from + (fade.to - fade.from) * progress;
}

}  // namespace hemiroll::task

namespace hemiroll::task {

namespace {

std::string shortest(double v) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

}  // namespace

TrialOverrides mergedOver(const TrialOverrides& base, const TrialOverrides& own) {
  TrialOverrides o = base;
  if (own.method) o.method = own.method;
  if (own.stiffness) o.stiffness = own.stiffness;
  if (own.damping) o.damping = own.damping;
  if (own.alpha) o.alpha = own.alpha;
  if (own.timeLimit) o.timeLimit = own.timeLimit;
  if (own.guidance) o.guidance = own.guidance;
  return o;
}

std::string defaultConditionLabel(const TrialOverrides& o, const std::string& level) {
  std::string label;
  auto add = [&](const std::string& part) { label += (label.empty() ? "" : " ") + part; };
  if (o.method) add(*o.method);
  if (o.stiffness) add("kr " + shortest(*o.stiffness));
  if (o.damping) add("kv " + shortest(*o.damping));
  if (o.alpha) add("alpha " + shortest(*o.alpha));
  if (o.timeLimit) add("time limit " + shortest(*o.timeLimit) + " s");
  if (o.guidance && o.guidance->kind != "none") add(o.guidance->kind == "autopilot" ? "guided" : "error augmented");
  return label.empty() ? std::filesystem::path(level).stem().string() : label;
}

ConditionDef conditionInGroup(const ConditionDef& condition, int block, const GroupDef* group) {
  if (group == nullptr) return condition;
  ConditionDef c = condition;
  bool changed = false;
  for (const GroupChange& change : group->changes)
    if (change.block == block) {
      c.overrides = mergedOver(c.overrides, change.overrides);
      changed = true;
    }
  if (changed && !c.labelGiven) c.label = defaultConditionLabel(c.overrides, c.level);
  return c;
}

std::vector<std::vector<int>> williamsSquare(int n) {
  if (n <= 0) return {};
  // First row 0, 1, n-1, 2, n-2, ...; row r adds r (mod n) to every entry.
  std::vector<int> first = {0};
  for (int low = 1, high = n - 1, j = 1; j < n; ++j) first.push_back(j % 2 == 1 ? low++ : high--);
  std::vector<std::vector<int>> rows;
  for (int r = 0; r < n; ++r) {
    std::vector<int> row;
    for (const int v : first) row.push_back((v + r) % n);
    rows.push_back(row);
  }
  if (n % 2 == 1)
    for (int r = 0; r < n; ++r) rows.emplace_back(rows[static_cast<std::size_t>(r)].rbegin(), rows[static_cast<std::size_t>(r)].rend());
  return rows;
}

int ProtocolDef::orderCount() const {
  return counterbalanced.size() < 2 ? 1 : static_cast<int>(williamsSquare(static_cast<int>(counterbalanced.size())).size());
}

std::vector<int> ProtocolDef::blockSequence(int order) const {
  std::vector<int> sequence;
  for (std::size_t b = 0; b < blocks.size(); ++b) sequence.push_back(static_cast<int>(b));
  if (counterbalanced.size() < 2) return sequence;
  const auto rows = williamsSquare(static_cast<int>(counterbalanced.size()));
  const auto& row = rows.at(static_cast<std::size_t>((std::max(order, 1) - 1) % static_cast<int>(rows.size())));
  // The k-th counterbalanced place gets the row's k-th counterbalanced block.
  for (std::size_t k = 0; k < counterbalanced.size(); ++k)
    sequence[static_cast<std::size_t>(counterbalanced[k])] = counterbalanced[static_cast<std::size_t>(row[k])];
  return sequence;
}

const GroupDef* ProtocolDef::group(const std::string& name) const {
  for (const GroupDef& g : groups)
    if (g.name == name) return &g;
  return nullptr;
}

}  // namespace hemiroll::task

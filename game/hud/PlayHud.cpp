#include "game/hud/PlayHud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/physics/StateLayout.h"

namespace hemiroll::game {

namespace {

const ImVec4 kGreen(0.35f, 0.85f, 0.4f, 1.0f);
const ImVec4 kRed(0.95f, 0.4f, 0.35f, 1.0f);
const ImVec4 kAmber(0.95f, 0.75f, 0.3f, 1.0f);
const ImVec4 kGhostBlue(0.55f, 0.75f, 1.0f, 1.0f);  // the ghost's own colour

double wrapAngle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a;
}

}  // namespace

PlayHud::PlayHud() : plot_(600), faceX_(400), faceY_(400) {}

void PlayHud::reset() {
  readout_ = {};
  plot_.clear();
  faceX_.clear();
  faceY_.clear();
  lastTime_ = -1.0;
  componentCount_ = 0;
  score_.reset();
  messageUntil_.fill(0.0);
}

void PlayHud::setLabels(std::string level, std::string device, std::string method, bool mousePlayer,
                        double faceRadius) {
  faceRadius_ = faceRadius > 0.0 ? faceRadius : 0.04;
  level_ = std::move(level);
  device_ = std::move(device);
  method_ = std::move(method);
  mousePlayer_ = mousePlayer;
}

void PlayHud::addMessage(const std::string& text, double until) {
  messages_[nextMessage_] = text;
  messageUntil_[nextMessage_] = until;
  nextMessage_ = (nextMessage_ + 1) % kMessages;
}

std::vector<std::string> PlayHud::messages(double now) const {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < kMessages; ++k) {
    const std::size_t i = (nextMessage_ + k) % kMessages;
    if (messageUntil_[i] > now) out.push_back(messages_[i]);
  }
  return out;
}

void PlayHud::update(const haptics::ServoSnapshot& s, const script::TaskJudge& judge) {
  namespace slot = physics::force_slot;
  HudReadout& r = readout_;
  r.time = s.time;
  r.timeLimit = judge.task().timeLimit;
  r.holdTime = judge.holdTime();
  r.requiredHold = judge.requiredHold();
  r.engagement = s.engagement;
  r.rampScale = s.rampScale;
  r.latenessMs = s.maxLateness * 1e3;
  r.missedTicks = s.missedTicks;
  r.loopWarning = s.missedTicks > 0 || s.lateness > kLateWarning;

  const auto comps = judge.components();
  componentCount_ = static_cast<int>(std::min(comps.size(), components_.size()));
  std::copy_n(comps.begin(), componentCount_, components_.begin());
  r.components = componentCount_;
  r.componentsInside = 0;
  double du = 0.0, dv = 0.0;
  bool contactTarget = false;
  for (int i = 0; i < componentCount_; ++i) {
    const script::ComponentStatus& c = components_[static_cast<std::size_t>(i)];
    if (c.inside) ++r.componentsInside;
    if (c.variable == script::TaskVariable::u_a) { du = c.error; contactTarget = true; }
    if (c.variable == script::TaskVariable::v_a) { dv = c.error; contactTarget = true; }
  }
  r.distanceToTarget = contactTarget ? std::hypot(du, dv) : -1.0;

  // Precession: psi's rate between frames (unwrapped), not w_z, which is the
  // spin about the face normal in body axes and differs while tilted.
  const double psi = s.state[slot::psi];
  if (lastTime_ >= 0.0 && s.time > lastTime_)
    r.precessionRate = wrapAngle(psi - lastPsi_) / (s.time - lastTime_);
  if (s.time != lastTime_) {
    lastPsi_ = psi;
    lastTime_ = s.time;
    plot_.push(static_cast<float>(s.state[static_cast<std::size_t>(kChannels[static_cast<std::size_t>(channel_)])]));
    faceX_.push(static_cast<float>(s.state[slot::x_p]));
    faceY_.push(static_cast<float>(s.state[slot::y_p]));
  }
}

void PlayHud::draw(double fps) {
  const HudReadout& r = readout_;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("hud", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  ImGui::Text("%s", level_.c_str());
  ImGui::Text("time %6.1f / %.0f s", r.time, r.timeLimit);
  if (r.distanceToTarget >= 0.0) ImGui::Text("to target %.1f mm", r.distanceToTarget * 1e3);
  ImGui::Text("precession %+.2f rad/s", r.precessionRate);
  if (r.requiredHold > 0.0) ImGui::Text("hold %.1f / %.1f s", r.holdTime, r.requiredHold);
  if (score_) ImGui::Text("score so far %.1f", *score_);
  for (int i = 0; i < componentCount_; ++i) {
    const script::ComponentStatus& c = components_[static_cast<std::size_t>(i)];
    ImGui::TextColored(c.inside ? kGreen : kRed, "%-6s %s margin %+.3g (tol %.3g)", script::taskVariableName(c.variable),
                       c.inside ? "in " : "out", c.margin, c.tolerance);
  }
  ImGui::Separator();
  ImGui::Text("%s, %s", device_.c_str(), method_.c_str());
  switch (r.engagement) {
    case haptics::Engagement::Disengaged: ImGui::TextColored(kAmber, "%s", takeHoldHint_.c_str()); break;
    case haptics::Engagement::Armed: ImGui::TextColored(kAmber, "bring the proxy onto the mass point"); break;
    case haptics::Engagement::Engaged: ImGui::Text("engaged, force %3.0f%%", r.rampScale * 100.0); break;
    case haptics::Engagement::RampingOut: ImGui::Text("letting go %3.0f%%", r.rampScale * 100.0); break;
  }
  if (mousePlayer_) ImGui::TextDisabled("a mouse pushes no force back: the arrow shows it");
  if (!ghost_.empty()) ImGui::TextColored(kGhostBlue, "%s", ghost_.c_str());
  if (!autopilot_.empty()) ImGui::TextColored(ImVec4(0.3f, 0.95f, 0.55f, 1.0f), "%s", autopilot_.c_str());
  if (r.loopWarning)
    ImGui::TextColored(kAmber, "servo loop late: worst %.2f ms, %llu missed ticks", r.latenessMs, r.missedTicks);
  ImGui::Text("%.0f fps", fps);
  ImGui::End();

  // The level's messages, top centre, oldest first.
  bool anyMessage = false;
  for (std::size_t i = 0; i < kMessages; ++i) anyMessage = anyMessage || messageUntil_[i] > r.time;
  if (anyMessage) {
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x / 2, 10), ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("messages", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoNav);
    for (std::size_t k = 0; k < kMessages; ++k) {
      const std::size_t i = (nextMessage_ + k) % kMessages;
      if (messageUntil_[i] > r.time) ImGui::TextUnformatted(messages_[i].c_str());
    }
    ImGui::End();
  }

  // Plots, bottom right.
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x - 10, size.y - 10), ImGuiCond_Always, ImVec2(1, 1));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("plots", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoNav);
  static constexpr const char* kNames[] = {"contact x u_a [m]", "contact y v_a [m]", "tilt u_o [rad]",
                                           "tilt v_o [rad]",    "heading psi [rad]", "mass point x_p [m]"};
  int channel = channel_;
  ImGui::SetNextItemWidth(200);
  if (ImGui::Combo("channel", &channel, kNames, IM_ARRAYSIZE(kNames))) setChannel(channel);
  ImGui::PlotLines("##channel", &ScrollingPlot::getter, &plot_, static_cast<int>(plot_.size()), 0, nullptr, FLT_MAX,
                   FLT_MAX, ImVec2(360, 90));
  // The mass point on the face (where the rose of the paper's Sec. 5
  // appears): the last samples as a path inside the face's circle.
  const float side = 120.0f;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("face", ImVec2(side, side));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 c(o.x + side / 2, o.y + side / 2);
  const float k = (side / 2 - 4) / static_cast<float>(faceRadius_);
  dl->AddCircle(c, side / 2 - 4, IM_COL32(160, 160, 160, 255), 48);
  for (std::size_t i = 1; i < faceX_.size(); ++i)
    dl->AddLine(ImVec2(c.x + k * faceX_.at(i - 1), c.y - k * faceY_.at(i - 1)),
                ImVec2(c.x + k * faceX_.at(i), c.y - k * faceY_.at(i)), IM_COL32(90, 200, 255, 255));
  ImGui::SameLine();
  ImGui::TextDisabled("mass point\non the face");
  ImGui::End();
}

}  // namespace hemiroll::game

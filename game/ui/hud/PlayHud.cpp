#include "game/ui/hud/PlayHud.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/physics/StateLayout.h"
#include "game/ui/hud/HintCompass.h"
#include "game/ui/hud/HudLayout.h"
#include "game/ui/hud/ImGuiLayer.h"
#include "game/ui/hud/WrappedText.h"

namespace hemiroll::game {

namespace {

const ImVec4 kGreen(0.35f, 0.85f, 0.4f, 1.0f);
const ImVec4 kRed(0.95f, 0.4f, 0.35f, 1.0f);
const ImVec4 kAmber(0.95f, 0.75f, 0.3f, 1.0f);
const ImVec4 kGhostBlue(0.55f, 0.75f, 1.0f, 1.0f);  // the ghost's own colour
constexpr double kDegrees = 180.0 / std::numbers::pi;

constexpr ImGuiWindowFlags kPanel =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;

// Designed sizes at interface scale 1 [px].
constexpr float kHudWidth = 470.0f;      // the top-left panel, wide enough for a row in one line
constexpr float kHudMinWidth = 300.0f;   // narrower than this it would only wrap everything
constexpr float kTableWidth = 470.0f;
constexpr float kMessagesWidth = 560.0f;
constexpr float kFloorReserve = 215.0f;  // the magnified floor's panel at the bottom left (FloorInset)
constexpr float kMargin = 10.0f;

double wrapAngle(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

// One decimal in the player's unit, two for bands narrower than one unit
// (a 0.5° tilt band), so that a number never reads as its band's edge.
int decimalsFor(double toleranceInUnit) { return toleranceInUnit < 1.0 ? 2 : 1; }

}  // namespace

// Enough decimals that the axis's two ends differ: one for a range of a unit
// or more, up to three for a thousandth.
// What rounds to zero at `decimals` is shown as +0.0, not -0.0.
double PlayHud::shownAs(double value, int decimals) {
  return std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}

int PlayHud::axisDecimals(double range) {
  if (!(range > 0.0) || !std::isfinite(range)) return 1;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(range))) + 1, 1, 3);
}

namespace {

}  // namespace

PlayHud::PlayHud() : faceX_(400), faceY_(400) { setPlots({}, physics::HemisphereParams{}); }

void PlayHud::reset() {
  readout_ = {};
  for (ScrollingPlot& p : plots_) p.clear();
  faceX_.clear();
  faceY_.clear();
  lastTime_ = -1.0;
  componentCount_ = 0;
  score_.reset();
  prompt_.clear();
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

void PlayHud::setPlots(const std::vector<std::string>& names, const physics::HemisphereParams& params) {
  channels_.clear();
  for (const std::string& name : names)
    if (const std::optional<HudChannel> c = HudChannel::fromName(name); c && channels_.size() < kMaxPlots)
      channels_.push_back(*c);
  // A level without plots: where the contact point is, the task of most.
  if (channels_.empty())
    for (const char* name : {"u_a", "v_a"}) channels_.push_back(*HudChannel::fromName(name));
  plots_.assign(channels_.size(), ScrollingPlot(600));
  dynamics_.emplace(params);
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

void PlayHud::update(const haptics::ServoSnapshot& s, const task::TaskJudge& judge) {
  namespace slot = physics::force_slot;
  HudReadout& r = readout_;
  r.time = s.time;
  r.timeLimit = judge.task().timeLimit;
  r.holdTime = judge.holdTime();
  r.requiredHold = judge.requiredHold();
  r.holdBreak = judge.lastHoldBreak();
  r.allInside = judge.allInside();
  r.engagement = s.engagement;
  r.rampScale = s.rampScale;
  r.latenessMs = s.maxLateness * 1e3;
  r.missedTicks = s.missedTicks;
  r.stalls = s.stalls;
  r.loopWarning = s.missedTicks > 0 || s.lateness > kLateWarning;
  r.tilt = tiltOf(s);

  const auto comps = judge.components();
  componentCount_ = static_cast<int>(std::min(comps.size(), components_.size()));
  std::copy_n(comps.begin(), componentCount_, components_.begin());
  r.components = componentCount_;
  r.componentsInside = 0;
  double du = 0.0, dv = 0.0;
  bool contactTarget = false;
  for (int i = 0; i < componentCount_; ++i) {
    const task::ComponentStatus& c = components_[static_cast<std::size_t>(i)];
    if (c.inside) ++r.componentsInside;
    if (c.variable == task::TaskVariable::u_a) { du = c.error; contactTarget = true; }
    if (c.variable == task::TaskVariable::v_a) { dv = c.error; contactTarget = true; }
  }
  r.distanceToTarget = contactTarget ? std::hypot(du, dv) : -1.0;
  adviceCount_ = game::adviceRows(std::span<const task::ComponentStatus>(components_.data(), componentCount_),
                                  screenYaw_, advice_);

  // Precession: psi's rate between frames (unwrapped), not w_z, which is the
  // spin about the face normal in body axes and differs while tilted.
  const double psi = s.state[slot::psi];
  if (lastTime_ >= 0.0 && s.time > lastTime_)
    r.precessionRate = wrapAngle(psi - lastPsi_) / (s.time - lastTime_);
  if (s.time != lastTime_) {
    lastPsi_ = psi;
    lastTime_ = s.time;
    for (std::size_t i = 0; i < channels_.size(); ++i)
      plots_[i].push(static_cast<float>(channels_[i].value(s, *dynamics_) * channels_[i].unit().scale));
    faceX_.push(static_cast<float>(s.state[slot::x_p]));
    faceY_.push(static_cast<float>(s.state[slot::y_p]));
  }
}

// The value and what it wants, not their difference: "off by" (value -
// target) made the player negate it (issue 27).
void PlayHud::componentLine(const task::ComponentStatus& c, std::span<char> out) {
  const PlayerUnit u = playerUnitOf(c.variable);
  const int d = decimalsFor(c.tolerance * u.scale);
  std::snprintf(out.data(), out.size(), "%s (%s) %+.*f %s, wants %+.*f ±%.*f %s", u.label,
                task::taskVariableName(c.variable), d, (c.target + c.error) * u.scale, u.unit, d,
                c.target * u.scale, d, c.tolerance * u.scale, u.unit);
}

std::string PlayHud::componentLine(const task::ComponentStatus& c) {
  std::array<char, 128> line{};
  componentLine(c, line);
  return line.data();
}

void PlayHud::holdBreakLine(const task::HoldBreak& b, std::span<char> out) {
  const PlayerUnit u = playerUnitOf(b.variable);
  const int d = b.excess * u.scale < 1.0 ? 2 : 1;
  std::snprintf(out.data(), out.size(), "the %s went out by %.*f %s after %.1f s", playerGroupName(b.variable), d,
                b.excess * u.scale, u.unit, b.heldFor);
}

std::string PlayHud::holdBreakLine(const task::HoldBreak& b) {
  std::array<char, 128> line{};
  holdBreakLine(b, line);
  return line.data();
}

void PlayHud::draw(double fps) {
  fps_ = fps;
  rects_.clear();
  const float scale = uiScale();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // As wide as designed, but never into the hemisphere (nor narrower than
  // the window allows).
  float width = kHudWidth * scale;
  if (keepClear_.width > 0.0f) width = std::min(width, keepClear_.x - 2 * kMargin);
  width = std::clamp(width, std::min(kHudMinWidth * scale, display.x - 2 * kMargin), display.x - 2 * kMargin);
  const float maxHeight = std::max(100.0f, display.y - 3 * kMargin - kFloorReserve * scale);
  ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, maxHeight));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("hud", nullptr, kPanel);
  drawStatus();
  drawComponents();
  drawSettleMeter();
  ImGui::Separator();
  switch (readout_.engagement) {
    case haptics::Engagement::Disengaged: wrappedText(kAmber, takeHoldHint_); break;
    case haptics::Engagement::Armed: wrappedText(kAmber, "bring the proxy onto the mass point"); break;
    case haptics::Engagement::Engaged:
      if (mousePlayer_) ImGui::TextUnformatted("holding");
      else ImGui::Text("holding, force %3.0f%%", readout_.rampScale * 100.0);
      break;
    case haptics::Engagement::RampingOut: ImGui::Text("letting go %3.0f%%", readout_.rampScale * 100.0); break;
  }
  if (!ghost_.empty()) wrappedText(kGhostBlue, ghost_);
  if (!autopilot_.empty()) wrappedText(ImVec4(0.3f, 0.95f, 0.55f, 1.0f), autopilot_);
  drawLoopNote();
  ImGui::TextDisabled("%s: %s", tableKey_.c_str(), fullTable_ ? "fewer" : "every component");
  rects_.noteCurrentWindow("hud");
  const WindowRect hud = rects_.rects().back();
  ImGui::End();

  // The full table takes the plots' place (right of the hemisphere, under
  // the messages): both would not fit beside a 720-line hemisphere.
  const WindowRect messages = drawMessages(hud.x + hud.width + kMargin, display.x - kMargin);
  const WindowRect plots = fullTable_ ? WindowRect{"plots", 0, 0, 0, 0} : drawPlots();
  const WindowRect table = drawTable(messages);
  drawPrompt(hud, messages, plots, table);
}

// What the late ticks meant for this device: a force device stops (the
// pause screen says so); a mouse rides them out, and the player may like to
// know why the clock lagged.
void PlayHud::drawLoopNote() {
  const HudReadout& r = readout_;
  if (!r.loopWarning && r.stalls == 0) return;
  char line[160];
  if (mousePlayer_ && r.stalls > 0)
    std::snprintf(line, sizeof line, "servo loop ran late %llu times (worst %.1f ms): no force to hold, play went on%s",
                  r.stalls, r.latenessMs, r.missedTicks > 0 ? ", the clock slowed" : ", caught up");
  else
    std::snprintf(line, sizeof line, "servo loop late: worst %.2f ms, %llu missed ticks", r.latenessMs, r.missedTicks);
  wrappedText(kAmber, line);
}

// The full table (I): every judged component in the physics' names, with
// the device and the frame rate; right of the hemisphere, under the
// messages, in the plots' place.
WindowRect PlayHud::drawTable(const WindowRect& messages) {
  if (!fullTable_) return WindowRect{"table", 0, 0, 0, 0};
  const float scale = uiScale();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  float left = display.x - kMargin - kTableWidth * scale;
  if (keepClear_.width > 0.0f) left = std::max(left, keepClear_.x + keepClear_.width + kMargin);
  const float width = std::max(100.0f, display.x - kMargin - left);
  const float top = messages.height > 0.0f ? messages.y + messages.height + kMargin : kMargin;
  ImGui::SetNextWindowPos(ImVec2(left, top), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, std::max(60.0f, display.y - kMargin - top)));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("table", nullptr, kPanel);
  for (int k = 0; k < componentCount_; ++k) {
    const task::ComponentStatus& c = components_[static_cast<std::size_t>(k)];
    std::array<char, 128> line{};
    componentLine(c, line);
    wrappedText(c.inside ? kGreen : kRed, line.data());
  }
  ImGui::Separator();
  char line[160];
  std::snprintf(line, sizeof line, "%s, %s; precession %+.0f °/s; %.0f fps", device_.c_str(), method_.c_str(),
                readout_.precessionRate * kDegrees, fps_);
  wrappedText(line);
  if (mousePlayer_) wrappedTextDisabled("a mouse pushes no force back: the arrow shows it");
  rects_.noteCurrentWindow("table");
  const WindowRect table = rects_.rects().back();
  ImGui::End();
  return table;
}

// The level, what it asks for (short, always on screen), and the numbers
// of now; the tilt gauge beside the numbers.
void PlayHud::drawStatus() {
  const HudReadout& r = readout_;
  wrappedText(level_);
  if (!goal_.empty()) wrappedText(ImVec4(0.85f, 0.85f, 0.7f, 1.0f), goal_);
  ImGui::BeginGroup();
  ImGui::Text("time %5.1f / %.0f s", r.time, r.timeLimit);
  if (r.distanceToTarget >= 0.0) ImGui::Text("to target %.1f mm", r.distanceToTarget * 1e3);
  if (r.requiredHold > 0.0 && fullTable_) ImGui::Text("hold %.1f / %.1f s", r.holdTime, r.requiredHold);
  if (score_) ImGui::Text("score so far %.1f", *score_);
  ImGui::EndGroup();
  ImGui::SameLine(0.0f, 24.0f * uiScale());
  drawTiltGauge();
}

// Compact: how many are in, and the few groups furthest out with what to
// do about each, in screen directions (PlayerWords). The full table (I) has
// every component in the physics' names.
void PlayHud::drawComponents() {
  if (componentCount_ == 0) return;
  const HudReadout& r = readout_;
  ImGui::TextColored(r.allInside ? kGreen : kAmber, "in their bands: %d of %d", r.componentsInside, r.components);
  std::array<int, 8> order{};
  for (int i = 0; i < adviceCount_; ++i) order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.begin() + adviceCount_, [&](int a, int b) {
    return advice_[static_cast<std::size_t>(a)].margin < advice_[static_cast<std::size_t>(b)].margin;
  });
  int shown = 0, out = 0;
  for (int k = 0; k < adviceCount_; ++k) {
    const AdviceRow& row = advice_[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
    if (row.inside) continue;
    ++out;
    if (shown == kCompactRows) continue;
    wrappedText(kRed, row.text.data());
    ++shown;
  }
  if (out > shown) ImGui::TextColored(kRed, "and %d more (%s: all)", out - shown, tableKey_.c_str());
}

// While every component is inside the hold fills up; once one wobbles out
// the meter says which and by how much, so a player knows what to steady.
void PlayHud::drawSettleMeter() {
  const HudReadout& r = readout_;
  if (r.requiredHold <= 0.0 || componentCount_ == 0) return;
  if (r.allInside) {
    char label[48];
    std::snprintf(label, sizeof label, "hold still %.1f / %.1f s", r.holdTime, r.requiredHold);
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, kGreen);
    ImGui::ProgressBar(static_cast<float>(std::clamp(r.holdTime / r.requiredHold, 0.0, 1.0)),
                       ImVec2(260 * uiScale(), 0), label);
    ImGui::PopStyleColor();
  } else if (r.holdBreak.happened && r.time - r.holdBreak.time < kHoldBreakShown) {
    std::array<char, 128> line{};
    holdBreakLine(r.holdBreak, line);
    std::array<char, 160> text{};
    std::snprintf(text.data(), text.size(), "hold lost: %s", line.data());
    wrappedText(kAmber, text.data());
  }
}

// A bubble level seen from above: the dot leans the way the face goes
// downhill (where the mass point would slide), in screen directions; rings
// every 5 degrees, the edge at 15.
void PlayHud::drawTiltGauge() {
  const float kSide = 56.0f * uiScale();
  constexpr double kEdge = 15.0;  // [degrees] at the rim
  const Tilt& t = readout_.tilt;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(kSide, kSide));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 c(o.x + kSide / 2, o.y + kSide / 2);
  const float radius = kSide / 2 - 2;
  for (int ring = 1; ring <= 3; ++ring)
    dl->AddCircle(c, radius * static_cast<float>(ring) / 3.0f, IM_COL32(150, 150, 150, ring == 3 ? 255 : 110), 32);
  double right = 0.0, up = 0.0;
  toScreenDirections(t.downhillX, t.downhillY, screenYaw_, right, up);
  const double degrees = t.angle * kDegrees;
  const float reach = radius * static_cast<float>(std::min(1.0, degrees / kEdge));
  const ImVec2 dot(c.x + reach * static_cast<float>(right), c.y - reach * static_cast<float>(up));
  dl->AddLine(c, dot, IM_COL32(120, 200, 255, 255), 2.0f * uiScale());
  dl->AddCircleFilled(dot, 4.0f * uiScale(), IM_COL32(120, 200, 255, 255));
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::Text("tilt %.1f °", degrees);
  ImGui::TextDisabled("the dot:");
  ImGui::TextDisabled("the low side");
  ImGui::EndGroup();
}

// Right of the HUD, wrapped to the room left, above the hemisphere: a long
// message never covers the HUD, the hemisphere or the table, nor runs off
// the window.
WindowRect PlayHud::drawMessages(float left, float right) {
  bool anyMessage = false;
  for (std::size_t i = 0; i < kMessages; ++i) anyMessage = anyMessage || messageUntil_[i] > readout_.time;
  if (!anyMessage) return WindowRect{"messages", left, 0, 0, 0};
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = std::max(120.0f, std::min(kMessagesWidth * uiScale(), right - left));
  const float bottom = keepClear_.height > 0.0f ? keepClear_.y - kMargin : display.y / 3;
  ImGui::SetNextWindowPos(ImVec2(left, kMargin), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(width, std::max(40.0f, bottom - kMargin)));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("messages", nullptr, kPanel);
  const float wrap = width - 2 * ImGui::GetStyle().WindowPadding.x;
  for (std::size_t k = 0; k < kMessages; ++k) {
    const std::size_t i = (nextMessage_ + k) % kMessages;
    if (messageUntil_[i] > readout_.time) wrappedText(messages_[i], wrap);
  }
  rects_.noteCurrentWindow("messages");
  const WindowRect messages = rects_.rects().back();
  ImGui::End();
  return messages;
}

// Its size is the last frame's (an auto-sized window's). Beside the HUD,
// under the level's messages: the top of the window shows sky and far
// floor, where it hides neither the hemisphere nor the targets round it;
// else right of the hemisphere, or under it, or under the HUD.
void PlayHud::drawPrompt(const WindowRect& hud, const WindowRect& messages, const WindowRect& plots,
                         const WindowRect& table) {
  if (prompt_.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float w = promptSize_.x, h = promptSize_.y;
  const WindowRect taken[] = {hud, messages, plots, table, keepClear_,
                              WindowRect{"floor", 0, display.y - kFloorReserve * uiScale(), hud.width, display.y}};
  const float besideHud = hud.x + hud.width + kMargin;
  const float rightOfBall = keepClear_.x + keepClear_.width + kMargin;
  const PanelPlace at = firstFreePlace(
      {{besideHud, messages.y + messages.height + kMargin},
       {besideHud, kMargin},
       {rightOfBall, table.height > 0.0f ? table.y + table.height + kMargin : kMargin},
       {display.x / 2 - w / 2, keepClear_.y + keepClear_.height + kMargin},
       {kMargin, hud.y + hud.height + kMargin}},
      w, h, taken, display.x, display.y);
  ImGui::SetNextWindowPos(ImVec2(at.x, at.y), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("prompt", nullptr, kPanel);
  ImGui::SetWindowFontScale(1.3f);
  ImGui::TextColored(kAmber, "%s", prompt_.c_str());
  rects_.noteCurrentWindow("prompt");
  promptSize_ = {ImGui::GetWindowSize().x, ImGui::GetWindowSize().y};
  ImGui::End();
}

WindowRect PlayHud::drawPlots() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x - 10, size.y - 10), ImGuiCond_Always, ImVec2(1, 1));
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::Begin("plots", nullptr, kPanel);
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    const PlayerUnit& u = channels_[i].unit();
    const ScrollingPlot& p = plots_[i];
    float lo = p.size() ? p.min() : 0.0f, hi = p.size() ? p.max() : 0.0f;
    // A flat trace still gets an axis: a unit either side of its value.
    if (hi - lo < 1e-3f) {
      lo -= 1.0f;
      hi += 1.0f;
    }
    const int d = axisDecimals(hi - lo);
    ImGui::Text("%s [%s]  now %+.*f", u.label, u.unit, d, shownAs(p.size() ? p.at(p.size() - 1) : 0.0f, d));
    const float scale = uiScale();
    ImGui::BeginGroup();
    ImGui::TextDisabled("%+7.*f", d, shownAs(hi, d));
    ImGui::Dummy(ImVec2(0, 18 * scale));
    ImGui::TextDisabled("%+7.*f", d, shownAs(lo, d));
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::PlotLines(i == 0 ? "##plot0" : i == 1 ? "##plot1" : "##plot2", &ScrollingPlot::getter,
                     const_cast<ScrollingPlot*>(&p), static_cast<int>(p.size()), 0, nullptr, lo, hi,
                     ImVec2(300 * scale, 58 * scale));
  }
  // The mass point on the face (where the rose of the paper's Sec. 5
  // appears): the last samples as a path inside the face's circle, and where
  // it is now as a dot a player can see (it was the path's 1-2 px end).
  const float side = 100.0f * uiScale();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(side, side));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 c(o.x + side / 2, o.y + side / 2);
  const float k = (side / 2 - 4) / static_cast<float>(faceRadius_);
  dl->AddCircle(c, side / 2 - 4, IM_COL32(160, 160, 160, 255), 48);
  for (std::size_t i = 1; i < faceX_.size(); ++i)
    dl->AddLine(ImVec2(c.x + k * faceX_.at(i - 1), c.y - k * faceY_.at(i - 1)),
                ImVec2(c.x + k * faceX_.at(i), c.y - k * faceY_.at(i)), IM_COL32(90, 200, 255, 255),
                1.5f * uiScale());
  dl->AddLine(ImVec2(c.x - 4 * uiScale(), c.y), ImVec2(c.x + 4 * uiScale(), c.y), IM_COL32(160, 160, 160, 255));
  dl->AddLine(ImVec2(c.x, c.y - 4 * uiScale()), ImVec2(c.x, c.y + 4 * uiScale()), IM_COL32(160, 160, 160, 255));
  if (faceX_.size() > 0) {
    const ImVec2 now(c.x + k * faceX_.at(faceX_.size() - 1), c.y - k * faceY_.at(faceY_.size() - 1));
    dl->AddCircleFilled(now, 5.0f * uiScale(), IM_COL32(255, 205, 60, 255));  // the mass point's own yellow
    dl->AddCircle(now, 5.0f * uiScale(), IM_COL32(40, 40, 40, 255));
  }
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::TextDisabled("mass point");
  ImGui::TextDisabled("on the face");
  ImGui::TextDisabled("(radius %.0f mm)", faceRadius_ * 1e3);
  ImGui::EndGroup();
  rects_.noteCurrentWindow("plots");
  const WindowRect plots = rects_.rects().back();
  ImGui::End();
  return plots;
}

}  // namespace hemiroll::game

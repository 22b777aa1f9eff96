#include "game/ui/screens/SettingsScreen.h"

#include <imgui.h>

#include <algorithm>

#include "engine/haptics/devices/sdl/DeviceFactory.h"
#include "engine/physics/ForceCoupling.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/audio/Audio.h"
#include "game/ui/hud/WrappedText.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenLayout.h"
#include "game/ui/screens/ScreenStack.h"
#include "game/trial/DeviceProfiles.h"

namespace hemiroll::game {

void SettingsScreen::leave() { host_.saveSettings(); }

void SettingsScreen::input(const platform::InputEvent& e) {
  if (e.type != platform::InputType::KeyDown || e.repeat) return;
  if (!listening_) {
    if (e.key == platform::Key::Escape) host_.screens().pop();
    return;
  }
  const KeyAction action = *listening_;
  listening_.reset();
  KeyBindings& keys = host_.settings().keys;
  if (e.key == platform::Key::Escape) {
    keyNote_ = "unchanged: Escape always pauses and goes back";
    return;
  }
  const std::optional<KeyAction> holder = keys.actionOf(e.code);
  const std::string old = keys.keyName(action);
  if (!keys.bind(action, e.code)) {
    keyNote_ = "unchanged: that key cannot be bound";
    return;
  }
  keyNote_ = std::string(keyActionInfo(action).label) + ": " + keys.keyName(action);
  if (holder && *holder != action) keyNote_ += " (" + std::string(keyActionInfo(*holder).label) + " took " + old + ")";
}

void SettingsScreen::listenFor(KeyAction action) {
  listening_ = action;
  keyNote_.clear();
}

void SettingsScreen::paintKeys() {
  KeyBindings& keys = host_.settings().keys;
  wrappedTextDisabled("mouse: left click takes hold, right click lets go, the wheel sets the proxy's height; "
                      "Esc pauses (and cannot be changed)");
  // Two actions a row, each its name and a button with its key; the
  // buttons stand right of the longest name at this font scale.
  float longest = 0.0f;
  for (int i = 0; i < kKeyActionCount; ++i)
    longest = std::max(longest, ImGui::CalcTextSize(keyActionInfo(static_cast<KeyAction>(i)).label).x);
  const float kButtonAt = longest + ImGui::GetStyle().ItemSpacing.x * 2;
  const float kButtonWidth = std::max(100.0f, (ImGui::GetContentRegionAvail().x - 2 * kButtonAt) / 2 - 16.0f);
  const float kColumn = kButtonAt + kButtonWidth + 16.0f;
  for (int i = 0; i < kKeyActionCount; ++i) {
    const auto action = static_cast<KeyAction>(i);
    const float left = (i % 2) * kColumn;
    if (i % 2 == 1) ImGui::SameLine(left);
    ImGui::PushID(i);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(keyActionInfo(action).label);
    ImGui::SameLine(left + kButtonAt);
    const std::string label = listening_ == action ? "press a key..." : keys.keyName(action);
    if (ImGui::Button(label.c_str(), ImVec2(kButtonWidth, 0))) listenFor(action);
    ImGui::PopID();
  }
  if (listening_) ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "press the key for %s (Esc: cancel)",
                                     keyActionInfo(*listening_).label);
  if (ImGui::Button("default keys")) {
    keys = KeyBindings{};
    listening_.reset();
    keyNote_ = "the default keys";
  }
  if (!keyNote_.empty()) wrappedTextDisabled(keyNote_);
}

void SettingsScreen::paintDevice(Settings& s) {
  bool first = true;
  for (const char* device : haptics::kPlayerDevices) {
    if (!first) ImGui::SameLine();
    first = false;
    if (ImGui::RadioButton(device, s.device == device)) s.device = device;
  }
  if (s.device == haptics::kMouseDevice) {
    wrappedTextDisabled("no force feedback: the coupling force is drawn as an arrow (and the force cues below)");
    float mm = static_cast<float>(s.mouseMmPerPixel);
    if (ImGui::SliderFloat("mouse: mm per pixel", &mm, static_cast<float>(kMouseMmPerPixel[0]),
                           static_cast<float>(kMouseMmPerPixel[1]), "%.2f", ImGuiSliderFlags_Logarithmic))
      s.mouseMmPerPixel = std::clamp(static_cast<double>(mm), kMouseMmPerPixel[0], kMouseMmPerPixel[1]);
    wrappedTextDisabled("how far the proxy moves per pixel of mouse motion: lower is finer, higher reaches further "
                        "(0.25 spans a desk device's 20 cm in 800 pixels)");
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("mouse feel:");
    ImGui::SameLine();
    if (ImGui::RadioButton("direct", s.mouseFeel == MouseFeel::Direct)) s.mouseFeel = MouseFeel::Direct;
    ImGui::SameLine();
    if (ImGui::RadioButton("hand", s.mouseFeel == MouseFeel::Hand)) s.mouseFeel = MouseFeel::Hand;
    wrappedTextDisabled(s.mouseFeel == MouseFeel::Hand
                            ? "hand: the proxy is a simulated hand (0.3 kg, 300 N/m, 15 N s/m) that the mouse pulls "
                              "on a spring and the force pushes back, as a force device pushes your hand"
                            : "direct: the proxy is where the mouse puts it");
  } else if (s.device == haptics::kJoystickDevice) {
    ImGui::InputInt("joystick index", &s.joystickIndex);
    s.joystickIndex = std::clamp(s.joystickIndex, 0, 63);
    wrappedTextDisabled("an SDL force-feedback joystick or wheel (constant-force effect)");
  } else {
    ImGui::InputInt("udp port", &s.udpPort);
    s.udpPort = std::clamp(s.udpPort, 1, 65535);
    wrappedTextf("a haptic device behind the UDP bridge on 127.0.0.1:%d: start its bridge program "
                 "(or hemiroll-haptic-client); the trial starts with its first state (docs/UDP_BRIDGE.md)",
                 s.udpPort);
    // The device's limits: the shipped profiles, read once (devices/*.lua).
    static const std::vector<std::string> profiles = deviceProfileNames();
    const char* shown = s.deviceProfile.empty() ? "none (the bridge's defaults)" : s.deviceProfile.c_str();
    if (ImGui::BeginCombo("device profile", shown)) {
      if (ImGui::Selectable("none (the bridge's defaults)", s.deviceProfile.empty())) s.deviceProfile.clear();
      for (const std::string& name : profiles)
        if (ImGui::Selectable(name.c_str(), name == s.deviceProfile)) s.deviceProfile = name;
      ImGui::EndCombo();
    }
    wrappedTextDisabled("the device's peak force, stiffness and workspace (devices/NAME.lua): the safety layer holds "
                        "every trial to them");
  }
}

void SettingsScreen::paintForceCues(Settings& s) {
  wrappedTextDisabled("what stands in for the force you cannot feel with a mouse");
  ImGui::Checkbox("strain ring round the proxy", &s.strainRing);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::Checkbox("force tone", &s.forceTone);
  ImGui::Checkbox("edge warning", &s.fallWarning);
  ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.55f);
  ImGui::Checkbox("rumble (gamepad)", &s.rumble);
  wrappedTextDisabled("ring: grows and turns red as the coupling pulls harder (red: as hard as 0.4 of the mass "
                      "point's weight); tone: its pitch rises with the pull; edge warning: the screen's edge "
                      "pulses red before the mass point slides off the face");
}

void SettingsScreen::paintForceMethod(Settings& s) {
  ImGui::Checkbox("override the level's method and gains", &s.overrideCoupling);
  ImGui::BeginDisabled(!s.overrideCoupling);
  static constexpr const char* kMethods[] = {"M1", "M2", "M3 (the paper's)", "visual only"};
  ImGui::Combo("method", &s.method, kMethods, IM_ARRAYSIZE(kMethods));
  float k = static_cast<float>(s.stiffness), c = static_cast<float>(s.damping), a = static_cast<float>(s.alpha);
  if (ImGui::SliderFloat("stiffness k_r [N/m]", &k, 10.0f, 1000.0f, "%.0f")) s.stiffness = k;
  if (ImGui::SliderFloat("damping k_v [N s/m]", &c, 0.0f, 40.0f, "%.1f")) s.damping = c;
  if (ImGui::SliderFloat("M3 alpha [-]", &a, 0.5f, 5.0f, "%.1f")) s.alpha = a;
  ImGui::EndDisabled();
  if (s.overrideCoupling) {
    const std::string problem = physics::validateCoupling(couplingFor(s, physics::CouplingDef{}));
    if (!problem.empty()) wrappedText(ImVec4(1, 0.5f, 0.4f, 1), problem);
  }
}

void SettingsScreen::paintAudio(Settings& s) {
  float volume = static_cast<float>(s.volume);
  if (ImGui::SliderFloat("volume", &volume, 0.0f, 1.0f, "%.2f")) {
    s.volume = volume;
    host_.audio().setVolume(volume);
  }
  if (!host_.audio().available()) wrappedTextDisabled(host_.audio().note());
}

void SettingsScreen::paintGraphics(Settings& s) {
  bool vsync = s.vsync;
  if (ImGui::Checkbox("vsync", &vsync)) host_.setVsync(vsync);
  int cap = s.frameCap;
  if (ImGui::SliderInt("frame cap [fps]", &cap, kFrameCapFps[0], kFrameCapFps[1]))
    s.frameCap = std::clamp(cap, kFrameCapFps[0], kFrameCapFps[1]);
  wrappedTextDisabled("frames in play at most (watching the autopilot and menus 30, paused 15): the rest of the "
                      "CPU goes to the 1 kHz servo loop and the autopilot");
  float scale = static_cast<float>(s.uiScale);
  if (ImGui::SliderFloat("interface scale", &scale, static_cast<float>(kUiScale[0]), static_cast<float>(kUiScale[1]),
                         "%.2f"))
    s.uiScale = std::clamp(static_cast<double>(scale), kUiScale[0], kUiScale[1]);
  wrappedTextDisabled("text and dials, times the window's height / 720");
  int camera = static_cast<int>(s.camera);
  static constexpr const char* kCameras[] = {"follow", "orbit", "top"};
  if (ImGui::Combo("camera", &camera, kCameras, IM_ARRAYSIZE(kCameras))) s.camera = static_cast<render::CameraMode>(camera);
  float zoom = static_cast<float>(s.zoom);
  if (ImGui::SliderFloat("zoom", &zoom, 0.5f, 3.0f, "%.2f")) s.zoom = zoom;
  ImGui::Checkbox("race against your best run (a translucent ghost)", &s.ghost);
}

void SettingsScreen::paint() {
  Settings& s = host_.settings();
  beginCentredPanel("settings", 620);
  ImGui::SetWindowFontScale(1.6f);
  ImGui::Text("Settings");
  ImGui::SetWindowFontScale(1.0f);
  // Half the panel for a slider, the rest for its label: the longest label
  // ("stiffness k_r [N/m]", "mouse: mm per pixel") then fits beside it.
  ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Device");
  paintDevice(s);

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Force cues");
  paintForceCues(s);

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Force method");
  paintForceMethod(s);

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Keys");
  paintKeys();

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Audio");
  paintAudio(s);

  ImGui::Separator();
  ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.35f, 1), "Graphics");
  paintGraphics(s);

  ImGui::Spacing();
  if (ImGui::Button("Back  (Esc)", ImVec2(-1, 0))) host_.screens().pop();
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace hemiroll::game

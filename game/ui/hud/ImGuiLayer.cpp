#include "game/ui/hud/ImGuiLayer.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hemiroll::game {

namespace {

// ImGui's key map indices: our Key enum's values (small, below 512).
int keyIndex(platform::Key key) { return 256 + static_cast<int>(key); }

int buttonIndex(platform::PointerButton b) {
  switch (b) {
    case platform::PointerButton::Left: return 0;
    case platform::PointerButton::Right: return 1;
    case platform::PointerButton::Middle: return 2;
    default: return -1;
  }
}

}  // namespace

float uiScale() { return ImGui::GetIO().FontGlobalScale / kBaseFontScale; }

ImGuiLayer::ImGuiLayer() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the player's working directory
  io.FontGlobalScale = kBaseFontScale;
  io.KeyMap[ImGuiKey_Enter] = keyIndex(platform::Key::Enter);
  io.KeyMap[ImGuiKey_Escape] = keyIndex(platform::Key::Escape);
  io.KeyMap[ImGuiKey_Space] = keyIndex(platform::Key::Space);
  io.KeyMap[ImGuiKey_UpArrow] = keyIndex(platform::Key::Up);
  io.KeyMap[ImGuiKey_DownArrow] = keyIndex(platform::Key::Down);
  io.KeyMap[ImGuiKey_LeftArrow] = keyIndex(platform::Key::Left);
  io.KeyMap[ImGuiKey_RightArrow] = keyIndex(platform::Key::Right);
  io.KeyMap[ImGuiKey_Tab] = keyIndex(platform::Key::Tab);
  io.KeyMap[ImGuiKey_Backspace] = keyIndex(platform::Key::Backspace);
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 6.0f;
  designed_ = std::make_unique<ImGuiStyle>(ImGui::GetStyle());
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext();
    throw std::runtime_error("Dear ImGui's OpenGL 3 backend did not start");
  }
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

bool ImGuiLayer::feed(const platform::InputEvent& e) {
  ImGuiIO& io = ImGui::GetIO();
  using platform::InputType;
  switch (e.type) {
    case InputType::PointerMove:
      io.MousePos = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
      return io.WantCaptureMouse;
    case InputType::ButtonDown: {
      io.MousePos = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
      const int b = buttonIndex(e.button);
      if (b >= 0) {
        io.MouseDown[b] = true;
        pressedThisFrame_[b] = true;
        releasePending_[b] = false;
      }
      return wantsPointer();
    }
    case InputType::ButtonUp: {
      const int b = buttonIndex(e.button);
      if (b >= 0) {
        if (pressedThisFrame_[b])
          releasePending_[b] = true;  // let ImGui see the press for one frame first
        else
          io.MouseDown[b] = false;
      }
      return io.WantCaptureMouse;
    }
    case InputType::Wheel:
      io.MouseWheel += static_cast<float>(e.wheel);
      return io.WantCaptureMouse;
    case InputType::KeyDown:
    case InputType::KeyUp: {
      const bool down = e.type == InputType::KeyDown;
      if (e.key != platform::Key::Other) io.KeysDown[keyIndex(e.key)] = down;
      // Printable keys type their character (participant ids, file names).
      if (down && e.key == platform::Key::Other && e.code >= 32 && e.code < 127)
        io.AddInputCharacter(static_cast<unsigned>(e.code));
      return io.WantCaptureKeyboard;
    }
    default:
      return false;
  }
}

void ImGuiLayer::setScale(double scale) {
  scale = std::clamp(std::isfinite(scale) ? scale : 1.0, 0.5, 4.0);
  if (scale == scale_) return;
  scale_ = scale;
  ImGui::GetIO().FontGlobalScale = kBaseFontScale * static_cast<float>(scale);
  ImGui::GetStyle() = *designed_;
  ImGui::GetStyle().ScaleAllSizes(static_cast<float>(scale));
}

bool ImGuiLayer::wantsPointer() const { return ImGui::GetIO().WantCaptureMouse; }

void ImGuiLayer::beginFrame(int width, int height, int drawableWidth, int drawableHeight, double dt) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  if (width > 0 && height > 0)
    io.DisplayFramebufferScale = ImVec2(static_cast<float>(drawableWidth) / static_cast<float>(width),
                                        static_cast<float>(drawableHeight) / static_cast<float>(height));
  io.DeltaTime = static_cast<float>(std::max(dt, 1e-4));  // ImGui asserts on a zero step
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::endFrame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ImGuiIO& io = ImGui::GetIO();
  for (int b = 0; b < 3; ++b) {
    if (releasePending_[b]) io.MouseDown[b] = false;
    releasePending_[b] = false;
    pressedThisFrame_[b] = false;
  }
}

}  // namespace hemiroll::game

#include "engine/haptics/devices/sdl/SdlJoystickDevice.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <ctime>

namespace hemiroll::haptics {

namespace {

constexpr int kMaxAxes = 8;
constexpr int kMaxButtons = 32;

void sleepUntil(std::int64_t deadlineNs) {
  timespec ts{static_cast<time_t>(deadlineNs / 1'000'000'000), static_cast<long>(deadlineNs % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

SDL_HapticEffect constantEffect(const ConstantForceCommand& c) {
  SDL_HapticEffect e;
  SDL_memset(&e, 0, sizeof e);
  e.type = SDL_HAPTIC_CONSTANT;
  e.constant.direction.type = SDL_HAPTIC_CARTESIAN;
  for (int i = 0; i < 3; ++i) e.constant.direction.dir[i] = c.direction[static_cast<std::size_t>(i)];
  e.constant.length = SDL_HAPTIC_INFINITY;
  e.constant.level = c.level;
  return e;
}

}  // namespace

SdlJoystickDevice::SdlJoystickDevice(const SdlJoystickDef& def) : def_(def), spec_(def.spec), velocity_(def.velocity) {}

SdlJoystickDevice::~SdlJoystickDevice() { close(); }

bool SdlJoystickDevice::fail(std::string message) {
  close();
  openError_ = "SDL joystick: " + std::move(message);
  return false;
}

bool SdlJoystickDevice::open() {
  close();
  openError_.clear();
  spec_ = def_.spec;
  if (!(def_.updateRate >= 1.0 && def_.updateRate <= 10000.0)) return fail("updateRate must be within 1..10000 Hz");
  if (SDL_InitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_HAPTIC) != 0)
    return fail(std::string("SDL could not start its joystick and haptic subsystems: ") + SDL_GetError());
  subsystems_ = true;
  const int count = SDL_NumJoysticks();
  if (count <= 0) return fail("no joystick found (SDL sees none); connect one, or choose the mouse or the UDP bridge");
  if (def_.index < 0 || def_.index >= count)
    return fail("no joystick number " + std::to_string(def_.index) + " (SDL sees " + std::to_string(count) +
                ", numbered from 0)");
  joystick_ = SDL_JoystickOpen(def_.index);
  if (joystick_ == nullptr)
    return fail("cannot open joystick " + std::to_string(def_.index) + ": " + SDL_GetError());
  const char* name = SDL_JoystickName(joystick_);
  name_ = name != nullptr ? name : "unnamed joystick";
  const int axes = SDL_JoystickNumAxes(joystick_);
  const int needed = std::max({def_.mapping.axisX, def_.mapping.axisY, def_.mapping.axisZ}) + 1;
  if (axes < needed || needed > kMaxAxes)
    return fail("'" + name_ + "' has " + std::to_string(axes) + " axes; the mapping uses axis " +
                std::to_string(needed - 1));

  if (SDL_JoystickIsHaptic(joystick_) == 1) haptic_ = SDL_HapticOpenFromJoystick(joystick_);
  if (haptic_ != nullptr) {
    if ((SDL_HapticQuery(haptic_) & SDL_HAPTIC_CONSTANT) == 0)
      return fail("'" + name_ + "' has force feedback but no constant-force effect");
    SDL_HapticEffect e = constantEffect({});
    effect_ = SDL_HapticNewEffect(haptic_, &e);
    if (effect_ < 0 || SDL_HapticRunEffect(haptic_, effect_, 1) != 0)
      return fail("cannot start a constant-force effect on '" + name_ + "': " + SDL_GetError());
  } else if (def_.requireForceFeedback && !(def_.acceptRumble && SDL_JoystickHasRumble(joystick_) == SDL_TRUE)) {
    return fail("'" + name_ +
                "' has no force feedback (SDL_Haptic cannot drive it); set requireForceFeedback = false to use "
                "it as an input-only device");
  }
  spec_.hasForceOutput = haptic_ != nullptr;
  disconnectedError_ = "SDL joystick: '" + name_ + "' was disconnected";
  current_ = Pose{};
  lastSerial_ = 0;
  health_.store(Health::Starting, std::memory_order_relaxed);
  stop_.store(false, std::memory_order_relaxed);
  firstPose_.store(false, std::memory_order_relaxed);
  thread_ = std::thread([this] { run(); });
  // The loop may tick right after open(): wait for the first pose, so that
  // its first read is not an error.
  for (int i = 0; i < 500 && !firstPose_.load(std::memory_order_acquire); ++i) sleepUntil(monotonicNowNs() + 1'000'000);
  if (!firstPose_.load(std::memory_order_acquire)) return fail("the device thread delivered no pose within 0.5 s");
  return true;
}

void SdlJoystickDevice::close() {
  if (thread_.joinable()) {
    stop_.store(true, std::memory_order_relaxed);
    thread_.join();
  }
  if (haptic_ != nullptr) {
    if (effect_ >= 0) {
      SDL_HapticStopEffect(haptic_, effect_);
      SDL_HapticDestroyEffect(haptic_, effect_);
    }
    SDL_HapticClose(haptic_);
  }
  haptic_ = nullptr;
  effect_ = -1;
  if (joystick_ != nullptr) SDL_JoystickClose(joystick_);
  joystick_ = nullptr;
  if (subsystems_) SDL_QuitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_HAPTIC);
  subsystems_ = false;
  health_.store(Health::NotOpen, std::memory_order_relaxed);
}

void SdlJoystickDevice::run() {
  const auto period = static_cast<std::int64_t>(std::llround(1e9 / def_.updateRate));
  const int axisCount = std::min(SDL_JoystickNumAxes(joystick_), kMaxAxes);
  const int buttonCount = std::min(SDL_JoystickNumButtons(joystick_), kMaxButtons);
  ConstantForceCommand sent;
  bool sentAny = false;
  Pose pose;
  std::int64_t deadline = monotonicNowNs();
  while (!stop_.load(std::memory_order_relaxed)) {
    SDL_JoystickUpdate();
    std::int16_t axes[kMaxAxes] = {};
    for (int i = 0; i < axisCount; ++i) axes[i] = SDL_JoystickGetAxis(joystick_, i);
    const Vec3 p = axesToPosition(def_.mapping, axes, axisCount);
    pose.position = {p.x(), p.y(), p.z()};
    pose.buttons = 0;
    for (int i = 0; i < buttonCount; ++i)
      if (SDL_JoystickGetButton(joystick_, i) != 0) pose.buttons |= 1u << i;
    pose.attached = SDL_JoystickGetAttached(joystick_) == SDL_TRUE;
    ++pose.serial;
    poses_.write(pose);
    firstPose_.store(true, std::memory_order_release);

    ForceSample f;
    if (haptic_ != nullptr && forces_.read(f)) {
      // Only changes go to the device: each update is a USB write.
      const ConstantForceCommand c = forceToConstantEffect(Vec3(f.force[0], f.force[1], f.force[2]), spec_.maxForce);
      if (!sentAny || !(c == sent)) {
        SDL_HapticEffect e = constantEffect(c);
        SDL_HapticUpdateEffect(haptic_, effect_, &e);
        sent = c;
        sentAny = true;
      }
    }
    deadline += period;
    sleepUntil(deadline);
  }
  if (haptic_ != nullptr) {  // leave the stick slack
    SDL_HapticEffect e = constantEffect({});
    SDL_HapticUpdateEffect(haptic_, effect_, &e);
  }
}

DeviceReading SdlJoystickDevice::read(double /*t: the stick runs on wall time*/) {
  Pose p;
  const bool any = poses_.read(p);
  if (any) current_ = p;
  const Vec3 position(current_.position[0], current_.position[1], current_.position[2]);
  DeviceReading r;
  r.fresh = current_.serial != lastSerial_;
  r.position = position;
  r.velocity = velocity_.update(static_cast<double>(monotonicNowNs()) * 1e-9, position, r.fresh);
  r.buttons = current_.buttons;
  lastSerial_ = current_.serial;
  if (health_.load(std::memory_order_relaxed) != Health::NotOpen)
    health_.store(!any ? Health::Starting : current_.attached ? Health::Ok : Health::Disconnected,
                  std::memory_order_relaxed);
  return r;
}

void SdlJoystickDevice::sendForce(const Vec3& force) {
  ForceSample f;
  f.force = {force.x(), force.y(), force.z()};
  forces_.write(f);
}

const char* SdlJoystickDevice::error() const {
  switch (health_.load(std::memory_order_relaxed)) {
    case Health::Ok: return nullptr;
    case Health::NotOpen: return openError_.empty() ? "SDL joystick: not open" : openError_.c_str();
    case Health::Starting: return "SDL joystick: no reading from the device thread yet";
    case Health::Disconnected: return disconnectedError_.c_str();
  }
  return "SDL joystick: unknown state";
}

bool SdlJoystickDevice::rumble(double strength) {
  if (joystick_ == nullptr || SDL_JoystickHasRumble(joystick_) != SDL_TRUE) return false;
  const double s = std::isfinite(strength) ? std::clamp(strength, 0.0, 1.0) : 0.0;
  const auto level = static_cast<Uint16>(std::lround(s * 0xFFFF));
  return SDL_JoystickRumble(joystick_, level, level, 150) == 0;
}

}  // namespace hemiroll::haptics

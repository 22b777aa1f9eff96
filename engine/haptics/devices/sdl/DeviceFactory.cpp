#include "engine/haptics/devices/sdl/DeviceFactory.h"

#include <sstream>
#include <utility>

namespace hemiroll::haptics {

DeviceFactory::DeviceFactory() {
  add(kMouseDevice, "the pointer on a horizontal plane, wheel for height; forces shown, not felt",
      [](const DeviceOptions& o) { return std::make_unique<MouseDevice>(o.mouse); });
  add(kMouseHandDevice, "the mouse through a simulated hand: the pointer pulls it, the coupling force pushes it",
      [](const DeviceOptions& o) { return std::make_unique<MouseDevice>(mouseHandDef(o.mouse, o.mouseHand)); });
  add(kJoystickDevice, "a force-feedback joystick through SDL_Haptic (constant-force effect)",
      [](const DeviceOptions& o) { return std::make_unique<SdlJoystickDevice>(o.joystick); });
  add(kUdpDevice, "a real haptic device driven by an external program over the UDP bridge",
      [](const DeviceOptions& o) { return std::make_unique<UdpBridgeDevice>(o.udp); });
  add(kScriptedDevice, "the pose is a function of time (bots, headless runs)", [](const DeviceOptions& o) {
    ScriptedDevice::PoseFunction pose = o.scriptedPose ? o.scriptedPose : [](double) { return DeviceReading{}; };
    return std::make_unique<ScriptedDevice>(std::move(pose), o.scriptedSpec);
  });
  add(kSimulatedHandDevice, "a spring-mass hand following an intent and pushed by the force", [](const DeviceOptions& o) {
    SimulatedHandDevice::IntentFunction intent =
        o.handIntent ? o.handIntent : [](double) { return SimulatedHandDevice::Intent{}; };
    return std::make_unique<SimulatedHandDevice>(std::move(intent), o.hand, o.handSpec);
  });
}

void DeviceFactory::add(const std::string& name, const std::string& description, Maker make) {
  for (Entry& e : entries_) {
    if (e.name == name) {
      e = {name, description, std::move(make)};
      return;
    }
  }
  entries_.push_back({name, description, std::move(make)});
}

std::optional<DeviceSpec> DeviceFactory::specOf(const std::string& name, const DeviceOptions& options) const {
  const DeviceChoice c = make(name, options);
  if (!c.device) return std::nullopt;
  return c.device->spec();
}

DeviceChoice DeviceFactory::make(const std::string& name, const DeviceOptions& options) const {
  DeviceChoice c;
  for (const Entry& e : entries_) {
    if (e.name != name) continue;
    try {
      c.device = e.make(options);
    } catch (const std::exception& ex) {  // constructors reject invalid definitions with a sentence
      c.error = "device '" + name + "': " + ex.what();
      return c;
    }
    if (!c.device) c.error = "device '" + name + "' could not be created";
    return c;
  }
  std::string known;
  for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
  c.error = "unknown device '" + name + "'; known devices: " + known;
  return c;
}

DeviceChoice DeviceFactory::makeAndOpen(const std::string& name, const DeviceOptions& options) const {
  DeviceChoice c = make(name, options);
  if (c.device && !c.device->open()) {
    const char* why = c.device->error();
    c.error = why != nullptr ? why : "device '" + name + "' failed to open";
    c.device.reset();
  }
  return c;
}

std::vector<std::string> DeviceFactory::names() const {
  std::vector<std::string> n;
  for (const Entry& e : entries_) n.push_back(e.name);
  return n;
}

std::string DeviceFactory::describe(const DeviceOptions& options) const {
  std::ostringstream out;
  for (const Entry& e : entries_) {
    out << e.name << ": " << e.description;
    const DeviceChoice c = make(e.name, options);
    if (c.device) out << " [" << describeSpec(c.device->spec()) << "]";
    out << "\n";
  }
  return out.str();
}

std::string describeSpec(const DeviceSpec& s) {
  std::ostringstream out;
  out << "maxForce " << s.maxForce << " N, maxStiffness " << s.maxStiffness << " N/m, workspace radius "
      << s.workspaceRadius << " m, force output " << (s.hasForceOutput ? "yes" : "no");
  return out.str();
}

}  // namespace hemiroll::haptics

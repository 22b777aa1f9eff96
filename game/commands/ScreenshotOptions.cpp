#include "game/commands/ScreenshotOptions.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

#include "engine/physics/StateLayout.h"

namespace hemiroll::game {

namespace {

bool parseDouble(const std::string& text, double& value) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, value);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(value);
}

bool parseInt(const std::string& text, int& value) {
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, value);
  return r.ec == std::errc() && r.ptr == end;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, sep)) parts.push_back(part);
  return parts;
}

// "x_p=0.01,psi=1.2" -> slots; the error names the bad item.
std::string parseState(const std::string& text, std::vector<std::pair<int, double>>& out) {
  for (const std::string& item : split(text, ',')) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) return "--state: '" + item + "' is not name=value";
    const std::string name = item.substr(0, eq);
    int slot = -1;
    for (int i = 0; i < 12; ++i)
      if (name == physics::kStateNames[i]) slot = i;
    if (slot < 0)
      return "--state: unknown state variable '" + name +
             "' (x_p, y_p, xd_p, yd_p, w_x, w_y, w_z, u_a, v_a, u_o, v_o, psi)";
    double value = 0.0;
    if (!parseDouble(item.substr(eq + 1), value)) return "--state: " + name + " needs a finite number";
    out.emplace_back(slot, value);
  }
  return "";
}

}  // namespace

const char* screenshotUsage() {
  return "usage: hemiroll screenshot LEVEL.lua --out FILE.png [--state NAME=VALUE,...]\n"
         "                           [--camera follow|orbit|top] [--zoom Z] [--size WxH]\n"
         "                           [--proxy X,Y,Z] [--frames N]\n"
         "\n"
         "Renders one frame of a level offscreen and writes it as a PNG: the level's\n"
         "hemisphere, initial state and targets (docs/RENDERING.md). Needs a display;\n"
         "headless, run it under a virtual one: xvfb-run -a hemiroll screenshot ...\n"
         "\n"
         "  --out FILE.png      where the image goes (required)\n"
         "  --state N=V,...     override initial state variables (SI: m, m/s, rad/s, rad),\n"
         "                      names as in the level file (x_p, ..., psi)\n"
         "  --camera MODE       follow (default), orbit or top\n"
         "  --zoom Z            > 0, 2 = twice as close (default 1)\n"
         "  --size WxH          image size in pixels (default 1280x720)\n"
         "  --proxy X,Y,Z       show the haptic proxy there [m, scene frame], with the\n"
         "                      spring and the level's coupling force on the mass point\n"
         "  --frames N          also render N frames and print the median frames per second\n"
         "  --help              print this help\n"
         "\n"
         "Exit codes: 0 written, 1 no display or the file could not be written,\n"
         "2 bad input (a flag, or a level that cannot be loaded: file:line).\n";
}

ScreenshotOptionsResult parseScreenshotOptions(const std::vector<std::string>& args) {
  ScreenshotOptionsResult result;
  ScreenshotOptions& o = result.options;
  auto fail = [&](const std::string& message) {
    result.error = message;
    return result;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    if (arg == "--help" || arg == "-h") {
      o.help = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0) {
      if (!o.levelPath.empty()) return fail("more than one level given ('" + o.levelPath + "', '" + arg + "')");
      o.levelPath = arg;
      continue;
    }
    std::string value;
    const std::size_t eq = arg.find('=');
    if (eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    } else {
      if (i + 1 >= args.size()) return fail(arg + " needs a value");
      value = args[++i];
    }
    if (arg == "--out") {
      o.outPath = value;
    } else if (arg == "--state") {
      if (std::string e = parseState(value, o.state); !e.empty()) return fail(e);
    } else if (arg == "--camera") {
      if (value == "follow") o.camera = render::CameraMode::Follow;
      else if (value == "orbit") o.camera = render::CameraMode::Orbit;
      else if (value == "top") o.camera = render::CameraMode::Top;
      else return fail("--camera: '" + value + "' is not follow, orbit or top");
    } else if (arg == "--zoom") {
      if (!parseDouble(value, o.zoom) || !(o.zoom > 0.0)) return fail("--zoom needs a number > 0");
    } else if (arg == "--size") {
      const std::size_t x = value.find('x');
      if (x == std::string::npos || !parseInt(value.substr(0, x), o.width) ||
          !parseInt(value.substr(x + 1), o.height) || o.width < 16 || o.height < 16 || o.width > 8192 ||
          o.height > 8192)
        return fail("--size: '" + value + "' is not WxH with 16 <= W, H <= 8192");
    } else if (arg == "--proxy") {
      const std::vector<std::string> parts = split(value, ',');
      std::array<double, 3> p{};
      if (parts.size() != 3 || !parseDouble(parts[0], p[0]) || !parseDouble(parts[1], p[1]) ||
          !parseDouble(parts[2], p[2]))
        return fail("--proxy: '" + value + "' is not X,Y,Z in metres");
      o.proxy = p;
    } else if (arg == "--frames") {
      if (!parseInt(value, o.frames) || o.frames < 1 || o.frames > 100000)
        return fail("--frames needs a whole number in 1..100000");
    } else {
      return fail("unknown flag '" + arg + "'");
    }
  }
  if (o.help) return result;
  if (o.levelPath.empty()) return fail("missing LEVEL.lua");
  if (o.outPath.empty()) return fail("missing --out FILE.png");
  return result;
}

}  // namespace hemiroll::game

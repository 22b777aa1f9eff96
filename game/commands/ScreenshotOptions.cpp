#include "game/commands/ScreenshotOptions.h"

#include "engine/physics/StateLayout.h"
#include "game/cli/ArgumentReader.h"

namespace hemiroll::game {

namespace {

// "x_p=0.01,psi=1.2" -> slots; the error names the bad item.
std::string parseState(const std::string& text, std::vector<std::pair<int, double>>& out) {
  for (const std::string& item : cli::splitList(text, ',')) {
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
    if (!cli::readNumber(item.substr(eq + 1), value)) return "--state: " + name + " needs a finite number";
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
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("level", 1, [&](const std::string& path) { o.levelPath = path; })
      .option("--out", cli::text(o.outPath, "a file name"))
      .option("--state", [&](const std::string&, const std::string& value) { return parseState(value, o.state); })
      .option("--camera",
              [&](const std::string& flag, const std::string& value) {
                if (value == "follow") o.camera = render::CameraMode::Follow;
                else if (value == "orbit") o.camera = render::CameraMode::Orbit;
                else if (value == "top") o.camera = render::CameraMode::Top;
                else return cli::needs(flag, "follow, orbit or top", value);
                return std::string();
              })
      .option("--zoom", cli::positiveNumber(o.zoom, "a number > 0"))
      .option("--size", cli::size(o.width, o.height, 16, 8192))
      .option("--proxy",
              [&](const std::string& flag, const std::string& value) {
                std::array<double, 3> p{};
                if (!cli::readNumbers(value, p)) return cli::needs(flag, "X,Y,Z in metres", value);
                o.proxy = p;
                return std::string();
              })
      .option("--frames", cli::integerIn(o.frames, 1, 100000, "a whole number in 1..100000"));
  result.error = reader.read(args);
  if (!result.error.empty() || o.help) return result;
  if (o.levelPath.empty()) result.error = "missing LEVEL.lua";
  else if (o.outPath.empty()) result.error = "missing --out FILE.png";
  return result;
}

}  // namespace hemiroll::game

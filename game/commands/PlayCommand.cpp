#include "game/commands/PlayCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numbers>

#include "engine/platform/PlatformError.h"
#include "engine/render/RenderError.h"
#include "game/app/App.h"
#include "game/app/ScreenTour.h"
#include "game/app/ScriptedMouse.h"
#include "engine/render/Image.h"
#include "game/cli/ArgumentReader.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/screens/FreePlay.h"
#include "game/screens/PlayScreen.h"

namespace hemiroll::game {

namespace {

constexpr const char* kPrefix = "hemiroll play: ";

bool haveDisplay() {
  for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"})
    if (const char* s = std::getenv(v); s && *s) return true;
  return false;
}

int autoplay(App& app, const PlayOptions& o) {
  app.screens().push(std::make_unique<PlayScreen>(app, std::make_unique<FreePlay>(app, o.level, o.watch)));
  std::vector<double> frameSeconds;
  frameSeconds.reserve(static_cast<std::size_t>(o.autoplay * 2000) + 16);
  const auto start = std::chrono::steady_clock::now();
  auto last = start;
  ScriptedMouse mouse;
  haptics::LoopTimingSummary timing;
  std::string engagement = "never engaged";
  std::string scheduling;
  std::uint64_t plans = 0;
  std::string autopilotNote, outcome = "the trial was still running";
  while (true) {
    const auto now = std::chrono::steady_clock::now();
    const double t = std::chrono::duration<double>(now - start).count();
    if (t >= o.autoplay) break;
    if (!o.watch) mouse.step(app, t);  // watching: the autopilot holds the proxy
    if (!app.frame()) break;
    auto* play = dynamic_cast<PlayScreen*>(app.screens().top());
    if (play && play->session()) {
      plans = play->session()->autopilotPlans();
      autopilotNote = play->session()->autopilotNote();
      const script::TaskJudge& judge = play->session()->judging().judge();
      if (judge.finished()) {
        char line[160];
        std::snprintf(line, sizeof line, "%s at %.2f s (%.*s)", script::trialOutcomeName(judge.outcome()),
                      judge.finishTime(), static_cast<int>(judge.reason().size()), judge.reason().data());
        outcome = line;
      }
      if (play->session()->snapshot().engagement == haptics::Engagement::Engaged) engagement = "engaged";
      timing = play->session()->timing();
      scheduling = play->session()->realtimeNote();
    }
    const auto after = std::chrono::steady_clock::now();
    if (app.frames() > 1) frameSeconds.push_back(std::chrono::duration<double>(after - last).count());
    last = after;
  }
  if (frameSeconds.empty()) {
    std::cerr << kPrefix << "no frames were drawn\n";
    return kExitFailure;
  }
  std::sort(frameSeconds.begin(), frameSeconds.end());
  const double median = frameSeconds[frameSeconds.size() / 2];
  std::printf("%sautoplay %.1f s: %zu frames, median %.1f fps (p90 frame %.1f ms), %s, screen %s\n", kPrefix,
              o.autoplay, frameSeconds.size(), 1.0 / median, frameSeconds[frameSeconds.size() * 9 / 10] * 1e3,
              engagement.c_str(), app.topScreen());
  std::printf("%sservo loop: %llu ticks, lateness p50 %.0f us, p99 %.0f us, p99.9 %.0f us, max %.0f us, "
              "missed ticks %llu\n",
              kPrefix, static_cast<unsigned long long>(timing.ticks), timing.latenessP50 * 1e6,
              timing.latenessP99 * 1e6, timing.latenessP999 * 1e6, timing.latenessMax * 1e6,
              static_cast<unsigned long long>(timing.missedTicks));
  std::printf("%sservo thread: %s\n", kPrefix, scheduling.c_str());
  std::printf("%strial: %s\n", kPrefix, outcome.c_str());
  if (o.watch)
    std::printf("%sautopilot: %llu plans (%.0f per second)%s%s\n", kPrefix, static_cast<unsigned long long>(plans),
                static_cast<double>(plans) / o.autoplay, autopilotNote.empty() ? "" : "; ", autopilotNote.c_str());
  return kExitOk;
}

// The main screens as PNGs in o.tourDir: title.png, levels.png, play.png, ...
int tour(App& app, const PlayOptions& o) {
  ScreenTourDef def;
  def.level = o.level;
  def.playSeconds = o.autoplay > 0.0 ? o.autoplay : 3.0;
  for (const ScreenTourStop& s : runScreenTour(app, def)) {
    const std::string file = o.tourDir + "/" + s.screen + ".png";
    render::writePng(file, s.image);
    std::cout << kPrefix << file << "\n";
  }
  return kExitOk;
}

}  // namespace

std::string playUsage() {
  return "usage: hemiroll play [LEVEL.lua] [--levels DIR] [--size WxH] [--no-vsync] [--autoplay SECONDS]\n"
         "                     [--watch] [--tour DIR]\n"
         "Opens the game window on the title screen (or straight into LEVEL).\n"
         "  --levels DIR        the level select lists DIR/*.lua (default: levels)\n"
         "  --size WxH          window size in pixels (default 1280x720)\n"
         "  --no-vsync          draw frames as fast as they come\n"
         "  --autoplay SECONDS  a scripted mouse plays LEVEL for SECONDS, then the frame rate\n"
         "                      and the servo loop's timing are printed\n"
         "  --watch             the autopilot plays LEVEL (click or the take-hold key takes over);\n"
         "                      with --autoplay, the autopilot plays instead of the scripted mouse\n"
         "  --tour DIR          title, settings, level select (LEVEL picked), play, pause, results,\n"
         "                      watch, hint and start as PNGs in DIR (--autoplay sets the seconds played)\n";
}

std::string playNoDisplayMessage(const std::string& why) {
  return std::string(kPrefix) + "no display to open the game window on (" + why +
         "). Without a display, play a level with a bot: `hemiroll run LEVEL.lua --bot BOT.lua`, "
         "or run the physics alone: `hemiroll sim SCENARIO.lua`; or give the game a virtual display: "
         "`xvfb-run -a make play`.";
}

PlayOptionsResult parsePlayOptions(const std::vector<std::string>& args) {
  PlayOptionsResult r;
  PlayOptions& o = r.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .flag("--no-vsync", [&] { o.vsync = false; })
      .flag("--watch", [&] { o.watch = true; })
      .positional("level", 1, [&](const std::string& path) { o.level = path; })
      .option("--tour", cli::text(o.tourDir, "a directory"))
      .option("--levels", cli::text(o.levelsDir, "a directory"))
      .option("--size", cli::size(o.width, o.height, 64, 16384))
      .option("--autoplay", cli::numberIn(o.autoplay, 1e-3, 3600.0, "seconds in [0.001, 3600]"));
  r.error = reader.read(args);
  if (r.error.empty() && (o.autoplay > 0.0 || !o.tourDir.empty() || o.watch) && o.level.empty())
    r.error = std::string(o.autoplay > 0.0 ? "--autoplay" : o.watch ? "--watch" : "--tour") + " needs a LEVEL.lua";
  return r;
}

int runPlayCommand(const std::vector<std::string>& args) {
  const PlayOptionsResult parsed = parsePlayOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning(kPrefix, parsed, playUsage())) return *exit;
  const PlayOptions& o = parsed.options;
  if (!haveDisplay()) {
    std::cerr << playNoDisplayMessage("DISPLAY is not set") << "\n";
    return kExitUsage;
  }
  try {
    AppDef def;
    def.width = o.width;
    def.height = o.height;
    def.vsync = o.vsync;
    def.levelsDir = o.levelsDir;
    App app(def);
    // What the game starts without (no sound card, missing assets), once,
    // in our words; the title screen shows the same.
    for (const std::string& note : app.notes()) std::cerr << kPrefix << note << "\n";
    if (!o.tourDir.empty()) return tour(app, o);
    if (o.autoplay > 0.0) return autoplay(app, o);
    if (!o.level.empty())
      app.screens().push(std::make_unique<PlayScreen>(app, std::make_unique<FreePlay>(app, o.level, o.watch)));
    return app.run();
  } catch (const platform::PlatformError& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitUsage;
  } catch (const render::RenderError& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace hemiroll::game

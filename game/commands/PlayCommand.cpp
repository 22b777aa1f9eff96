#include "game/commands/PlayCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numbers>

#include <sys/resource.h>

#include "engine/platform/PlatformError.h"
#include "engine/render/RenderError.h"
#include "game/ui/app/App.h"
#include "game/ui/app/ScreenTour.h"
#include "game/ui/app/ScriptedMouse.h"
#include "engine/render/Image.h"
#include "game/cli/ArgumentReader.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/ui/screens/FreePlay.h"
#include "game/ui/screens/PlayScreen.h"
#include "game/ui/view/ShippedDirectories.h"

namespace hemiroll::game {

namespace {

constexpr const char* kPrefix = "hemiroll play: ";

bool haveDisplay() {
  for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"})
    if (const char* s = std::getenv(v); s && *s) return true;
  return false;
}

// The process's CPU time so far [s], user and system, every thread.
double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

// What an autoplay saw of the window and the trial, for its report.
struct AutoplayRecord {
  std::vector<double> frameSeconds;
  haptics::LoopTimingSummary timing;
  std::string engagement = "never engaged";
  std::string scheduling, stops = "none";
  std::uint64_t plans = 0, stopCount = 0;
  autopilot::RealTimePlanCounts decisions;
  std::string autopilotNote, outcome = "the trial was still running";
  double wall = 0.0, cpu = 0.0;
};

// How the trial ended, or where an unfinished one stands: how far from the
// target, how many in.
std::string trialStanding(PlaySession& session, PlayScreen& play) {
  const task::TaskJudge& judge = session.judging().judge();
  char line[160];
  if (judge.finished()) {
    std::snprintf(line, sizeof line, "%s at %.2f s (%.*s)", task::trialOutcomeName(judge.outcome()),
                  judge.finishTime(), static_cast<int>(judge.reason().size()), judge.reason().data());
    return line;
  }
  const HudReadout& r = play.hud().readout();
  if (r.distanceToTarget >= 0.0)
    std::snprintf(line, sizeof line, "the trial was still running at %.1f s (%.1f mm to the target, %d of %d in their bands",
                  r.time, r.distanceToTarget * 1e3, r.componentsInside, r.components);
  else
    std::snprintf(line, sizeof line, "the trial was still running at %.1f s (%d of %d in their bands", r.time,
                  r.componentsInside, r.components);
  // Which are out and by how much: a watched run that hovers on its target
  // says whether the spin, the lean or the contact keeps it from winning.
  std::string standing = line;
  for (const task::ComponentStatus& c : judge.components()) {
    if (c.inside || !std::isfinite(c.error)) continue;  // not yet judged: nothing to say
    std::snprintf(line, sizeof line, "; %s off by %.4g, band %.4g", task::taskVariableName(c.variable), c.error,
                  c.tolerance);
    standing += line;
  }
  return standing + ")";
}

// The report's lines; frameSeconds sorted and not empty.
void printAutoplay(App& app, const PlayOptions& o, const AutoplayRecord& a) {
  const std::vector<double>& frameSeconds = a.frameSeconds;
  const double median = frameSeconds[frameSeconds.size() / 2];
  std::printf("%sautoplay %.1f s: %zu frames, median %.1f fps (p90 frame %.1f ms), %s, screen %s\n", kPrefix, a.wall,
              frameSeconds.size(), 1.0 / median, frameSeconds[frameSeconds.size() * 9 / 10] * 1e3, a.engagement.c_str(),
              app.topScreen());
  std::printf("%scpu: %.1f s in %.1f s of wall time (%.0f %% of one core), frame cap %.0f fps\n", kPrefix, a.cpu, a.wall,
              a.wall > 0.0 ? 100.0 * a.cpu / a.wall : 0.0, static_cast<double>(app.settings().frameCap));
  const haptics::LoopTimingSummary& timing = a.timing;
  std::printf("%sservo loop: %llu ticks, lateness p50 %.0f us, p99 %.0f us, p99.9 %.0f us, max %.0f us, "
              "missed ticks %llu, stalls over the overrun limit %llu\n",
              kPrefix, static_cast<unsigned long long>(timing.ticks), timing.latenessP50 * 1e6,
              timing.latenessP99 * 1e6, timing.latenessP999 * 1e6, timing.latenessMax * 1e6,
              static_cast<unsigned long long>(timing.missedTicks), static_cast<unsigned long long>(timing.stalls));
  std::printf("%sservo thread: %s\n", kPrefix, a.scheduling.c_str());
  std::printf("%ssafety stops: %llu (%s)\n", kPrefix, static_cast<unsigned long long>(a.stopCount), a.stops.c_str());
  std::printf("%strial: %s\n", kPrefix, a.outcome.c_str());
  if (o.watch)
    std::printf("%sautopilot: %llu plans (%.0f per second); planner decisions applied %llu, dropped late %llu, "
                "stale %llu%s%s\n",
                kPrefix, static_cast<unsigned long long>(a.plans),
                a.wall > 0.0 ? static_cast<double>(a.plans) / a.wall : 0.0,
                static_cast<unsigned long long>(a.decisions.applied), static_cast<unsigned long long>(a.decisions.late),
                static_cast<unsigned long long>(a.decisions.stale), a.autopilotNote.empty() ? "" : "; ",
                a.autopilotNote.c_str());
}

int autoplay(App& app, const PlayOptions& o) {
  app.screens().push(std::make_unique<PlayScreen>(app, std::make_unique<FreePlay>(app, o.level, o.watch)));
  AutoplayRecord a;
  std::vector<double>& frameSeconds = a.frameSeconds;
  frameSeconds.reserve(static_cast<std::size_t>(o.autoplay * 2000) + 16);
  const auto start = std::chrono::steady_clock::now();
  const double cpuAtStart = processCpuSeconds();
  auto last = start;
  ScriptedMouse mouse;
  std::vector<Screen*> visible;
  while (true) {
    const auto now = std::chrono::steady_clock::now();
    a.wall = std::chrono::duration<double>(now - start).count();
    if (a.wall >= o.autoplay) break;
    if (!o.watch) mouse.step(app, a.wall);  // watching: the autopilot holds the proxy
    if (!app.frame()) break;
    // The play screen, also under a pause screen after a safety stop.
    PlayScreen* play = nullptr;
    app.screens().visible(visible);
    for (Screen* s : visible)
      if (auto* p = dynamic_cast<PlayScreen*>(s)) play = p;
    if (!play || !play->session()) break;  // the trial ended (the results screen replaced it)
    PlaySession& session = *play->session();
    a.plans = session.autopilotPlans();
    a.decisions = session.autopilotDecisions();
    a.autopilotNote = session.autopilotNote();
    a.outcome = trialStanding(session, *play);
    if (session.snapshot().engagement == haptics::Engagement::Engaged) a.engagement = "engaged";
    a.timing = session.timing();
    a.scheduling = session.realtimeNote();
    if (!session.stops().empty()) {
      a.stopCount = session.stops().size();
      char line[160];
      std::snprintf(line, sizeof line, "%s at %.2f s", haptics::safetyFaultName(session.stops().back().fault),
                    session.stops().back().time);
      a.stops = line;
      a.outcome = std::string("stopped for safety (") + line + ")";
      break;  // nobody is there to take hold again
    }
    const auto after = std::chrono::steady_clock::now();
    if (app.frames() > 1) frameSeconds.push_back(std::chrono::duration<double>(after - last).count());
    last = after;
  }
  a.cpu = processCpuSeconds() - cpuAtStart;
  if (frameSeconds.empty()) {
    std::cerr << kPrefix << "no frames were drawn\n";
    return kExitFailure;
  }
  std::sort(frameSeconds.begin(), frameSeconds.end());
  printAutoplay(app, o, a);
  return kExitOk;
}

// The main screens as PNGs in o.tourDir: title.png, levels.png, play.png, ...
int tour(App& app, const PlayOptions& o) {
  // The folder is made if it is missing, before the minute the tour takes.
  std::error_code made;
  std::filesystem::create_directories(o.tourDir, made);
  if (made) {
    std::cerr << kPrefix << "cannot make the folder " << o.tourDir << ": " << made.message() << "\n";
    return kExitFailure;
  }
  ScreenTourDef def;
  def.level = o.level;
  def.playSeconds = o.autoplay > 0.0 ? o.autoplay : 3.0;
  def.captureEdge = true;
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
         "                     [--watch] [--tour DIR] [--device-profile NAME]\n"
         "Opens the game window on the title screen (or straight into LEVEL).\n"
         "  --levels DIR        the level select lists DIR/*.lua (default: the shipped levels)\n"
         "  --device-profile NAME  the limits of the device behind the UDP bridge (devices/NAME.lua;\n"
         "                      default: the settings' device_profile)\n"
         "  --size WxH          window size in pixels (default 1280x720)\n"
         "  --no-vsync          no vsync (the frame cap of the settings still holds)\n"
         "  --autoplay SECONDS  a scripted mouse plays LEVEL for at most SECONDS (until the trial\n"
         "                      ends or a safety stop), then the frame rate, CPU, the servo loop's\n"
         "                      timing, the safety stops and the outcome are printed\n"
         "  --watch             the autopilot plays LEVEL (click or the take-hold key takes over);\n"
         "                      with --autoplay, the autopilot plays instead of the scripted mouse\n"
         "  --tour DIR          title, settings, level select (LEVEL picked), play, pause, results,\n"
         "                      watch, hint and start as PNGs in DIR (--autoplay sets the seconds played;\n"
         "                      edge.png too if the edge warning came on while it played)\n";
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
      .option("--device-profile", cli::text(o.deviceProfile, "a device profile name"))
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
  PlayOptions o = parsed.options;
  // A level that is not there is said here, before any window: in the window
  // the loader would say it on a screen that --autoplay and --tour never show.
  const std::string levelsDir = o.levelsDir.empty() ? findLevelsDirectory() : o.levelsDir;
  o.level = resolveLevelPath(o.level, levelsDir);
  if (std::error_code ec; !o.level.empty() && !std::filesystem::is_regular_file(o.level, ec)) {
    std::cerr << kPrefix << "no level file '" << o.level << "'"
              << (levelsDir.empty() ? std::string() : " (nor one of that name in " + levelsDir + ")") << "\n";
    return kExitUsage;
  }
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
    def.deviceProfile = o.deviceProfile;
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

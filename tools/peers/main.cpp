// peer_bench: hemiroll against MuJoCo, Bullet and ODE on the same scenes
// (issue 15). See docs/PEERS.md.
//
//   peer_bench [--quick] [--only SCENE] [--out DIR] [--doc FILE.md]
//   peer_bench [--quick] [--only SCENE] --trace ENGINE:SETTING:STEP   (prints one run's samples)
//
// Writes DIR/peers.csv (one row per scene, engine, setting and step),
// DIR/peers.gp (gnuplot script for DIR/peers.png) and the markdown report.
// --quick: 0.2 s horizons and two steps per engine, for the ctest smoke run,
// which also checks that every engine starts without slip or penetration,
// follows the prescribed point, and stays near the reference (exit 1 if not).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tools/peers/HemirollRuns.h"
#include "tools/peers/PeerEngine.h"
#include "tools/peers/PeerReport.h"

namespace hemiroll::tools::peers {
namespace {

struct Options {
  bool quick = false;
  std::string only;
  std::string out = ".";
  std::string doc;
  std::string trace;  // ENGINE:SETTING:STEP: print that run's samples
};

int usage(const char* why) {
  std::fprintf(stderr, "peer_bench: %s\nusage: peer_bench [--quick] [--only SCENE] [--out DIR] [--doc FILE.md]\n", why);
  return 2;
}

int run(const Options& o) {
  const double targetSeconds = o.quick ? 0.0 : 0.2;
  const int maxRepeats = o.quick ? 1 : 5;
  const std::vector<double> ourSteps = o.quick ? std::vector<double>{1e-3} : std::vector<double>{4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4};
  const std::vector<double> ourTolerances =
      o.quick ? std::vector<double>{1e-8} : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10};
  const std::vector<double> peerSteps =
      o.quick ? std::vector<double>{1e-3, 2.5e-4} : std::vector<double>{2e-3, 1e-3, 5e-4, 2.5e-4, 1e-4, 5e-5};

  std::vector<std::unique_ptr<PeerEngine>> engines;
  engines.push_back(makeMujocoEngine());
  engines.push_back(makeBulletEngine());
  engines.push_back(makeOdeEngine());

  Study study;
  for (const auto& e : engines) study.engines.push_back({e->name(), e->version(), e->settings()});
  for (const PeerScene& scene : peerScenes(o.quick)) {
    if (!o.only.empty() && scene.name != o.only) continue;
    SceneStudy s;
    s.scene = scene;
    s.reference = referenceSamples(scene);
    const std::vector<Sample> tighter = referenceSamples(scene, 1e-13);
    for (std::size_t i = 0; i < tighter.size(); ++i)
      s.referenceDisagreement =
          std::max(s.referenceDisagreement, (tighter[i].contact - s.reference[i].contact).norm());
    std::fprintf(stderr, "%s: reference (tol 1e-12) against tol 1e-13: %.1e m\n", scene.name.c_str(),
                 s.referenceDisagreement);
    auto add = [&](RunResult r) {
      std::fprintf(stderr, "  %-10s %-8s %-14s %-9.2g", scene.name.c_str(), r.engine.c_str(), r.setting.c_str(), r.step);
      const RunScore sc = score(scene, r, s.reference);
      if (sc.finite) {
        std::fprintf(stderr, " contact %.2e m  tilt %.2e rad  slip %.1e m/s  pen %.1e m  dE %.1e J  cpu/s %.2e s\n",
                     sc.contactError, sc.tiltError, sc.maxSlip, sc.maxPenetration, sc.energyDrift, sc.cpuPerSimSecond);
      } else {
        std::fprintf(stderr, " failed: %s\n", r.failure.empty() ? "not finite" : r.failure.c_str());
      }
      s.runs.push_back({std::move(r), sc});
    };
    if (!o.trace.empty()) {
      const auto a = o.trace.find(':'), b = o.trace.rfind(':');
      const std::string engine = o.trace.substr(0, a), setting = o.trace.substr(a + 1, b - a - 1);
      const double h = std::atof(o.trace.c_str() + b + 1);
      for (const auto& e : engines)
        if (e->name() == engine) {
          const RunResult r = runPeer(*e, scene, setting, h);
          std::printf("# %s %s %s h %g %s\n# t contact_x contact_y ref_x ref_y tilt ref_tilt slip penetration energy p_x p_y\n",
                      scene.name.c_str(), engine.c_str(), setting.c_str(), h, r.failure.c_str());
          for (std::size_t i = 0; i < r.samples.size(); ++i) {
            const Sample& x = r.samples[i];
            const Sample& ref = s.reference[i];
            std::printf("%.3f %.6e %.6e %.6e %.6e %.5e %.5e %.2e %.2e %.6e %.6e %.6e\n", x.t, x.contact.x(), x.contact.y(),
                        ref.contact.x(), ref.contact.y(), x.tilt, ref.tilt, x.slip, x.penetration, x.energy, x.p.x(), x.p.y());
          }
        }
      continue;
    }
    for (double h : ourSteps) add(hemirollRun(scene, "rk4", h, targetSeconds, maxRepeats));
    for (double tol : ourTolerances) add(hemirollRun(scene, "dop853", tol, targetSeconds, maxRepeats));
    for (const auto& e : engines)
      for (const PeerSetting& setting : e->settings())
        for (double h : peerSteps)
          add(timedRun([&] { return runPeer(*e, scene, setting.name, h); }, targetSeconds, maxRepeats));
    study.scenes.push_back(std::move(s));
  }
  if (!o.trace.empty()) return 0;
  if (study.scenes.empty()) return usage(("no scene named " + o.only).c_str());

  std::string error;
  if (!writeStudy(study, o.out, o.doc, error)) {
    std::fprintf(stderr, "peer_bench: %s\n", error.c_str());
    return 1;
  }
  if (o.quick) {
    const std::vector<std::string> problems = smokeCheck(study);
    for (const std::string& p : problems) std::fprintf(stderr, "peer_bench: check failed: %s\n", p.c_str());
    if (!problems.empty()) return 1;
    std::fprintf(stderr, "peer_bench: quick checks passed\n");
  }
  return 0;
}

}  // namespace
}  // namespace hemiroll::tools::peers

int main(int argc, char** argv) {
  using namespace hemiroll::tools::peers;
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& into) {
      if (i + 1 >= argc) return false;
      into = argv[++i];
      return true;
    };
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--only") {
      if (!value(o.only)) return usage("--only needs a scene name");
    } else if (a == "--out") {
      if (!value(o.out)) return usage("--out needs a directory");
    } else if (a == "--trace") {
      if (!value(o.trace)) return usage("--trace needs ENGINE:SETTING:STEP");
    } else if (a == "--doc") {
      if (!value(o.doc)) return usage("--doc needs a file name");
    } else {
      return usage(("unknown argument " + a).c_str());
    }
  }
  return run(o);
}

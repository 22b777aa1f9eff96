#include "tools/peers/PeerMarkdown.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace hemiroll::tools::peers {

namespace {

std::string settingsTable(const Study& study) {
  std::ostringstream o;
  o << "| engine | version | setting | what is set |\n|---|---|---|---|\n"
    << "| hemiroll | this repository | rk4 | the paper's RK4, fixed step h, the 12-state model (8-state where the "
       "point is prescribed) |\n"
    << "| hemiroll | | dop853 | Dormand-Prince 8(5,3), adaptive, tolerance tol |\n";
  for (const EngineInfo& e : study.engines)
    for (const PeerSetting& s : e.settings) o << "| " << e.name << " | " << e.version << " | " << s.name << " | " << s.description << " |\n";
  return o.str();
}

std::string sceneTable(const SceneStudy& s) {
  std::ostringstream o;
  o << "### " << s.scene.name << ": " << s.scene.description << ", " << fmt("%g", s.scene.horizon) << " s\n\n"
    << "Each engine at its most accurate step of each setting, and our RK4 at 1 ms. Errors are maxima over the "
       "samples every 10 ms, over the whole run and over its first second. The reference (tol 1e-12) is "
    << fmt("%.1e m", s.referenceDisagreement) << " from one at tol 1e-13.\n\n"
    << "| engine | setting | step | contact error [m] | in the first second [m] | tilt error [rad] | max slip [m/s] | max penetration [m] | "
    << (s.scene.conservative ? "energy drift [J]" : "point off its path [m]")
    << " | CPU per simulated s [s] |\n|---|---|---|---|---|---|---|---|---|---|\n";
  auto row = [&](const ScoredRun& r) {
    o << "| " << r.run.engine << " | " << r.run.setting << " | " << stepLabel(r.run) << " | ";
    if (!r.score.finite) {
      o << "failed: " << (r.run.failure.empty() ? "not finite" : r.run.failure) << " | | | | | | |\n";
      return;
    }
    o << fmt("%.2e", r.score.contactError) << " | " << fmt("%.2e", r.score.contactErrorFirstSecond) << " | "
      << fmt("%.2e", r.score.tiltError) << " | "
      << (r.run.engine == "hemiroll" ? std::string("0 (exact)") : fmt("%.1e", r.score.maxSlip)) << " | "
      << fmt("%.1e", r.score.maxPenetration) << " | "
      << (s.scene.conservative ? fmt("%.1e", r.score.energyDrift)
          : s.scene.drive == PointDrive::Prescribed ? fmt("%.1e", r.score.trackingError) : std::string("-"))
      << " | "
      << fmt("%.2e", r.score.cpuPerSimSecond) << " |\n";
  };
  if (const ScoredRun* ours = find(s, "hemiroll", "rk4", 1e-3)) row(*ours);
  for (const Curve& c : curvesOf(s))
    if (c.engine != "hemiroll")
      if (const ScoredRun* best = mostAccurate(c)) row(*best);
  o << "\n";
  return o.str();
}

// Our RK4 at 1 ms against each engine's best setting: the error ratio at
// our cost and the cost ratio at our error.
std::string targetsTable(const SceneStudy& s, const std::vector<EngineInfo>& engines) {
  std::ostringstream o;
  const ScoredRun* ours = find(s, "hemiroll", "rk4", 1e-3);
  if (!ours || !ours->score.finite) return "our RK4 at 1 ms did not run\n";
  const double e0 = ours->score.contactError, c0 = ours->score.cpuPerSimSecond;
  const std::vector<Curve> curves = curvesOf(s);
  for (const EngineInfo& e : engines) {
    const Curve* best = bestCurve(curves, e.name);
    if (!best) {
      o << "| " << s.scene.name << " | " << e.name << " | - | every run failed | | | |\n";
      continue;
    }
    const ScoredRun* cheapest = best->points.front();
    const ScoredRun* accurate = mostAccurate(*best);
    std::string atCost, atError;
    const double eAtCost = errorAtCost(*best, c0);
    if (std::isfinite(eAtCost)) {
      atCost = fmt("%.1e m", eAtCost) + ": **" + fmt("%.0f", eAtCost / e0) + "x**";
    } else {
      // Its cheapest run costs more than ours already; less CPU would only
      // add error (its error falls with its step), so this bounds the ratio.
      atCost = "its cheapest run (" + stepLabel(cheapest->run) + ", " +
               fmt("%.1fx", cheapest->score.cpuPerSimSecond / c0) + " our cost): " +
               fmt("%.1e m", cheapest->score.contactError) + ", **>= " +
               fmt("%.0f", cheapest->score.contactError / e0) + "x**";
    }
    const double cAtError = costAtError(*best, e0);
    if (std::isfinite(cAtError)) {
      atError = fmt("%.2e s", cAtError) + ": **" + fmt("%.0f", cAtError / c0) + "x**";
    } else {
      atError = "not reached; at its most accurate (" + stepLabel(accurate->run) + ") " +
                fmt("%.1e m", accurate->score.contactError) + " (" +
                fmt("%.0f", accurate->score.contactError / e0) + "x ours) for " +
                fmt("%.0f", accurate->score.cpuPerSimSecond / c0) + "x our cost";
    }
    o << "| " << s.scene.name << " | " << e.name << " | " << best->setting << " | " << fmt("%.1e m", e0) << ", "
      << fmt("%.2e s", c0) << " | " << atCost << " | " << atError << " |\n";
  }
  return o.str();
}

// The step each setting needs for a target error: measured when a run reached
// it, else extrapolated from the order observed between its two finest steps.
std::string reachCell(const Curve& c, double target, double radius) {
  if (const ScoredRun* r = cheapestWithin(c, target))
    return stepLabel(r->run) + ", " + fmt("%.1e s", r->score.cpuPerSimSecond);
  // Points are ordered by cost: the last two are the finest steps.
  if (c.points.size() < 2) return "no: one step ran, the others left the model";
  const ScoredRun* a = c.points[c.points.size() - 2];
  const ScoredRun* b = c.points.back();
  // An error of a quarter of the radius is no longer one that shrinks with
  // the step: the run has gone another way, and no order can be read off it.
  if (b->score.contactError > 0.25 * radius)
    return "no: at its finest step it has gone another way (" + fmt("%.1e m", b->score.contactError) + ")";
  const double order = std::log(a->score.contactError / b->score.contactError) / std::log(a->run.step / b->run.step);
  if (!(order > 0.3))
    return "no: the error stops falling (order " + fmt("%.1f", order) + " at the finest steps, " +
           fmt("%.1e m", b->score.contactError) + ")";
  const double h = b->run.step * std::pow(target / b->score.contactError, 1.0 / order);
  const double cost = b->score.cpuPerSimSecond * b->run.step / h;
  return "not within " + stepLabel(b->run) + "; order " + fmt("%.1f", order) + " gives h " + fmt("%.1g", h * 1e3) +
         " ms, CPU about " + fmt("%.0e s", cost) + " per simulated s";
}

std::string reachTable(const Study& study) {
  std::ostringstream o;
  o << "| scene | engine | setting | 1 mm | 10 um |\n|---|---|---|---|---|\n";
  for (const SceneStudy& s : study.scenes)
    for (const Curve& c : curvesOf(s)) {
      if (c.engine == "hemiroll") continue;
      o << "| " << s.scene.name << " | " << c.engine << " | " << c.setting << " | "
        << reachCell(c, 1e-3, s.scene.params.radius) << " | " << reachCell(c, 1e-5, s.scene.params.radius) << " |\n";
    }
  return o.str();
}

// The targets in two sentences, from the same matching as the table.
std::string inShort(const Study& study) {
  double smallestRatio = std::numeric_limits<double>::infinity();
  std::string where;
  int pairs = 0, reached = 0;
  for (const SceneStudy& s : study.scenes) {
    const ScoredRun* ours = find(s, "hemiroll", "rk4", 1e-3);
    if (!ours || !ours->score.finite) continue;
    const std::vector<Curve> curves = curvesOf(s);
    for (const EngineInfo& e : study.engines) {
      const Curve* best = bestCurve(curves, e.name);
      if (!best) continue;
      ++pairs;
      double ratio = errorAtCost(*best, ours->score.cpuPerSimSecond);
      if (!std::isfinite(ratio)) ratio = best->points.front()->score.contactError;  // the bound, as in the table
      ratio /= ours->score.contactError;
      if (ratio < smallestRatio) {
        smallestRatio = ratio;
        where = e.name + " on " + s.scene.name;
      }
      if (std::isfinite(costAtError(*best, ours->score.contactError)) ||
          best->points.front()->score.contactError <= ours->score.contactError)
        ++reached;
    }
  }
  std::ostringstream o;
  o << "**In short.** At the CPU time our RK4 takes at 1 ms, every engine's best setting has at least "
    << fmt("%.0f", smallestRatio) << "x our contact-point error (the smallest ratio: " << where
    << "; goal 100x). Our RK4's error at 1 ms was reached by " << reached << " of the " << pairs
    << " engine-scene pairs at any step down to 0.05 ms, so the cost ratio at equal error (goal 5x) is "
    << (reached == 0 ? "beyond what was measured: larger than each engine's cost at its finest step over ours, "
                       "with its error still larger (right column)."
                     : "given where it was reached (right column).");
  return o.str();
}

}  // namespace

std::string peersMarkdown(const Study& study) {
  std::ostringstream o;
  o << "# hemiroll against MuJoCo, Bullet and ODE\n\n"
       "The engines a researcher would otherwise pick, on the same scenes, measured in one run on one core of the "
       "same machine. Made by `make bench` (`build/bench/peer_bench --out docs/peers --doc docs/PEERS.md`, then "
       "`gnuplot docs/peers/peers.gp`); the data are in [peers/peers.csv](peers/peers.csv). `tools/peers/` is the "
       "tool; the engine and the game never link a peer (checked: `tools.peers_not_linked`).\n\n"
       "![contact-point error against CPU time per simulated second](peers/peers.png)\n\n"
       "## What is compared\n\n"
       "The same system in every engine: a solid hemisphere (radius R, mass m_s, centre of mass 3R/8 below the "
       "face centre, principal inertias 83/320 and 2/5 m_s R^2, given explicitly) rolling on a plane, its contact "
       "a sphere of radius R centred on the face (only the spherical part touches while the tilt is below 90 "
       "degrees), and the mass point m_p on two slide joints in the face plane. Gravity 9.81 m/s^2, double precision "
       "everywhere (Debian's float64 build of Bullet, ODE's double build).\n\n"
       "- **Start.** Our 12-state is converted to bodies by `poseOf` (tools/peers/PeerScene.cpp): rotation, "
       "centre, angular velocity, the centre's velocity w x (0, 0, R) and the point's. No slip and no "
       "penetration at t = 0 (checked to 1e-12 m/s and 1e-15 m for every engine by the quick run).\n"
       "- **Measured** every 10 ms, by one function for every engine (`sampleOf`, from the bodies each engine "
       "reports): the contact point (the sphere centre's x, y), the tilt, the slip speed of the shell's material "
       "point at the contact (exact rolling: zero), the penetration, the energy.\n"
       "- **Reference:** hemiroll's dop853 in long double at tolerance 1e-12. **Error:** the largest distance of "
       "the contact point from the reference's over the run, and the largest tilt difference.\n"
       "- **Cost:** the thread's CPU time of the stepping loop per simulated second (building a model is not "
       "counted), median of up to 5 repeats.\n"
       "- **Drives, the same right-hand conditions for all.** Free: nothing acts on the point but gravity and the "
       "face. Tether: the spring k_r (r_h - r_p) on the point (M2, undamped), read at the start of each step and "
       "held over it (Bullet, ODE) or MuJoCo's own spring (a spatial tendon of rest length 0, evaluated in every "
       "stage of its integrator). Prescribed (rocking, rose): the model's hand, an *external* force in the face "
       "plane (physics-notes.md: nothing pushes back on the shell in that plane; a slide-joint motor would push "
       "back, a different system). It is a servo: the acceleration the point needs on its path from the bodies' "
       "state (the shell's accelerations by backward differences) plus a critically damped correction at "
       "omega h = 1/4; the tables give how far it lets the point stray.\n\n"
       "## Settings\n\n"
    << settingsTable(study)
    << "\nEach engine's contact is tuned as its documentation recommends for rolling without slip: MuJoCo's "
       "elliptic cones, impratio, noslip iterations and the stiffest stable solref; Bullet's rolling and spinning "
       "friction off and more solver iterations; ODE's direct solver, ERP/CFM and the friction pyramid. Substeps "
       "are the step sweep itself (2 ms down to 0.05 ms).\n\n"
       "## The targets: our RK4 at 1 ms against each engine's best setting\n\n"
    << inShort(study) << "\n\n"
       "The best setting is the one that reaches the smallest error on the scene. Ratios are the engine's over "
       "ours (error at our cost; cost at our error). Goal: at least 100x less error at equal cost and at least 5x "
       "less cost at equal error.\n\n"
       "| scene | engine | best setting | our RK4 at 1 ms (error, CPU per s) | its error at our cost | its cost at "
       "our error |\n|---|---|---|---|---|---|\n";
  for (const SceneStudy& s : study.scenes) o << targetsTable(s, study.engines);
  o << "\n## What it takes to reach 1 mm and 10 um of contact-point error\n\n"
       "Over each scene's horizon (";
  for (const SceneStudy& s : study.scenes)
    o << (&s == &study.scenes.front() ? "" : ", ") << s.scene.name << " " << fmt("%g", s.scene.horizon) << " s";
  o << "; the free scenes end before the point slides off the face, the tether where our own RK4 at 1 ms is "
       "still within microns of the reference, its motion being chaotic). The cheapest step that did, or an "
       "extrapolation from the order measured between the two finest steps (CPU per simulated second in "
       "proportion), or why not.\n\n"
    << reachTable(study) << "\n## Per scene\n\n";
  for (const SceneStudy& s : study.scenes) o << sceneTable(s);
  o << "## What makes the comparison unfair, and to whom\n\n"
       "- hemiroll integrates the model's rolling constraint exactly; the peers do not know the contact rolls and "
       "solve a general contact problem every step (collision detection of a sphere and a plane included). That is "
       "the point of the comparison, and it is also more general work than ours.\n"
       "- The prescribed hand is a servo we wrote, first order in h, the same for the three peers; its own error "
       "is in the tables (point off its path). In the free scenes and the tether no servo is involved.\n"
       "- In Bullet and ODE, the tether's spring is held over each step (their integrators have no stages); "
       "MuJoCo's tendon is evaluated inside its integrator.\n"
       "- The bodies riding on the shell (the point; ODE's carrier) get a tenth of the shell's smallest inertia, "
       "taken off the shell's (the total is exact, since they cannot turn relative to it); with a token 1e-12 kg m^2 "
       "Bullet ran 1.8x slower and less accurately. ODE has no two-axis slide joint: the point "
       "hangs on two sliders through a carrier body of 1e-6 of its mass, which adds 1e-6 of the point's mass along "
       "one face axis only.\n"
       "- Bullet's 6-dof constraint applies its linear rows at its frames' origins: its frame on the shell is moved "
       "to the point at the start of every step, or the point's weight would act at the face centre (the shell "
       "did not rock at all before this).\n"
       "- We build hemiroll (Release, -O2, no -march); the peers are Debian's builds of their libraries, with "
       "their own flags. Timings are one thread's CPU time on a shared 2-core machine: medians, but noisy.\n";
  return o.str();
}

}  // namespace hemiroll::tools::peers

#include "game/commands/AnalyzeOptions.h"

#include <limits>

#include "game/cli/ArgumentReader.h"

namespace hemiroll::game {

const char* analyzeUsage() {
  return "usage: hemiroll analyze RECORDING... [--out DIR] [--plots svg|none]\n"
         "       hemiroll analyze EXPERIMENT_FOLDER [--out DIR] [--plots svg|none]\n"
         "\n"
         "Measures the movement features of Svinin et al. (2009), Sec. 4.2 and 5, in each\n"
         "trial (docs/ANALYSIS.md): the phases (acceleration, steady precession,\n"
         "deceleration) from the precession angle psi(t); the rose the mass point draws\n"
         "on the face (leaves per cycle, leaf and outer radius, time span); the helix the\n"
         "contact point draws on the plane (the arc's curvature, the loops along it).\n"
         "Prints a markdown table of all trials.\n"
         "\n"
         "RECORDING is a trial CSV with its JSON sidecar (hemiroll run --record), a\n"
         "session folder (all trials in it) or a `hemiroll sim` CSV.\n"
         "\n"
         "EXPERIMENT_FOLDER is <data root>/<experiment> of `hemiroll session` (its\n"
         "participants' session folders below it): prints each group's trials, success\n"
         "rate and mean time; with --out writes trials.csv (one row per trial: participant,\n"
         "group, block, condition, outcome, time, results.csv's measures, the movement\n"
         "features), learning_curves.csv (per participant and group, by trial and by\n"
         "block: n, mean, sd) and, with plots, the curves as SVGs (docs/ANALYSIS.md).\n"
         "\n"
         "  --out DIR        write per trial <trial>.analysis.json and, with plots, SVGs\n"
         "                   (<trial>.overview.svg, .contact.svg, .mass_point.svg,\n"
         "                   .psi.svg, .channels.svg), and analysis.csv + analysis.md\n"
         "                   over all trials\n"
         "  --plots svg|none write the SVG plots (default: svg when --out is given)\n"
         "  --help           print this help\n"
         "\n"
         "Exit codes: 0 done (a feature not found is a result), 1 an output file could\n"
         "not be written, 2 bad input (a flag, a missing or broken file).\n";
}

AnalyzeOptionsResult parseAnalyzeOptions(const std::vector<std::string>& args) {
  AnalyzeOptionsResult result;
  AnalyzeOptions& o = result.options;
  std::optional<std::string> plots;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("recording", std::numeric_limits<std::size_t>::max(),
                  [&](const std::string& path) { o.inputs.push_back(path); })
      .option("--out", cli::text(o.outDir, "a directory"))
      .option("--plots", [&](const std::string& flag, const std::string& value) {
        if (value != "svg" && value != "none") return cli::needs(flag, "'svg' or 'none'", value);
        plots = value;
        return std::string();
      });
  result.error = reader.read(args);
  if (!result.error.empty() || o.help) return result;
  if (o.inputs.empty()) {
    result.error = "missing the recording(s) to analyse";
  } else if (plots == "svg" && !o.outDir) {
    result.error = "--plots svg needs --out DIR (the plots are files)";
  } else {
    o.plots = plots ? *plots == "svg" : o.outDir.has_value();
  }
  return result;
}

}  // namespace hemiroll::game

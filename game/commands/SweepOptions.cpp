#include "game/commands/SweepOptions.h"

#include <limits>

#include "game/cli/ArgumentReader.h"

namespace hemiroll::game {

const char* sweepUsage() {
  return "usage: hemiroll sweep SPEC.lua --out DIR [--threads N] [--lanes W] [--shard i/N] [--maps svg|none]\n"
         "       hemiroll sweep SPEC.lua --out DIR --slurm N [--threads T] [--maps svg|none]\n"
         "             [--slurm-time LIMIT] [--slurm-partition P] [--slurm-account A] [--slurm-mem M]\n"
         "       hemiroll sweep merge DIR... --out DIR [--maps svg|none]\n"
         "       hemiroll sweep map DIR --x PARAM --y PARAM --metric NAME [--aggregate HOW] [--out FILE.svg]\n"
         "\n"
         "Sweeps the paper's rose drive (Svinin et al. 2009, Sec. 5) over a grid of\n"
         "parameters (k, Omega, r1, r2, the masses, ...) given by a spec file, and\n"
         "measures at each point: tip-over, the steady precession and its spread, the\n"
         "arc of the contact trace, the drift, the loops (docs/SWEEP.md).\n"
         "\n"
         "  --out DIR         run, merge: the output folder (created); a rerun into the\n"
         "                    same folder keeps the points already done\n"
         "  --threads N       run: worker threads (default: every CPU this process may\n"
         "                    use); the CSV does not depend on N\n"
         "  --lanes W         run: trajectories integrated together in SIMD lanes on\n"
         "                    each thread, 1, 2, 4 (AVX2) or 8 (AVX-512) (default: the\n"
         "                    widest this CPU runs); the CSV does not depend on W\n"
         "  --shard i/N       run: only the points whose index is i modulo N, into\n"
         "                    part-i-of-N.csv/.json (for a cluster's job array); join\n"
         "                    the parts with `hemiroll sweep merge`\n"
         "  --slurm N         writes DIR/slurm/: a Slurm job array of N shards into\n"
         "                    DIR/parts, T threads each, and a merge into DIR that\n"
         "                    waits for them; submit with DIR/slurm/submit.sh, and\n"
         "                    again after a failure (finished parts are kept); #SBATCH\n"
         "                    lines added to the files by hand are kept when they\n"
         "                    are written again\n"
         "  --slurm-time LIMIT  --slurm: each task's time limit as Slurm writes it\n"
         "                    (90, 2:30:00, 1-12:00:00); many sites refuse a job\n"
         "                    without one\n"
         "  --slurm-partition P, --slurm-account A\n"
         "                    --slurm: the partition (or a list: a,b) and the account\n"
         "  --slurm-mem M     --slurm: memory per node (4G, 500M)\n"
         "  --maps svg|none   run (whole sweeps), merge: draw map-<x>-<y>.svg for every\n"
         "                    pair of axes (default svg)\n"
         "  --x, --y PARAM    map: the axes (R, m_s, m_p, g, r1, r2, k, Omega)\n"
         "  --metric NAME     map: a metric (paper_like, steady_fraction, ...; see\n"
         "                    docs/SWEEP.md)\n"
         "  --aggregate HOW   map: median, mean, min, max or best over the other axes\n"
         "                    (default: the metric's own, named in the title)\n"
         "  --out FILE.svg    map: where (default DIR/map-<x>-<y>-<metric>.svg)\n"
         "  --help            print this help\n"
         "\n"
         "Progress is drawn on stderr when it is a terminal; the result is one JSON line\n"
         "on stdout. Exit codes: 0 done (a run that tips over is a result), 1 a file\n"
         "could not be written or read, 2 bad input.\n";
}

SweepOptionsResult parseSweepOptions(const std::vector<std::string>& args) {
  SweepOptionsResult result;
  SweepOptions& o = result.options;
  std::vector<std::string> rest = args;
  if (!rest.empty() && (rest.front() == "merge" || rest.front() == "map")) {
    o.action = rest.front() == "merge" ? SweepAction::Merge : SweepAction::Map;
    rest.erase(rest.begin());
  }
  const bool run = o.action == SweepAction::Run, merge = o.action == SweepAction::Merge, map = o.action == SweepAction::Map;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; }).flag("-h", [&] { o.help = true; });
  reader.positional(run ? "sweep spec" : merge ? "part folder" : "sweep folder",
                    merge ? std::numeric_limits<std::size_t>::max() : 1,
                    [&](const std::string& input) { o.inputs.push_back(input); });
  reader.option("--out", cli::text(o.out, map ? "an SVG file name" : "a folder"));
  if (run) {
    reader.option("--threads", cli::integerIn(o.threads, 1, 1024, "a whole number of threads from 1 to 1024"));
    reader.option("--lanes", [&](const std::string& flag, const std::string& value) {
      if (value != "1" && value != "2" && value != "4" && value != "8") return cli::needs(flag, "1, 2, 4 or 8", value);
      o.lanes = std::stoi(value);
      return std::string();
    });
    reader.option("--shard", [&](const std::string& flag, const std::string& value) {
      const auto shard = SweepShard::parse(value);
      if (!shard) return cli::needs(flag, "i/N with 0 <= i < N (e.g. 0/4)", value);
      o.shard = *shard;
      return std::string();
    });
    reader.option("--slurm", cli::integerIn(o.slurmTasks, 1, 10000, "a whole number of shards from 1 to 10000"));
    auto slurmValue = [](std::string& field, std::optional<std::string> (*problem)(std::string_view)) {
      return [&field, problem](const std::string& flag, const std::string& value) {
        if (const auto why = problem(value)) return cli::needs(flag, *why, value);
        field = value;
        return std::string();
      };
    };
    reader.option("--slurm-time", slurmValue(o.slurm.time, slurmTimeProblem))
        .option("--slurm-partition", slurmValue(o.slurm.partition, slurmNameProblem))
        .option("--slurm-account", slurmValue(o.slurm.account, slurmNameProblem))
        .option("--slurm-mem", slurmValue(o.slurm.memory, slurmMemoryProblem));
  }
  if (run || merge) {
    reader.option("--maps", [&](const std::string& flag, const std::string& value) {
      if (value != "svg" && value != "none") return cli::needs(flag, "'svg' or 'none'", value);
      o.maps = value == "svg";
      return std::string();
    });
  }
  if (map) {
    reader.option("--x", cli::text(o.x, "a parameter name"))
        .option("--y", cli::text(o.y, "a parameter name"))
        .option("--metric", [&](const std::string& flag, const std::string& value) {
          if (!findSweepMetric(value)) return cli::needs(flag, "one of " + sweepMetricNames(), value);
          o.metric = value;
          return std::string();
        })
        .option("--aggregate", [&](const std::string& flag, const std::string& value) {
          o.aggregate = parseAggregate(value);
          return o.aggregate ? std::string() : cli::needs(flag, "median, mean, min, max or best", value);
        });
  }
  result.error = reader.read(rest);
  if (!result.error.empty() || o.help) return result;
  if (o.inputs.empty())
    result.error = run ? "missing the sweep spec file" : merge ? "missing the part folders to merge" : "missing the sweep folder";
  else if (!map && !o.out)
    result.error = "missing --out DIR";
  else if (map && (!o.x || !o.y || !o.metric))
    result.error = "missing --x, --y or --metric (a map needs all three)";
  else if (o.slurmTasks > 0 && !o.shard.whole())
    result.error = "--slurm writes a job for every shard; --shard is for one of its tasks";
  else if (o.slurmTasks == 0 && !(o.slurm.time.empty() && o.slurm.partition.empty() && o.slurm.account.empty() &&
                                  o.slurm.memory.empty()))
    result.error = "--slurm-time, --slurm-partition, --slurm-account and --slurm-mem are for the job files of --slurm N";
  return result;
}

}  // namespace hemiroll::game

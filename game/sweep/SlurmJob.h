#pragma once
// A sweep as a Slurm job (`hemiroll sweep SPEC --out DIR --slurm N`): the
// files a user submits on a cluster, written to DIR/slurm/:
//   sweep-array.sbatch  a job array of N tasks, task i running shard i/N
//                       into DIR/parts (SLURM_ARRAY_TASK_ID is the shard);
//   sweep-merge.sbatch  `hemiroll sweep merge DIR/parts --out DIR`;
//   submit.sh           submits the array, then the merge with
//                       --dependency=afterok on it.
// A task that failed or was killed: run submit.sh again. Every task resumes
// its part (finished points are kept, a finished part returns at once) and
// the merge runs when all have succeeded. Paths are absolute and the
// binary is this one, so that every task runs the same program on the same
// spec (docs/SWEEP.md, "On a Slurm cluster").

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::game {

struct SlurmJobDef {
  std::filesystem::path program;  // the hemiroll binary, absolute
  std::filesystem::path spec;     // the sweep spec, absolute
  std::filesystem::path out;      // the sweep's folder, absolute
  int tasks = 1;                  // shards, one array task each
  int threadsPerTask = 1;         // --cpus-per-task and the sweep's --threads
  bool maps = true;               // the merge draws the maps
};

struct SlurmJobFiles {
  std::string array, merge, submit;  // the three files' texts
};

SlurmJobFiles slurmJobFiles(const SlurmJobDef& def);

// Writes the files (the scripts executable) and returns their paths.
// Throws SweepError (Environment) naming a file that cannot be written.
std::vector<std::filesystem::path> writeSlurmJob(const SlurmJobDef& def);

// `text` as one word for bash: in single quotes, a quote inside as '\''.
std::string shellQuote(std::string_view text);

}  // namespace hemiroll::game

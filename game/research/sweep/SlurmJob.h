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
// spec (docs/SWEEP.md, "On a Slurm cluster"). Writing the job again keeps
// the #SBATCH lines a user added to the previous files (SbatchDirectives).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "game/research/sweep/SbatchDirectives.h"

namespace hemiroll::game {

struct SlurmJobDef {
  std::filesystem::path program;  // the hemiroll binary, absolute
  std::filesystem::path spec;     // the sweep spec, absolute
  std::filesystem::path out;      // the sweep's folder, absolute
  int tasks = 1;                  // shards, one array task each
  int threadsPerTask = 1;         // --cpus-per-task and the sweep's --threads
  bool maps = true;               // the merge draws the maps
  SlurmResources resources;       // asked of the cluster by the array and the merge alike
};

struct SlurmJobFiles {
  std::string array, merge, submit;  // the three files' texts
};

SlurmJobFiles slurmJobFiles(const SlurmJobDef& def);

struct SlurmJobWritten {
  std::vector<std::filesystem::path> files;  // array, merge, submit
  std::vector<std::string> notes;            // what became of the previous files' own lines, for the user
};

// Writes the files (the scripts executable). Where a file is there already,
// its hand-added #SBATCH lines are carried into the new one, and a file
// whose other hand edits the new one lacks is kept beside it as
// NAME.previous (nothing a user wrote is lost); `notes` says which.
// Throws SweepError: BadInput for a path sbatch cannot take, Environment
// naming a file that cannot be read or written.
SlurmJobWritten writeSlurmJob(const SlurmJobDef& def);

// `text` as one word for bash: in single quotes, a quote inside as '\''.
std::string shellQuote(std::string_view text);

}  // namespace hemiroll::game

#include "game/sweep/SlurmJob.h"

#include <system_error>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/sweep/SweepError.h"
#include "game/trial/JsonLine.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

std::string shellQuote(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

SlurmJobFiles slurmJobFiles(const SlurmJobDef& d) {
  const std::string program = shellQuote(d.program.string()), spec = shellQuote(d.spec.string());
  const std::string parts = shellQuote((d.out / "parts").string()), out = shellQuote(d.out.string());
  // An #SBATCH line is not a shell word: its file name patterns take % as
  // a field, so a literal one is written %%.
  std::string logs;
  for (const char c : (d.out / "slurm").string()) logs += c == '%' ? std::string("%%") : std::string(1, c);
  const std::string n = std::to_string(d.tasks), threads = std::to_string(d.threadsPerTask);
  SlurmJobFiles f;
  f.array = "#!/bin/bash\n"
            "# Written by `hemiroll sweep --slurm " + n + "`: one array task per shard of\n"
            "# " + d.spec.string() + ", each into the parts folder. A task run again\n"
            "# keeps the points its part already holds.\n"
            "#SBATCH --job-name=hemiroll-sweep\n"
            "#SBATCH --array=0-" + std::to_string(d.tasks - 1) + "\n"
            "#SBATCH --cpus-per-task=" + threads + "\n"
            "#SBATCH --output=" + logs + "/task-%a.log\n"
            "#SBATCH --requeue\n"
            "set -euo pipefail\n"
            "exec " + program + " sweep " + spec + " --out " + parts + " --shard \"${SLURM_ARRAY_TASK_ID}/" + n +
            "\" --threads \"${SLURM_CPUS_PER_TASK:-" + threads + "}\" --maps none\n";
  f.merge = "#!/bin/bash\n"
            "# Written by `hemiroll sweep --slurm " + n + "`: the parts joined and checked,\n"
            "# once every array task has succeeded (submit.sh makes it depend on them).\n"
            "#SBATCH --job-name=hemiroll-sweep-merge\n"
            "#SBATCH --output=" + logs + "/merge.log\n"
            "set -euo pipefail\n"
            "exec " + program + " sweep merge " + parts + " --out " + out + " --maps " + (d.maps ? "svg" : "none") +
            "\n";
  f.submit = "#!/bin/bash\n"
             "# Submits the sweep's " + n + " array tasks, then the merge once they have all\n"
             "# succeeded. After a failure (a task killed, a node lost) run this again: the\n"
             "# finished parts are kept and only what is missing is computed.\n"
             "set -euo pipefail\n"
             "cd \"$(dirname \"$0\")\"\n"
             "array=$(sbatch --parsable sweep-array.sbatch)\n"
             "array=${array%%;*}\n"
             "merge=$(sbatch --parsable --dependency=afterok:\"$array\" --kill-on-invalid-dep=yes sweep-merge.sbatch)\n"
             "merge=${merge%%;*}\n"
             "echo \"hemiroll sweep: array job $array (" + n + " tasks), merge job $merge\"\n";
  return f;
}

std::vector<fs::path> writeSlurmJob(const SlurmJobDef& def) {
  // A line break in a path would end an #SBATCH line and start a command.
  for (const fs::path* p : {&def.program, &def.spec, &def.out})
    if (p->string().find_first_of("\n\r") != std::string::npos)
      throw SweepError(SweepError::Kind::BadInput,
                       "a Slurm job cannot name a path with a line break in it: " + JsonLine::quote(p->string()));
  const fs::path dir = def.out / "slurm";
  const SlurmJobFiles files = slurmJobFiles(def);
  const std::vector<std::pair<fs::path, const std::string*>> out = {
      {dir / "sweep-array.sbatch", &files.array}, {dir / "sweep-merge.sbatch", &files.merge},
      {dir / "submit.sh", &files.submit}};
  std::error_code made;
  fs::create_directories(dir, made);
  if (made) throw SweepError(SweepError::Kind::Environment, dir.string() + ": cannot be made: " + made.message());
  std::vector<fs::path> written;
  for (const auto& [path, text] : out) {
    try {
      record::writeFileAtomically(path, *text);
    } catch (const record::RecordError& e) {
      throw SweepError(SweepError::Kind::Environment, e.what());
    }
    std::error_code ec;
    fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add, ec);
    if (ec) throw SweepError(SweepError::Kind::Environment, path.string() + ": cannot be made executable: " + ec.message());
    written.push_back(path);
  }
  return written;
}

}  // namespace hemiroll::game

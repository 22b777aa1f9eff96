#include "game/research/sweep/SlurmJob.h"

#include <system_error>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileKinds.h"
#include "engine/files/FileReadError.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/research/sweep/SweepError.h"
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

namespace {

// The #SBATCH lines both jobs share: what the cluster is asked for.
std::string resourceLines(const SlurmResources& r) {
  std::string lines;
  if (!r.time.empty()) lines += "#SBATCH --time=" + r.time + "\n";
  else lines += "# No --time: many sites refuse a job without one (hemiroll sweep --slurm-time).\n";
  if (!r.partition.empty()) lines += "#SBATCH --partition=" + r.partition + "\n";
  if (!r.account.empty()) lines += "#SBATCH --account=" + r.account + "\n";
  if (!r.memory.empty()) lines += "#SBATCH --mem=" + r.memory + "\n";
  return lines;
}

}  // namespace

SlurmJobFiles slurmJobFiles(const SlurmJobDef& d) {
  const std::string program = shellQuote(d.program.string()), spec = shellQuote(d.spec.string());
  const std::string parts = shellQuote((d.out / "parts").string()), out = shellQuote(d.out.string());
  const std::string logs = (d.out / "slurm").string(), resources = resourceLines(d.resources);
  const std::string n = std::to_string(d.tasks), threads = std::to_string(d.threadsPerTask);
  SlurmJobFiles f;
  f.array = "#!/bin/bash\n"
            "# Written by `hemiroll sweep --slurm " + n + "`: one array task per shard of\n"
            "# " + d.spec.string() + ", each into the parts folder. A task run again\n"
            "# keeps the points its part already holds.\n"
            "#SBATCH --job-name=hemiroll-sweep\n"
            "#SBATCH --array=0-" + std::to_string(d.tasks - 1) + "\n"
            "#SBATCH --cpus-per-task=" + threads + "\n"
            "#SBATCH --output=" + sbatchPathValue(logs, "task-%a.log") + "\n"
            "#SBATCH --requeue\n" + resources +
            "set -euo pipefail\n"
            "exec " + program + " sweep " + spec + " --out " + parts + " --shard \"${SLURM_ARRAY_TASK_ID}/" + n +
            "\" --threads \"${SLURM_CPUS_PER_TASK:-" + threads + "}\" --maps none\n";
  f.merge = "#!/bin/bash\n"
            "# Written by `hemiroll sweep --slurm " + n + "`: the parts joined and checked,\n"
            "# once every array task has succeeded (submit.sh makes it depend on them).\n"
            "#SBATCH --job-name=hemiroll-sweep-merge\n"
            "#SBATCH --output=" + sbatchPathValue(logs, "merge.log") + "\n" + resources +
            "set -euo pipefail\n"
            "exec " + program + " sweep merge " + parts + " --out " + out + " --maps " + (d.maps ? "svg" : "none") +
            "\n";
  // Each script names the #SBATCH options it holds, so that writing it
  // again carries a user's lines and retires hemiroll's own.
  for (std::string* text : {&f.array, &f.merge}) {
    const std::size_t commands = text->find("set -euo pipefail\n");
    text->insert(commands, writtenOptionsLine(*text) + "\n");
  }
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

namespace {

// The user's own lines in `previous`, carried into `fresh` (or, for lines
// that cannot be carried, the previous file kept beside the new one).
std::string withPreviousLines(const fs::path& path, const std::string& fresh, std::vector<std::string>& notes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return fresh;
  std::string previous;
  try {
    previous = files::readCheckedFile(path, files::kSlurmJobFile);
  } catch (const files::FileReadError& e) {
    throw SweepError(SweepError::Kind::Environment, std::string(e.what()) + " (it is not overwritten unread)");
  }
  const CarriedDirectives carried = carryHandAddedDirectives(previous, fresh);
  const std::string name = path.filename().string();
  auto listed = [](const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += (text.empty() ? "" : "; ") + line;
    return text;
  };
  if (!carried.kept.empty())
    notes.push_back(name + ": kept the #SBATCH lines added to it: " + listed(carried.kept));
  if (!carried.replaced.empty())
    notes.push_back(name + ": replaced by this command's values: " + listed(carried.replaced));
  if (!carried.retired.empty())
    notes.push_back(name + ": not written again (hemiroll wrote them last time; this command does not ask them): " +
                    listed(carried.retired));
  if (!carried.dropped.empty()) {
    const fs::path kept = path.string() + ".previous";
    try {
      record::writeFileAtomically(kept, previous);
    } catch (const record::RecordError& e) {
      throw SweepError(SweepError::Kind::Environment, e.what());
    }
    notes.push_back(name + ": lines not written again (the previous file is " + kept.filename().string() +
                    "): " + listed(carried.dropped));
  }
  return carried.text;
}

}  // namespace

SlurmJobWritten writeSlurmJob(const SlurmJobDef& def) {
  // A line break in a path would end an #SBATCH line and start a command.
  for (const fs::path* p : {&def.program, &def.spec, &def.out})
    if (p->string().find_first_of("\n\r") != std::string::npos)
      throw SweepError(SweepError::Kind::BadInput,
                       "a Slurm job cannot name a path with a line break in it: " + JsonLine::quote(p->string()));
  // sbatch reads a log name with a backslash in it literally, %a included:
  // every task would write one log (tried on sbatch 22.05).
  if (def.out.string().find('\\') != std::string::npos)
    throw SweepError(SweepError::Kind::BadInput,
                     "a Slurm job's logs cannot be under a path with a backslash in it (sbatch then names every "
                     "task's log alike): " + JsonLine::quote(def.out.string()));
  const fs::path dir = def.out / "slurm";
  const SlurmJobFiles files = slurmJobFiles(def);
  const std::vector<std::pair<fs::path, const std::string*>> out = {
      {dir / "sweep-array.sbatch", &files.array}, {dir / "sweep-merge.sbatch", &files.merge},
      {dir / "submit.sh", &files.submit}};
  std::error_code made;
  fs::create_directories(dir, made);
  if (made) throw SweepError(SweepError::Kind::Environment, dir.string() + ": cannot be made: " + made.message());
  SlurmJobWritten written;
  for (const auto& [path, text] : out) {
    const std::string carried = withPreviousLines(path, *text, written.notes);
    try {
      record::writeFileAtomically(path, carried);
    } catch (const record::RecordError& e) {
      throw SweepError(SweepError::Kind::Environment, e.what());
    }
    std::error_code ec;
    fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add, ec);
    if (ec) throw SweepError(SweepError::Kind::Environment, path.string() + ": cannot be made executable: " + ec.message());
    written.files.push_back(path);
  }
  return written;
}

}  // namespace hemiroll::game

#pragma once
// The #SBATCH lines of the job files `hemiroll sweep --slurm` writes: the
// values a user gives (time limit, partition, account, memory) checked
// against what sbatch accepts, a path written so that sbatch reads it as one
// value, and the lines a user added by hand to a previous file carried into
// the new one. Knows nothing of sweeps; SlurmJob composes the files.
//
// Checked against sbatch 22.05 (Debian 12) by tools/slurm-sweep-check.sh:
// sbatch splits an #SBATCH line on whitespace unless the value is in double
// quotes, inside which \" and \\ stand for " and \ (src/sbatch/opt.c).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::game {

// What the cluster is asked for; an empty field is not asked (sbatch and the
// site's defaults apply).
struct SlurmResources {
  std::string time;       // --time: minutes, M:S, H:M:S, D-H, D-H:M or D-H:M:S (the limit per task)
  std::string partition;  // --partition: one name or a comma-separated list
  std::string account;    // --account
  std::string memory;     // --mem: a whole number with an optional unit K, M, G or T (per node)
};

// Why `value` is not what sbatch takes for the option, in words for the
// user; nullopt when it is good.
std::optional<std::string> slurmTimeProblem(std::string_view value);
std::optional<std::string> slurmNameProblem(std::string_view value);  // partition, account
std::optional<std::string> slurmMemoryProblem(std::string_view value);

// A file name pattern as one #SBATCH value: in double quotes, " and \ escaped,
// and a literal % written %% (sbatch's patterns take %a, %j, ... as fields).
// `pattern` keeps its own fields: only the folder is escaped.
std::string sbatchPathValue(std::string_view folder, std::string_view pattern);

// The option an #SBATCH line sets, in its long form ("time" for both
// "-t 10" and "--time=10"); empty when the line is not an #SBATCH line.
std::string sbatchOption(std::string_view line);

struct CarriedDirectives {
  std::string text;                 // the fresh file with the previous file's own #SBATCH lines in it
  std::vector<std::string> kept;    // #SBATCH lines carried over, as they were
  std::vector<std::string> replaced;// previous #SBATCH lines whose option the fresh file sets differently
  std::vector<std::string> dropped; // other previous lines the fresh file does not have
  std::vector<std::string> retired; // previous #SBATCH lines hemiroll wrote whose option is not asked now
};

// The comment line that names the #SBATCH options hemiroll wrote into a
// file, so that writing it again tells its own old lines from a user's.
std::string writtenOptionsLine(std::string_view fileText);

// Carries into `fresh` every #SBATCH line of `previous` whose option
// `fresh` does not set and that hemiroll did not write (previous's
// writtenOptionsLine names those; they are `retired`): a user's --qos,
// --constraint or --mail-user survives writing the job again. They go after fresh's own #SBATCH lines (sbatch
// stops reading them at the first command). A previous line that sets an
// option fresh also sets, to another value, is reported in `replaced`; any
// other line of previous that fresh lacks (a hand-written command) in
// `dropped`, so that the caller can keep the previous file.
CarriedDirectives carryHandAddedDirectives(std::string_view previous, std::string_view fresh);

}  // namespace hemiroll::game

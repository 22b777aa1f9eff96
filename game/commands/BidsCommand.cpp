#include "game/commands/BidsCommand.h"

#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include "game/cli/ArgumentReader.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"
#include "game/research/session/BidsDataset.h"

namespace hemiroll::game {

namespace {

namespace fs = std::filesystem;

constexpr const char* kPrefix = "hemiroll bids: ";

struct BidsOptions {
  std::vector<std::string> inputs;
  std::optional<std::string> out, name;
  bool help = false;
};

struct BidsOptionsResult {
  BidsOptions options;
  std::string error;
};

std::string bidsUsage() {
  return "usage: hemiroll bids SESSION_OR_EXPERIMENT... --out DIR [--name NAME]\n"
         "\n"
         "Writes session folders as a BIDS motion dataset (BIDS 1.9; docs/RECORDING.md):\n"
         "dataset_description.json, README, participants.tsv and .json, and per trial\n"
         "the motion recording (_motion.tsv, _channels.tsv, _motion.json) and an\n"
         "_events.tsv with its block, condition, trial in block, guidance, fade and\n"
         "outcome. A trial that did not finish or cannot be read is left out and named\n"
         "on stderr (the rest are written, exit 0).\n"
         "\n"
         "SESSION_OR_EXPERIMENT is a session folder (with session.json) or a folder\n"
         "above them: an experiment's (every participant, every session).\n"
         "\n"
         "  --out DIR    the dataset's folder: new or empty\n"
         "  --name NAME  the dataset's Name (default: the experiment's folder name)\n"
         "  --help       print this help\n"
         "\n"
         "Exit codes: 0 written, 1 a file could not be written, 2 bad input (a flag, no\n"
         "session folder, an --out that is not empty, two trials whose ids give the same\n"
         "BIDS names; nothing is written then).\n";
}

BidsOptionsResult parseBidsOptions(const std::vector<std::string>& args) {
  BidsOptionsResult result;
  BidsOptions& o = result.options;
  cli::ArgumentReader reader;
  reader.flag("--help", [&] { o.help = true; })
      .flag("-h", [&] { o.help = true; })
      .positional("folder", std::numeric_limits<std::size_t>::max(), [&](const std::string& f) { o.inputs.push_back(f); })
      .option("--out", cli::text(o.out, "a directory"))
      .option("--name", cli::text(o.name, "a name"));
  result.error = reader.read(args);
  if (!result.error.empty() || o.help) return result;
  if (o.inputs.empty()) result.error = "missing the session or experiment folder(s)";
  else if (!o.out) result.error = "missing --out DIR (the dataset's folder)";
  return result;
}

// The experiment's folder name: the input itself, or two up from a session.
std::string defaultName(const fs::path& input) {
  std::error_code ec;
  const fs::path absolute = fs::weakly_canonical(input, ec);
  const fs::path& p = ec ? input : absolute;
  if (fs::is_regular_file(p / "session.json", ec)) return p.parent_path().parent_path().filename().string();
  return p.filename().string();
}

}  // namespace

int runBidsCommand(const std::vector<std::string>& args) {
  const BidsOptionsResult parsed = parseBidsOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning(kPrefix, parsed, bidsUsage())) return *exit;
  const BidsOptions& o = parsed.options;
  std::vector<fs::path> sessions;
  for (const std::string& input : o.inputs) {
    std::error_code ec;
    if (!fs::is_directory(input, ec)) {
      std::cerr << kPrefix << input << ": not a folder\n";
      return kExitUsage;
    }
    const std::vector<fs::path> found = sessionFolders(input);
    if (found.empty()) {
      std::cerr << kPrefix << input << ": no session folder in it (none with session.json, here or two levels down)\n";
      return kExitUsage;
    }
    sessions.insert(sessions.end(), found.begin(), found.end());
  }
  BidsDatasetReport report;
  try {
    report = writeBidsDataset(sessions, *o.out, o.name.value_or(defaultName(o.inputs.front())));
  } catch (const BidsInputError& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << kPrefix << e.what() << "\n";
    return kExitFailure;
  }
  for (const std::string& why : report.leftOut) std::cerr << kPrefix << "left out " << why << "\n";
  const std::size_t people = report.participants.size();
  std::cout << kPrefix << report.trials << (report.trials == 1 ? " trial of " : " trials of ") << people
            << (people == 1 ? " participant in " : " participants in ")
            << *o.out << (report.leftOut.empty() ? "" : " (" + std::to_string(report.leftOut.size()) + " left out)")
            << "\n";
  return kExitOk;
}

}  // namespace hemiroll::game

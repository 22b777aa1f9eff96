#include "tests/game/support/BidsChecks.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace hemiroll::test {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, '\t');) out.push_back(c);
  return out;
}

// The checks a BIDS validator makes that need no schema files.
void expectValidBidsMotion(const fs::path& root, int trials) {
  const nlohmann::json description = nlohmann::json::parse(slurp(root / "dataset_description.json"));
  EXPECT_TRUE(description.contains("Name"));
  EXPECT_TRUE(description.contains("BIDSVersion"));
  const std::vector<std::string> participants = lines(slurp(root / "participants.tsv"));
  ASSERT_GE(participants.size(), 2u);
  EXPECT_EQ(cells(participants[0]).front(), "participant_id");
  std::set<std::string> subjects;
  for (std::size_t i = 1; i < participants.size(); ++i) subjects.insert(cells(participants[i]).front());
  EXPECT_TRUE(fs::exists(root / "README"));

  const std::regex motionName(
      R"(sub-([A-Za-z0-9]+)(_ses-[A-Za-z0-9]+)?_task-[A-Za-z0-9]+_tracksys-[A-Za-z0-9]+(_run-[0-9]+)?_motion\.tsv)");
  const std::regex eventsName(R"(sub-[A-Za-z0-9]+(_ses-[A-Za-z0-9]+)?_task-[A-Za-z0-9]+(_run-[0-9]+)?_events\.tsv)");
  int motions = 0, events = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, motionName)) {
      ++motions;
      EXPECT_EQ(entry.path().parent_path().filename(), "motion") << name;
      EXPECT_TRUE(subjects.count("sub-" + m[1].str())) << name << " has no row in participants.tsv";
      const std::string stem = name.substr(0, name.size() - std::string("_motion.tsv").size());
      const fs::path channelsFile = entry.path().parent_path() / (stem + "_channels.tsv");
      const fs::path sidecar = entry.path().parent_path() / (stem + "_motion.json");
      ASSERT_TRUE(fs::exists(channelsFile)) << stem;
      ASSERT_TRUE(fs::exists(sidecar)) << stem;
      const std::vector<std::string> channels = lines(slurp(channelsFile));
      ASSERT_FALSE(channels.empty());
      const std::vector<std::string> header = cells(channels[0]);
      EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 5),
                (std::vector<std::string>{"name", "component", "type", "tracked_point", "units"}));
      const std::vector<std::string> rows = lines(slurp(entry.path()));
      ASSERT_FALSE(rows.empty()) << name;
      EXPECT_EQ(cells(rows.front()).size(), channels.size() - 1) << name << ": one channel per column";
      const nlohmann::json json = nlohmann::json::parse(slurp(sidecar));
      for (const char* key : {"TaskName", "SamplingFrequency", "TrackingSystemName"})
        EXPECT_TRUE(json.contains(key)) << stem << " lacks " << key;
    } else if (std::regex_match(name, eventsName)) {
      ++events;
      const std::vector<std::string> rows = lines(slurp(entry.path()));
      ASSERT_GE(rows.size(), 2u);
      const std::vector<std::string> header = cells(rows[0]);
      ASSERT_GE(header.size(), 2u);
      EXPECT_EQ(header[0], "onset");
      EXPECT_EQ(header[1], "duration");
      for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(cells(rows[i]).size(), header.size()) << name;
    } else if (entry.is_regular_file() && entry.path().parent_path() != root) {
      EXPECT_TRUE(name.find("_channels.tsv") != std::string::npos || name.find("_motion.json") != std::string::npos)
          << "a file BIDS does not name: " << name;
    }
  }
  EXPECT_EQ(motions, trials);
  EXPECT_EQ(events, trials);
}

}  // namespace hemiroll::test

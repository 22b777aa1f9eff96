#pragma once
// The sweep's progress on stderr: a bar redrawn in place ("\r") while stderr
// is a terminal; nothing until the end otherwise (a log file or a cluster's
// job output wants one line, not thousands).

#include <chrono>
#include <cstdio>
#include <string>

namespace hemiroll::game {

// "[#######.............]  35/100 points  12.3 points/s  ETA 5 s", fixed
// width for the bar; `resumed` points count as done but not in the rate.
std::string progressLine(long long done, long long total, long long resumed, double elapsedSeconds, int barWidth = 30);

class SweepProgress {
 public:
  // `terminal`: draw the bar (normally isatty(stderr)).
  SweepProgress(std::FILE* out, long long total, long long resumed, bool terminal);

  void update(long long done);
  // Ends the bar's line (terminal only).
  void finish(long long done);
  double elapsedSeconds() const;

 private:
  std::FILE* out_;
  long long total_, resumed_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hemiroll::game

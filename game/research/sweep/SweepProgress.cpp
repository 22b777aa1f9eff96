#include "game/research/sweep/SweepProgress.h"

#include <algorithm>
#include <cmath>

namespace hemiroll::game {

std::string progressLine(long long done, long long total, long long resumed, double elapsed, int barWidth) {
  const double share = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const int filled = std::clamp(static_cast<int>(std::floor(share * barWidth)), 0, barWidth);
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "[" + std::string.
  std::string line(1, '[');
  line.append(static_cast<std::size_t>(filled), '#').append(static_cast<std::size_t>(barWidth - filled), '.').append("] ");
  char text[128];
  const long long computed = done - resumed;
  const double rate = elapsed > 0.0 ? static_cast<double>(computed) / elapsed : 0.0;
  std::snprintf(text, sizeof text, "%lld/%lld points", done, total);
  line += text;
  if (rate > 0.0) {
    std::snprintf(text, sizeof text, "  %.3g points/s  ETA %.0f s", rate, static_cast<double>(total - done) / rate);
    line += text;
  }
  return line;
}

SweepProgress::SweepProgress(std::FILE* out, long long total, long long resumed, bool terminal)
    : out_(out), total_(total), resumed_(resumed), terminal_(terminal), start_(std::chrono::steady_clock::now()) {}

double SweepProgress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void SweepProgress::update(long long done) {
  if (!terminal_) return;
  // Cleared to the end of the line: the ETA may get shorter.
  std::fprintf(out_, "\r%s\x1b[K", progressLine(done, total_, resumed_, elapsedSeconds()).c_str());
  std::fflush(out_);
}

void SweepProgress::finish(long long done) {
  if (!terminal_) return;
  update(done);
  std::fputc('\n', out_);
  std::fflush(out_);
}

}  // namespace hemiroll::game

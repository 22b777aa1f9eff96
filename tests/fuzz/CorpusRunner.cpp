// The fuzz targets without libFuzzer (the normal GCC build, `make test`):
//   fuzz_<target> [--seconds S] [--seed N] PATH...
// runs every file under PATH (seed corpora and regression inputs) through
// the target once, then mutates them - byte flips, inserted and deleted
// runs, repeats, truncations, splices of two inputs - for S seconds with a
// fixed seed, and prints how many inputs ran. A finding aborts the process;
// the input that did it is written first to ./fuzz-crash-<target>.bin.
// With clang (`make fuzz`) the same targets link libFuzzer instead.
#include <algorithm>
#include <csignal>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "tests/fuzz/FuzzInput.h"

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxInput = 1 << 20;  // [bytes]: seeds larger than this are skipped

std::string crashFile;
const std::vector<std::uint8_t>* current = nullptr;

// Async-signal-safe: open, write, close, then the default action.
void onFatal(int signal) {
  if (current != nullptr) {
    const int fd = open(crashFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      const ssize_t ignored = write(fd, current->data(), current->size());
      (void)ignored;
      close(fd);
    }
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void collect(const fs::path& path, std::vector<std::vector<std::uint8_t>>& out) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(path, ec)) files.push_back(e.path());
    std::sort(files.begin(), files.end());  // the same order on every machine
    for (const fs::path& f : files) collect(f, out);
    return;
  }
  if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) > kMaxInput) return;
  std::ifstream in(path, std::ios::binary);
  out.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Random {  // xorshift64*: fixed seed, the same mutations everywhere
  std::uint64_t s;
  std::uint64_t next() {
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    return s * 2685821657736338717ULL;
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

std::vector<std::uint8_t> mutate(const std::vector<std::vector<std::uint8_t>>& seeds, Random& r) {
  std::vector<std::uint8_t> x = seeds[r.below(seeds.size())];
  const int edits = 1 + static_cast<int>(r.below(4));
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = r.below(x.size() + 1);
    switch (r.below(6)) {
      case 0:  // flip bits of a byte
        if (!x.empty()) x[r.below(x.size())] ^= static_cast<std::uint8_t>(1u << r.below(8));
        break;
      case 1:  // insert a random byte (often a delimiter)
        x.insert(x.begin() + static_cast<long>(at), static_cast<std::uint8_t>("{}[],\"\n=0-9e.\\"[r.below(14)]));
        break;
      case 2: {  // delete a run
        const std::size_t n = std::min(x.size() - std::min(at, x.size()), r.below(16) + 1);
        x.erase(x.begin() + static_cast<long>(at), x.begin() + static_cast<long>(at + n));
        break;
      }
      case 3: {  // repeat a run
        if (x.empty()) break;
        const std::size_t from = r.below(x.size()), n = std::min(x.size() - from, r.below(32) + 1);
        const std::vector<std::uint8_t> run(x.begin() + static_cast<long>(from), x.begin() + static_cast<long>(from + n));
        x.insert(x.begin() + static_cast<long>(at), run.begin(), run.end());
        break;
      }
      case 4:  // truncate
        x.resize(at);
        break;
      case 5: {  // splice: this input's head, another's tail
        const std::vector<std::uint8_t>& other = seeds[r.below(seeds.size())];
        const std::size_t from = r.below(other.size() + 1);
        x.resize(at);
        x.insert(x.end(), other.begin() + static_cast<long>(from), other.end());
        break;
      }
    }
    if (x.size() > kMaxInput) x.resize(kMaxInput);
  }
  return x;
}

void run(const std::vector<std::uint8_t>& input) {
  current = &input;
  LLVMFuzzerTestOneInput(input.data(), input.size());
  current = nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 2.0;
  std::uint64_t seed = 14;
  std::vector<fs::path> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seconds" && i + 1 < argc) seconds = std::stod(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::stoull(argv[++i]);
    else paths.emplace_back(a);
  }
  const std::string name = fs::path(argv[0]).filename().string();
  crashFile = "fuzz-crash-" + name + ".bin";
  for (const int s : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(s, onFatal);

  std::vector<std::vector<std::uint8_t>> seeds;
  for (const fs::path& p : paths) {
    if (!fs::exists(p)) {
      std::fprintf(stderr, "%s: no such file or folder: %s\n", name.c_str(), p.c_str());
      return 2;
    }
    collect(p, seeds);
  }
  if (seeds.empty()) {
    std::fprintf(stderr, "%s: no inputs under the paths given\n", name.c_str());
    return 2;
  }
  for (const auto& s : seeds) run(s);
  Random random{seed * 0x9E3779B97F4A7C15ULL + 1};
  const auto start = std::chrono::steady_clock::now();
  long long mutated = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds) {
    run(mutate(seeds, random));
    ++mutated;
  }
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%s: %zu corpus inputs, then %lld mutated inputs in %.1f s (%.0f per second), no finding\n", name.c_str(),
              seeds.size(), mutated, took, took > 0.0 ? static_cast<double>(mutated) / took : 0.0);
  std::error_code ec;
  fs::remove_all(fs::temp_directory_path() / ("hemiroll-fuzz-" + std::to_string(getpid())), ec);
  return 0;
}

#include "game/commands/WindowProgram.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <system_error>

#include "game/commands/ExitCode.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

fs::path windowProgramBeside(const fs::path& program) { return program.parent_path() / kWindowProgramName; }

int execWindowProgram(const char* invokedAs, const std::string& command, const std::vector<std::string>& args) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    std::cerr << "hemiroll " << command << ": cannot find this program's own path (/proc/self/exe: " << ec.message()
              << "), so not its window program " << kWindowProgramName << " beside it\n";
    return kExitFailure;
  }
  const fs::path window = windowProgramBeside(self);
  std::vector<std::string> owned{invokedAs, command};
  owned.insert(owned.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : owned) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  ::execv(window.c_str(), argv.data());
  const int error = errno;
  std::cerr << "hemiroll " << command << ": cannot run the window program " << window.string() << ": "
            << std::strerror(error) << "\n";
  if (error == ENOENT)
    std::cerr << "  the commands that open a window (play, screenshot) run in " << kWindowProgramName
              << ", which must lie beside hemiroll; the headless commands run without it.\n"
                 "  build it with `cmake --build build --target hemiroll-window` (or `make build`).\n";
  return kExitFailure;
}

int runCommandGuarded(std::string_view command, int (*run)(const std::vector<std::string>&),
                      const std::vector<std::string>& args) {
  try {
    return run(args);
  } catch (const std::bad_alloc&) {
    std::cerr << "hemiroll " << command << ": out of memory (an input asked for more than this machine has)\n";
  } catch (const std::exception& e) {
    std::cerr << "hemiroll " << command << ": " << e.what() << "\n";
  }
  return kExitFailure;
}

}  // namespace hemiroll::game

#pragma once
// The commands that open a window (play, screenshot) live in a program of
// their own, hemiroll-window, beside hemiroll: so that the headless commands
// (a sweep, a sim, analyze) start without loading SDL, GL, assimp, ImGui and
// sqlite and the ~60 shared libraries they bring (docs/ARCHITECTURE.md,
// "Two programs"). `hemiroll play` replaces itself with hemiroll-window
// (exec): one process, one copy of the engine, as before.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hemiroll::game {

inline constexpr std::string_view kWindowProgramName = "hemiroll-window";

// The window program beside `program` (a path to hemiroll).
std::filesystem::path windowProgramBeside(const std::filesystem::path& program);

// Runs `command args...` in the window program beside this process's own
// program (/proc/self/exe), in this process's place; argv[0] stays
// `invokedAs`, so that ps and pgrep show the command line as it was typed.
// Returns only when that could not be done: it has then said on stderr what
// is missing, where, and how to build it, and returns kExitFailure.
int execWindowProgram(const char* invokedAs, const std::string& command, const std::vector<std::string>& args);

// Runs one command's entry point, turning what escapes it (memory exhausted
// by an input, a library's exception) into one line on stderr and exit 1,
// never an abort. Shared by both programs' main().
int runCommandGuarded(std::string_view command, int (*run)(const std::vector<std::string>&),
                      const std::vector<std::string>& args);

}  // namespace hemiroll::game

#pragma once
// What each kind of file the program reads may hold at most, so that a
// file in the wrong place (a FIFO, /dev/zero, a 3 GB sparse file) is refused
// before it costs time or memory. Every cap is the largest file of its kind
// the program itself could write for the largest input it accepts, with
// room to spare, or, where that is unbounded in practice (recordings of a
// day), the kind is read as a stream, a line or a record at a time, and the
// cap only stops a file far beyond anything real. docs/RECORDING.md lists
// them.

#include <cstdint>

namespace hemiroll::files {

struct FileKind {
  const char* name;         // in messages: "the trial sidecar"
  std::uintmax_t maxBytes;  // larger files are refused before a byte is read
};

inline constexpr std::uintmax_t kKiB = 1024, kMiB = kKiB * 1024, kGiB = kMiB * 1024;

// Lua source: levels, bots, protocols, sweep specs, scenarios, modules.
inline constexpr FileKind kLuaSource{"Lua file", 4 * kMiB};
// A trial's sidecar (trial-NNN.json): metadata, a few kilobytes.
inline constexpr FileKind kSidecar{"trial sidecar", 1 * kMiB};
// settings.json: a few hundred bytes.
inline constexpr FileKind kSettings{"settings file", 1 * kMiB};
// A session's manifest: about 1 kB per planned trial, at most 100 000 trials.
inline constexpr FileKind kSessionManifest{"session manifest", 256 * kMiB};
// A lab's participants.tsv: a line per participant, a few columns.
inline constexpr FileKind kParticipants{"participants file", 16 * kMiB};
// A session's bot-memory.json: a simulated participant's memory (capped at
// 64 entries, BotMemory.h) written twice over.
inline constexpr FileKind kBotMemory{"bot memory", 64 * kKiB};
// results.csv: about 1 kB per trial row, at most 100 000 trials. Read as a stream.
inline constexpr FileKind kResults{"results table", 256 * kMiB};
// A sweep's CSV (sweep.csv, a part, sweep.csv.partial): about 600 bytes per
// point, at most 1 000 000 points. Read as a stream.
inline constexpr FileKind kSweepTable{"sweep table", 2 * kGiB};
// A sweep part's manifest (JSON with the spec): small.
inline constexpr FileKind kSweepManifest{"sweep manifest", 16 * kMiB};
// A Slurm job file of `sweep --slurm`, read back to keep its hand-added lines.
inline constexpr FileKind kSlurmJobFile{"Slurm job file", 1 * kMiB};
// A ghost's time (.hrr.time): one number.
inline constexpr FileKind kGhostTime{"ghost time", 4 * kKiB};
// Whose a ghost is (.hrr.by): one word.
inline constexpr FileKind kGhostOwner{"ghost owner", 64};
// A replay log (.hrr, also a ghost): 64 bytes a tick; a day at 1 kHz is
// 5.5 GB. Its header is checked before the body is read.
inline constexpr FileKind kReplayLog{"replay log", 8 * kGiB};
// A trial CSV or a `hemiroll sim` CSV handed to `analyze`: a day at 1 kHz
// is tens of gigabytes. Read as a stream of bounded lines.
inline constexpr FileKind kSampleTable{"sample table", 64 * kGiB};
// Shaders and meshes shipped in assets/.
inline constexpr FileKind kAsset{"asset", 64 * kMiB};

}  // namespace hemiroll::files

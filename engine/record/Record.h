#pragma once
// engine/record: the history unit. Per trial a CSV of the servo loop's rows
// with a JSON sidecar, a results.csv row per trial, a BIDS-motion export, and
// replay logs of the per-tick device input. Formats: docs/RECORDING.md.
//
// Owns: file formats and their readers (CsvRowFormat, Sidecar,
// RecordingReader, ReplayFormat, ReplayReader), the writers and their
// threads (TrialRecorder, ReplayLogger: they drain the servo loop's lock-free
// rings, so the 1 kHz tick never touches a file), durability (fdatasync at
// least every flush interval, atomic rewrite of sidecars), sessions
// (RecordingSession, ResultsFile), BidsExport.
// Must not know: Lua, levels (it receives a level's name and hash as text),
// the game, rendering. Depends on engine/haptics (the row types, the loop's
// timing summary), engine/physics (parameters), nlohmann-json and std.
//
// Usage (the game's `run --record DIR`):
//
//   record::RecordingSession session(dir, {.participant = "p01", .session = "2"});
//   record::TrialMeta meta;                  // ids, level name + hash, params,
//   meta.trialId = "trial-003"; ...          // coupling, device, rates
//   auto rows = std::make_unique<haptics::RecordRing>();
//   auto inputs = std::make_unique<haptics::InputRing>();      // optional:
//   auto commands = std::make_unique<haptics::CommandRing>();  // replay log
//   def.recordRing = rows.get(); def.recordEvery = meta.recordEvery;
//   def.inputRing = inputs.get(); def.commandRing = commands.get();
//   record::TrialRecorder rec = session.beginTrial(meta);
//   record::ReplayLogger replay(session.replayPath(meta.trialId), {.dt = def.period, ...});
//   haptics::ServoLoop loop(def, device);
//   rec.startWriter(*rows); replay.startWriter(*inputs, commands.get());
//   loop.start(); ... loop.stop();
//   record::TrialEnd end{.outcome = "success", .reason = "reached the goal",
//                        .hasTiming = true, .timing = loop.timingSummary(),
//                        .droppedRows = loop.recordDropped()};
//   rec.finish(end); replay.finish(loop.inputDropped());
//   auto result = record::RecordingSession::resultOf(rec, end, loop.time());
//   result.score = 42.0;
//   session.appendResult(result);
//
// Headless runs skip the threads: rec.push(row) (or rec.drain(*rows) between
// runHeadless chunks) on the calling thread; the same formatting path.
// Replaying: log = ReplayReader::load(path); a ServoLoop built from the same
// level with a haptics::ReplayDevice(log.inputs); ReplayRunner::run(loop, log).

#include "engine/record/BidsExport.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/RecordError.h"
#include "engine/record/RecordingReader.h"
#include "engine/record/RecordingSession.h"
#include "engine/record/ReplayFormat.h"
#include "engine/record/ReplayLogger.h"
#include "engine/record/ReplayReader.h"
#include "engine/record/ReplayRunner.h"
#include "engine/record/ResultsFile.h"
#include "engine/record/Sidecar.h"
#include "engine/record/TrialMeta.h"
#include "engine/record/TrialRecorder.h"

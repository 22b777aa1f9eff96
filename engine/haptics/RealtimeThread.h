#pragma once
// Asks the kernel for real-time scheduling (SCHED_FIFO) for the calling
// thread. Not being permitted (no CAP_SYS_NICE, no rtprio limit, a
// container) is normal on a desktop: it is reported as a note, never as an
// error, and the loop runs under the normal scheduler.

namespace hemiroll::haptics {

enum class RealtimeStatus { NotRequested, Fifo, NotPermitted, Failed };

struct RealtimeResult {
  RealtimeStatus status = RealtimeStatus::NotRequested;
  const char* note = "real-time scheduling not requested";  // static text
};

RealtimeResult requestFifoScheduling(int priority);

}  // namespace hemiroll::haptics

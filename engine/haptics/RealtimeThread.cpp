#include "engine/haptics/RealtimeThread.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <cerrno>

namespace hemiroll::haptics {

RealtimeResult requestFifoScheduling(int priority) {
  sched_param param{};
  param.sched_priority = std::clamp(priority, sched_get_priority_min(SCHED_FIFO), sched_get_priority_max(SCHED_FIFO));
  const int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  if (rc == 0) return {RealtimeStatus::Fifo, "SCHED_FIFO granted"};
  if (rc == EPERM)
    return {RealtimeStatus::NotPermitted,
            "SCHED_FIFO not permitted (needs CAP_SYS_NICE or an rtprio limit); running under the normal scheduler"};
  return {RealtimeStatus::Failed, "SCHED_FIFO request failed; running under the normal scheduler"};
}

}  // namespace hemiroll::haptics

#pragma once
// The autopilot's planning thread for real-time play: one job at a time.
// The caller posts a job (refused while one is running) and later takes the
// decision; neither call waits for a plan. Nothing here runs in the servo
// tick: the autopilot is called from the bot's thread.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "engine/autopilot/Autopilot.h"

namespace hemiroll::autopilot {

class PlannerWorker {
 public:
  using Plan = std::function<Autopilot::Decision(const Autopilot::PlanJob&)>;

  // `nice`: the thread's nice value on Linux (AutopilotDef::plannerNice).
  explicit PlannerWorker(Plan plan, int nice = 0);
  ~PlannerWorker();
  PlannerWorker(const PlannerWorker&) = delete;
  PlannerWorker& operator=(const PlannerWorker&) = delete;

  // False while a job is still running or its decision not yet taken.
  bool post(Autopilot::PlanJob job);
  // True, with the decision, once the posted job is done.
  bool take(Autopilot::Decision& out);

 private:
  void run();

  Plan plan_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Autopilot::PlanJob> job_;
  std::optional<Autopilot::Decision> done_;
  bool busy_ = false, stop_ = false;
  int nice_ = 0;
  std::thread thread_;  // last: started once everything above exists
};

}  // namespace hemiroll::autopilot

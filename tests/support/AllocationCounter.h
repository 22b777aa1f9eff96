#pragma once
// Counts C++ heap allocations (operator new) while a counter is open: the
// checks that the 1 kHz tick, a device's servo-side calls, judging a tick
// and drawing a frame allocate nothing. A test program that uses it has its
// global operator new and delete replaced (AllocationCounter.cpp: every
// form that pairs with them, so that memory from any of them may be freed
// by any, as sanitizers check). malloc is not counted: the GL driver's and
// C libraries' own allocations are not ours.

namespace hemiroll::test {

class AllocationCounter {
 public:
  enum class Threads {
    All,      // allocations on any thread
    Calling,  // only the constructing thread's (other threads of the code
              // under test, such as a device's receiver, are not charged)
  };
  explicit AllocationCounter(Threads threads = Threads::All);  // counts from zero
  ~AllocationCounter();                                         // stops counting
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;

  // Counting stops and starts again, keeping the count: for set-up between
  // the calls under test.
  void pause();
  void resume();
  long count() const;

 private:
  Threads threads_;
};

// A counter sees a direct call of operator new (through a volatile
// pointer: a new-expression may be elided): true when it counts exactly
// that one. Checks that a count of zero means something.
bool allocationCounterWorks();

}  // namespace hemiroll::test

#pragma once
// checkScript on a thread of its own, beside the run of the same script:
// `mpr gl` with more than one thread no longer waits for the whole script
// to be checked before the first call runs (on the bathroom trace the check
// was a fifth of the run). The run starts from scanScriptHeader's header
// and holds back everything a user would see (GL error reports, a failed
// probe, the files) until wait() says the script has no error; a script
// error is then reported exactly as before, with nothing written or printed
// before it, and the run is abandoned (failed() lets it stop early).
#include <atomic>
#include <exception>
#include <string>
#include <string_view>
#include <thread>

namespace mpr {

class ScriptCheckThread {
 public:
  // Starts checking `text` (which must outlive this object).
  ScriptCheckThread(std::string_view text, std::string file);
  ~ScriptCheckThread();  // waits for the check
  ScriptCheckThread(const ScriptCheckThread&) = delete;
  ScriptCheckThread& operator=(const ScriptCheckThread&) = delete;

  // Without waiting: the check has ended (passed()) or found an error (failed()).
  bool passed() const { return state_.load(std::memory_order_acquire) == kPassed; }
  bool failed() const { return state_.load(std::memory_order_acquire) == kFailed; }
  // Waits for the check to end, then throws what checkScript threw: the
  // script's first ScriptError (or another exception, out of memory); each
  // call throws it again.
  void wait();

 private:
  static constexpr int kRunning = 0, kPassed = 1, kFailed = 2;
  std::atomic<int> state_{kRunning};
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace mpr

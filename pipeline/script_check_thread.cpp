#include "pipeline/script_check_thread.hpp"

#include "pipeline/gl_script.hpp"

namespace mpr {

ScriptCheckThread::ScriptCheckThread(std::string_view text, std::string file)
    : thread_([this, text, file = std::move(file)] {
        int ending = kPassed;
        try {
          checkScript(text, file);
        } catch (const ScriptError& e) {
          error_ = e.what();
          ending = kFailed;
        } catch (...) {
          otherError_ = std::current_exception();
          ending = kFailed;
        }
        state_.store(ending, std::memory_order_release);
      }) {}

ScriptCheckThread::~ScriptCheckThread() {
  if (thread_.joinable()) thread_.join();
}

const std::optional<std::string>& ScriptCheckThread::wait() {
  if (thread_.joinable()) thread_.join();
  if (otherError_) std::rethrow_exception(otherError_);
  return error_;
}

}  // namespace mpr

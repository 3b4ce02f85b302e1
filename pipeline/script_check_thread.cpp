#include "pipeline/script_check_thread.hpp"

#include "pipeline/gl_script.hpp"

namespace mpr {

ScriptCheckThread::ScriptCheckThread(std::string_view text, std::string file)
    : thread_([this, text, file = std::move(file)] {
        try {
          checkScript(text, file);
        } catch (...) {
          error_ = std::current_exception();
        }
        state_.store(error_ ? kFailed : kPassed, std::memory_order_release);
      }) {}

ScriptCheckThread::~ScriptCheckThread() {
  if (thread_.joinable()) thread_.join();
}

void ScriptCheckThread::wait() {
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
}

}  // namespace mpr

#include "pipeline/script_read_ahead.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace mpr {
namespace {

// Commands per hand-over: the first batch small, so the calls start soon
// and a short script touches little memory, each next one twice the one
// before up to the last size (a lock per two thousand commands: on the
// bathroom trace batches of 1 024 took 0.67 s, of 2 048 or 4 096 0.61 s,
// the waits for a batch or for room fewer).
constexpr std::size_t kFirstBatchCommands = 256;
constexpr std::size_t kBatchCommands = 2048;
constexpr std::size_t kBatchesInFlight = 16;  // parsed ahead at most: some thirty thousand commands
// A reader that found the queue full sleeps until it is down to this many:
// then it parses a run of batches, not one per wake-up (on two cores shared
// with the row threads, each wake-up may wait for a time slice).
constexpr std::size_t kReaderResumesAt = kBatchesInFlight / 2;

// A batch's slots are reused from batch to batch (swapped with the
// parser's command, so each keeps its argument vector's capacity): no
// allocation or copy per command.
struct Batch {
  std::vector<ScriptCommand> commands;
  std::size_t size = 0;
};

struct ReaderStopped {};

constexpr std::size_t kPrefetchAhead = 8;

void prefetchCommand(const ScriptCommand& c) {
  const char* args = reinterpret_cast<const char*>(c.args.data());
  const std::size_t bytes = c.args.size() * sizeof(ScriptArg);
  for (std::size_t at = 0; at < bytes; at += 64) __builtin_prefetch(args + at);
}

// std::swap by member: the vectors, string and pointer trade their buffers
// (std::swap's three moves copied a short label's bytes each time).
void swapCommands(ScriptCommand& a, ScriptCommand& b) {
  std::swap(a.kind, b.kind);
  std::swap(a.line, b.line);
  std::swap(a.call, b.call);
  a.args.swap(b.args);
  // A call has no label or probe: both empty, nothing to trade (a string's
  // swap is a dozen branches on its short-string buffer).
  if (!a.label.empty() || !b.label.empty()) a.label.swap(b.label);
  if (a.probe || b.probe) a.probe.swap(b.probe);
}

}  // namespace

void streamScriptAhead(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  ScriptText whole = ScriptText::ofString(text);
  streamScriptAhead(whole, header, sink);
}

void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  std::mutex mutex;
  std::condition_variable readerMayGo, batchReady;
  bool readerWaiting = false, callerWaiting = false;
  std::deque<Batch> full;   // parsed, in order
  std::vector<Batch> spare;  // handed back by the caller's thread
  bool finished = false, stop = false;
  std::exception_ptr readError;

  std::thread reader([&] {
    Batch batch;
    std::size_t batchCommands = kFirstBatchCommands;
    auto handOver = [&] {
      std::unique_lock lock(mutex);
      if (full.size() >= kBatchesInFlight && !stop) {
        readerWaiting = true;
        readerMayGo.wait(lock, [&] { return full.size() <= kReaderResumesAt || stop; });
        readerWaiting = false;
      }
      if (stop) throw ReaderStopped{};
      full.push_back(std::move(batch));
      batch = Batch{};
      if (!spare.empty()) {
        batch = std::move(spare.back());
        spare.pop_back();
      }
      if (callerWaiting) batchReady.notify_one();
    };
    try {
      streamScript(text, header, [&](ScriptCommand&& c) {
        if (batch.size == batch.commands.size()) batch.commands.emplace_back();
        // Swapped, not copied: the slot takes the command, the parser gets
        // the slot's old one back to fill next, vectors and all.
        swapCommands(batch.commands[batch.size++], c);
        if (batch.size == batchCommands) {
          handOver();
          batchCommands = std::min(2 * batchCommands, kBatchCommands);
        }
      });
      if (batch.size > 0) handOver();
    } catch (const ReaderStopped&) {
    } catch (...) {
      readError = std::current_exception();
      try {
        if (batch.size > 0) handOver();  // the commands before the error still run
      } catch (const ReaderStopped&) {
      }
    }
    std::lock_guard lock(mutex);
    finished = true;
    batchReady.notify_one();
  });

  try {
    for (;;) {
      Batch batch;
      {
        std::unique_lock lock(mutex);
        if (full.empty() && !finished) {
          callerWaiting = true;
          batchReady.wait(lock, [&] { return !full.empty() || finished; });
          callerWaiting = false;
        }
        if (full.empty()) break;
        batch = std::move(full.front());
        full.pop_front();
        if (readerWaiting && full.size() <= kReaderResumesAt) readerMayGo.notify_one();
      }
      for (std::size_t i = 0; i < batch.size; ++i) {
        // The parser wrote these on another core: a command's arguments,
        // fetched a few commands ahead, are in this core's cache when its
        // call runs (the loads of a vertex's three numbers were a tenth of
        // the calling thread's time on the bathroom trace).
        if (i + kPrefetchAhead < batch.size) prefetchCommand(batch.commands[i + kPrefetchAhead]);
        sink(std::move(batch.commands[i]));
      }
      batch.size = 0;
      std::lock_guard lock(mutex);
      spare.push_back(std::move(batch));
    }
  } catch (...) {
    {
      std::lock_guard lock(mutex);
      stop = true;
      readerMayGo.notify_one();
    }
    reader.join();
    throw;
  }
  reader.join();
  if (readError) std::rethrow_exception(readError);
}

}  // namespace mpr

#include "script/script_read_ahead.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "util/helper_thread.hpp"

namespace mpr {
namespace {

// Commands per hand-over: the first batch small, so the calls start soon
// and a short script touches little memory, each next one twice the one
// before up to the last size (a lock per two thousand commands: fewer
// waits for a batch or for room; docs, "Measurements behind the code").
constexpr std::size_t kFirstBatchCommands = 256;
constexpr std::size_t kBatchCommands = 2048;
constexpr std::size_t kBatchesInFlight = 16;  // parsed ahead at most: some thirty thousand commands
// A reader that found the queue full sleeps until it is down to this many:
// then it parses a run of batches, not one per wake-up (on two cores shared
// with the row threads, each wake-up may wait for a time slice).
constexpr std::size_t kReaderResumesAt = kBatchesInFlight / 2;
// Slots of a batch fetched ahead of the command being unpacked (eight lines).
constexpr std::size_t kPrefetchSlots = 32;
// The reader refills the batch the caller handed back longest ago, and only
// once more than this many wait: its lines have left the calling core's
// cache by then, so writing them does not wait for that core to give them
// up.
constexpr std::size_t kSpareAge = 6;

// std::swap by member: the vectors, string and pointer trade their buffers
// (std::swap's three moves copied a short label's bytes each time).
// Every member is bound by name: a member added to ScriptCommand fails to
// compile here until it travels too (and with it Batch::add's packing and
// the unpacking below, which carry the same members: kind, line, call and
// args packed; label and probe whole).
void swapCommands(ScriptCommand& a, ScriptCommand& b) {
  auto& [kind, line, call, args, label, probe] = a;
  std::swap(kind, b.kind);
  std::swap(line, b.line);
  std::swap(call, b.call);
  args.swap(b.args);
  // A call has no label or probe: both empty, nothing to trade (a string's
  // swap is a dozen branches on its short-string buffer).
  if (!label.empty() || !b.label.empty()) label.swap(b.label);
  if (probe || b.probe) probe.swap(b.probe);
}

// A batch holds its commands packed one after another in slots of a
// ScriptArg's size: a command's header, then its arguments as they are (a
// vertex in 64 bytes, one or two cache lines). The calling thread hands a
// call on as a view of its arguments in the batch (no copy), and unpacks
// any other command into a command of its own. So the lines that cross
// from the reading core to the calling one are few, and the reader writes
// none the caller's cache holds but the batch's own: slots of ScriptCommand swapped to and fro,
// their argument vectors written by one core and read by the other, made
// every line of a command cross twice, and the reader ran twice as long on
// two cores as on one.
// A command with a label or a probe (directives) goes whole, in `whole`.
struct PackedHeader {
  std::int32_t line;
  GLCall call;
  ScriptCommand::Kind kind;
  std::uint16_t argCount;  // kWhole: the batch's next command in `whole`
};
static_assert(sizeof(PackedHeader) <= sizeof(ScriptArg) && sizeof(ScriptArg) == 16 &&
              std::is_trivially_copyable_v<ScriptArg>);
constexpr std::uint16_t kWhole = 0xffff;

// A batch's slot written past the reader's cache (a non-temporal store of
// its 16 bytes; a slot is 16-byte aligned, as operator new aligns a
// vector's storage, static_assert below): the batch's lines were last
// read on the calling core, and a plain store first fetched each back from
// there (a copy of a vertex's words was a quarter of the reader's time on
// the bathroom trace). handOver's fence orders
// these stores before the batch is handed on. (GCC's vector types may
// alias any object: the slot's bytes are written as a ScriptArg's.)
static_assert(__STDCPP_DEFAULT_NEW_ALIGNMENT__ >= 16);
inline void streamSlot(ScriptArg* to, const void* from) {
#if defined(__SSE2__)
  _mm_stream_si128(reinterpret_cast<__m128i*>(to), _mm_loadu_si128(static_cast<const __m128i*>(from)));
#else
  std::memcpy(static_cast<void*>(to), from, sizeof(ScriptArg));
#endif
}

struct Batch {
  std::vector<ScriptArg> slots;  // its size is its capacity; `used` of them hold commands
  std::size_t used = 0;
  std::size_t commands = 0;
  std::vector<ScriptCommand> whole;  // slots reused from batch to batch (swapped with the parser's)
  std::size_t wholeCount = 0;

  // A command: packed, or whole when it has a label or a probe.
  void add(ScriptCommand& c) {
    if (c.label.empty() && !c.probe && c.args.size() < kWhole) {
      addPacked(c.kind, c.call, c.line, c.args);
      return;
    }
    addPacked(c.kind, c.call, c.line, {}, kWhole);
    if (wholeCount == whole.size()) whole.emplace_back();
    swapCommands(whole[wholeCount++], c);
  }
  // A call as its parts (streamScript's call sink).
  void addCall(GLCall call, int line, std::span<const ScriptArg> args) {
    if (args.size() < kWhole) {
      addPacked(ScriptCommand::Kind::Call, call, line, args);
      return;
    }
    ScriptCommand c;  // (a call of 65 535 arguments or more: none of GL's)
    c.call = call;
    c.line = line;
    c.args.assign(args.begin(), args.end());
    add(c);
  }
  // The header and the arguments; argCount kWhole marks a whole command's
  // header (its arguments are in `whole`, none packed).
  void addPacked(ScriptCommand::Kind kind, GLCall call, int line, std::span<const ScriptArg> args,
                 std::uint16_t argCount = 0) {
    if (argCount != kWhole) argCount = static_cast<std::uint16_t>(args.size());
    const std::size_t need = 1 + args.size();
    if (used + need > slots.size()) slots.resize(std::max<std::size_t>(2 * slots.size(), used + need + 2048));
    alignas(16) unsigned char header[sizeof(ScriptArg)] = {};
    const PackedHeader h{line, call, kind, argCount};
    std::memcpy(header, &h, sizeof h);
    ScriptArg* to = slots.data() + used;  // (a local: the stores would reload the vector's pointer)
    streamSlot(to, header);
    for (std::size_t k = 0; k < args.size(); ++k) streamSlot(to + 1 + k, &args[k]);
    used += need;
    ++commands;
  }
};

struct ReaderStopped {};

}  // namespace

void streamScriptAhead(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  ScriptText whole = ScriptText::ofString(text);
  streamScriptAhead(whole, header, sink);
}

void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink) {
  streamScriptAhead(text, header, sink, nullptr);
}

void streamScriptAhead(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink,
                       const PackedCallSink& call) {
  std::mutex mutex;
  std::condition_variable readerMayGo, batchReady;
  bool readerWaiting = false, callerWaiting = false;
  std::deque<Batch> full;   // parsed, in order
  std::deque<Batch> spare;  // handed back by the caller's thread, oldest first
  bool finished = false, stop = false;
  std::exception_ptr readError;

  std::thread reader([&] {
    markHelperThread();  // the calling thread goes first on a shared core
    Batch batch;
    std::size_t batchCommands = kFirstBatchCommands;
    auto handOver = [&] {
#if defined(__SSE2__)
      _mm_sfence();  // the batch's streamed slots before the hand-over (streamSlot)
#endif
      std::unique_lock lock(mutex);
      if (full.size() >= kBatchesInFlight && !stop) {
        readerWaiting = true;
        readerMayGo.wait(lock, [&] { return full.size() <= kReaderResumesAt || stop; });
        readerWaiting = false;
      }
      if (stop) throw ReaderStopped{};
      full.push_back(std::move(batch));
      batch = Batch{};
      if (spare.size() > kSpareAge) {
        batch = std::move(spare.front());
        spare.pop_front();
      }
      if (callerWaiting) batchReady.notify_one();
    };
    try {
      auto added = [&] {
        if (batch.commands == batchCommands) {
          handOver();
          batchCommands = std::min(2 * batchCommands, kBatchCommands);
        }
      };
      // The calls packed from their parts: no command made for them (the
      // making and copying of a command per call line was a seventh of the
      // reader's instructions).
      streamScript(
          text, header,
          [&](ScriptCommand&& c) {
            batch.add(c);
            added();
          },
          [&](GLCall call, int line, std::span<const ScriptArg> args) {
            batch.addCall(call, line, args);
            added();
          });
      if (batch.commands > 0) handOver();
    } catch (const ReaderStopped&) {
    } catch (...) {
      readError = std::current_exception();
      try {
        if (batch.commands > 0) handOver();  // the commands before the error still run
      } catch (const ReaderStopped&) {
      }
    }
    std::lock_guard lock(mutex);
    finished = true;
    batchReady.notify_one();
  });

  try {
    ScriptCommand local;  // each packed command unpacked here, on the calling thread
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
      std::size_t at = 0, wholeAt = 0;
      for (std::size_t i = 0; i < batch.commands; ++i) {
        // The parser wrote these on another core: the slots a few commands
        // ahead are fetched while this one runs (the loads of a vertex's
        // three numbers were a tenth of the calling thread's time on the
        // bathroom trace).
        if (at + kPrefetchSlots < batch.used) __builtin_prefetch(&batch.slots[at + kPrefetchSlots]);
        PackedHeader h;
        std::memcpy(&h, &batch.slots[at], sizeof h);
        ++at;
        if (h.argCount == kWhole) {
          sink(std::move(batch.whole[wholeAt++]));
          continue;
        }
        // The arguments where they lie in the batch (a copy of them into a
        // command's vector, and the library's memcpy, were a tenth of the
        // calling thread's instructions on the bathroom trace).
        const std::span<const ScriptArg> args(batch.slots.data() + at, h.argCount);
        at += h.argCount;
        if (call && h.kind == ScriptCommand::Kind::Call && call(h.call, h.line, args)) continue;
        local.args.assign(args.begin(), args.end());
        local.kind = h.kind;
        local.line = h.line;
        local.call = h.call;
        local.label.clear();  // a sink may have left them moved from
        local.probe.reset();
        sink(std::move(local));
      }
      batch.used = 0;
      batch.commands = 0;
      batch.wholeCount = 0;
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

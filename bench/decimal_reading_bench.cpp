// The GL script's number reader against the standard library's (issue 42:
// keep a hand-written trick only where it pays clearly). The tokens are
// those a trace holds: vertex coordinates, normals and colours written by
// the trace writer's shortest round-trip text (util/number_text), each
// followed by the rest of its line as in a script, so the 16-byte reader
// may look past the token. Every reader must give the same doubles (the
// benchmark aborts otherwise); docs/dev/draw-path.md has the numbers.
#include <benchmark/benchmark.h>

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "script/recent_decimals.hpp"
#include "script/short_decimal.hpp"
#include "util/number_text.hpp"

namespace mpr {
namespace {

struct Tokens {
  std::string text;                    // "x y z\n" lines, as a script holds them
  std::vector<std::string_view> views;  // the numbers' tokens in it
};

// `distinct` different vertex lines, repeated to `lines` lines in a fixed
// random order: a mesh's vertices come back with each triangle that shares
// them (1: every line new; 8: about nine in ten repeat, as in the bathroom
// trace).
Tokens traceTokens(std::size_t lines, std::size_t distinct) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> coordinate(-20.0f, 20.0f), unit(-1.0f, 1.0f);
  std::vector<std::string> kinds;
  for (std::size_t i = 0; i < distinct; ++i) {
    std::string line;
    const bool normal = i % 3 == 1;
    for (int k = 0; k < 3; ++k) {
      if (k) line += ' ';
      appendShortest(line, normal ? unit(rng) : coordinate(rng));
    }
    kinds.push_back(line);
  }
  Tokens t;
  std::uniform_int_distribution<std::size_t> pick(0, distinct - 1);
  for (std::size_t i = 0; i < lines; ++i) t.text += kinds[i < distinct ? i : pick(rng)] + "\n";
  t.text.append(16, '\0');  // room for the 16-byte reads past the last token
  const std::string_view all(t.text.data(), t.text.size() - 16);
  std::size_t start = 0;
  for (std::size_t i = 0; i <= all.size(); ++i)
    if (i == all.size() || all[i] == ' ' || all[i] == '\n') {
      if (i > start) t.views.push_back(all.substr(start, i - start));
      start = i + 1;
    }
  return t;
}

// The numbers of a real trace (MPR_BENCH_TRACE=FILE.gls, e.g. one written
// by mpr render --trace), in their order: how often and how soon they repeat
// is the trace's own.
Tokens fileTokens(const char* path) {
  Tokens t;
  std::FILE* f = std::fopen(path, "rb");
  if (!f) std::abort();
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) t.text.append(buffer, n);
  std::fclose(f);
  t.text.append(16, '\0');
  const std::string_view all(t.text.data(), t.text.size() - 16);
  std::size_t start = 0;
  for (std::size_t i = 0; i <= all.size(); ++i)
    if (i == all.size() || all[i] == ' ' || all[i] == '\n') {
      const std::string_view v = all.substr(start, i - start);
      double d = 0.0;
      if (!v.empty() && (v[0] == '-' || (v[0] >= '0' && v[0] <= '9')) && plainShortDecimal(v, d)) t.views.push_back(v);
      start = i + 1;
    }
  return t;
}

// 1: every vertex line new; 8: each of 25 000 lines about eight times, in
// random order; 0: the trace named by MPR_BENCH_TRACE.
const Tokens& tokens(std::size_t repeat) {
  static const Tokens fresh = traceTokens(200000, 200000), repeated = traceTokens(200000, 25000);
  if (repeat == 0) {
    static const Tokens trace = std::getenv("MPR_BENCH_TRACE") ? fileTokens(std::getenv("MPR_BENCH_TRACE")) : fresh;
    return trace;
  }
  return repeat == 1 ? fresh : repeated;
}

void check(double a, double b) {
  if (std::memcmp(&a, &b, sizeof a) != 0) std::abort();
}

void BM_FromChars(benchmark::State& state) {
  const Tokens& t = tokens(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::string_view v : t.views) {
      double d = 0.0;
      std::from_chars(v.data(), v.data() + v.size(), d);
      sum += d;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.views.size()));
}

void BM_ShortDecimalAt(benchmark::State& state) {
  const Tokens& t = tokens(static_cast<std::size_t>(state.range(0)));
  const char* limit = t.text.data() + t.text.size();
  for (std::string_view v : t.views) {  // the same doubles as from_chars
    double a = 0.0, b = 0.0;
    if (!shortDecimalAt(v, limit, a)) std::abort();
    std::from_chars(v.data(), v.data() + v.size(), b);
    check(a, b);
  }
  for (auto _ : state) {
    double sum = 0.0;
    for (std::string_view v : t.views) {
      double d = 0.0;
      shortDecimalAt(v, limit, d);
      sum += d;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.views.size()));
}

// What the parser calls: the table of the numbers read last, then
// shortDecimalAt.
void BM_RecentDecimals(benchmark::State& state) {
  const Tokens& t = tokens(static_cast<std::size_t>(state.range(0)));
  const char* limit = t.text.data() + t.text.size();
  for (auto _ : state) {
    RecentDecimals recent;
    double sum = 0.0;
    for (std::string_view v : t.views) {
      double d = 0.0;
      recent.read(v, limit, d);
      sum += d;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * t.views.size()));
}

// Arg: 1, every vertex line new; 8, each distinct line eight times; 0, the
// trace MPR_BENCH_TRACE names (without it, as 1).
BENCHMARK(BM_FromChars)->Arg(1)->Arg(8)->Arg(0);
BENCHMARK(BM_ShortDecimalAt)->Arg(1)->Arg(8)->Arg(0);
BENCHMARK(BM_RecentDecimals)->Arg(1)->Arg(8)->Arg(0);

}  // namespace
}  // namespace mpr

// Times the same GL script on MPR (`mpr gl`) and on Mesa's llvmpipe and
// softpipe (bench/mesa_gl, through OSMesa) as whole processes: several runs,
// the tools alternating within each run so that a machine busy with other
// work slows them alike; prints per tool the median wall time, the ratio to
// llvmpipe's median, the median CPU time (user + system) and the peak
// resident memory (ru_maxrss from wait4). A last row, "reader", is the
// script read and checked alone as both read it (bench/read_gl_script): the
// floor under both, the part of their times that is not rendering.
//
// Usage: compare_mesa [--runs N] [--threads N] [--mpr PATH] [--mesa-gl PATH]
//                     [--no-softpipe] SCRIPT...
// --threads N sets LP_NUM_THREADS=N for llvmpipe and --threads N for MPR
// (both default to a thread a core). MPR runs the script with the mesa
// profile, the buffers OSMesa's context has.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct Sample {
  double seconds;
  double cpuSeconds;  // user + system, less sensitive than wall time to other work on the machine
  long peakKiB;
};

struct Tool {
  std::string name;
  std::vector<std::string> argv;  // the script is appended
  std::vector<std::string> env;   // NAME=VALUE set in the child
  std::vector<Sample> samples;
};

// Runs one command to its end; returns false when it failed.
bool runOnce(const Tool& tool, const std::string& script, Sample& out) {
  std::vector<std::string> args = tool.argv;
  args.push_back(script);
  std::vector<char*> cargs;
  for (std::string& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::fflush(stdout);  // else the child would write the parent's buffered lines again
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    for (const std::string& e : tool.env) putenv(const_cast<char*>(e.c_str()));
    if (std::freopen("/dev/null", "w", stdout) == nullptr) _exit(127);
    execv(cargs[0], cargs.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return false;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.peakKiB = usage.ru_maxrss;  // kilobytes on Linux
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
  out.cpuSeconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

int usage() {
  std::fprintf(stderr,
               "usage: compare_mesa [--runs N] [--threads N] [--mpr PATH] [--mesa-gl PATH] [--no-softpipe] "
               "SCRIPT...\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path here = std::filesystem::absolute(argv[0]).parent_path();
  std::string mpr = (here.parent_path() / "mpr").string(), mesaGl = (here / "mesa_gl").string(), threads;
  const std::string reader = (here / "read_gl_script").string();
  int runs = 5;
  bool softpipe = true;
  std::vector<std::string> scripts;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--runs" && hasValue) runs = std::atoi(argv[++i]);
    else if (a == "--threads" && hasValue) threads = argv[++i];
    else if (a == "--mpr" && hasValue) mpr = argv[++i];
    else if (a == "--mesa-gl" && hasValue) mesaGl = argv[++i];
    else if (a == "--no-softpipe") softpipe = false;
    else if (!a.empty() && a[0] != '-') scripts.push_back(a);
    else return usage();
  }
  if (scripts.empty() || runs < 1) return usage();

  for (const std::string& script : scripts) {
    std::vector<Tool> tools;
    Tool m{"mpr", {mpr, "gl", "--quiet", "--profile", "mesa"}, {}, {}};
    if (!threads.empty()) m.argv.insert(m.argv.end(), {"--threads", threads});
    tools.push_back(m);
    Tool lp{"llvmpipe", {mesaGl, "--driver", "llvmpipe"}, {}, {}};
    if (!threads.empty()) lp.env.push_back("LP_NUM_THREADS=" + threads);
    tools.push_back(lp);
    if (softpipe) tools.push_back({"softpipe", {mesaGl, "--driver", "softpipe"}, {}, {}});
    // The script read and checked as both read it, nothing drawn: the part
    // of every row above that is not the renderer's.
    tools.push_back({"reader", {reader}, {}, {}});
    for (int r = 0; r < runs; ++r)
      for (Tool& t : tools) {
        Sample s{};
        if (!runOnce(t, script, s)) {
          std::fprintf(stderr, "compare_mesa: %s failed on %s\n", t.name.c_str(), script.c_str());
          return 1;
        }
        t.samples.push_back(s);
      }
    auto medianOf = [](const Tool& t, bool cpu = false) {
      std::vector<double> v;
      for (const Sample& s : t.samples) v.push_back(cpu ? s.cpuSeconds : s.seconds);
      return median(v);
    };
    const double llvmpipe = medianOf(tools[1]);
    std::printf("%s (%d runs%s)\n", script.c_str(), runs, threads.empty() ? "" : (", " + threads + " threads").c_str());
    std::printf("  %-9s %9s %9s %9s %8s %10s %10s\n", "tool", "median s", "min s", "max s", "ratio", "cpu s", "peak MB");
    for (const Tool& t : tools) {
      double lo = t.samples[0].seconds, hi = lo;
      long peak = 0;
      for (const Sample& s : t.samples) {
        lo = std::min(lo, s.seconds);
        hi = std::max(hi, s.seconds);
        peak = std::max(peak, s.peakKiB);
      }
      std::printf("  %-9s %9.3f %9.3f %9.3f %8.2f %10.3f %10.1f\n", t.name.c_str(), medianOf(t), lo, hi,
                  medianOf(t) / llvmpipe, medianOf(t, true), static_cast<double>(peak) / 1024.0);
    }
  }
  return 0;
}

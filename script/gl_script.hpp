#pragma once
// The GL script format (spec/gl-script.md): parsing into a checked list of
// commands (parseScript), or checked and then streamed command by command
// from a text read a piece at a time (checkScript, streamScript; `mpr gl`):
// either way a script error is found before a file is written.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <memory>

#include "pipeline/gl/gl_call.hpp"
#include "framebuffer/script_probe.hpp"
#include "util/printable_text.hpp"

namespace mpr {

class ScriptText;  // pipeline/script_text.hpp

// A user error in a script: FILE:LINE:COLUMN: message.
class ScriptError : public std::runtime_error {
 public:
  ScriptError(std::string file, int line, int column, const std::string& message)
      : std::runtime_error(printableText(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message)),
        file_(std::move(file)), line_(line), column_(column) {}
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  int line_, column_;
};

// An argument as its value; its text is the script's at `column` of the
// command's line (no copy of it is kept: nothing that executes a command
// reads it, and sixteen bytes an argument, not forty-eight, keep a vertex's
// three in one cache line on their way from the reading thread to the
// calling one).
struct ScriptArg {
  double number = 0.0;       // the value as a number (enums: their value)
  std::uint32_t bits = 0;    // integer and enum arguments as GL's 32-bit word
  int column = 0;
};

struct ScriptCommand {
  // A GL call, or a directive: @pass, @snapshot, @window_map (args: 9
  // numbers, or none for off), @count_fragments (label: begin or end),
  // @expect and @expect-picture (probe; label: the directive as written).
  enum class Kind : std::uint8_t { Call, Pass, Snapshot, WindowMap, FragmentCount, Probe } kind = Kind::Call;
  int line = 0;
  GLCall call = GLCall::Finish;
  std::vector<ScriptArg> args;
  std::string label;  // pass label or snapshot name
  std::shared_ptr<const ScriptProbe> probe;  // Probe only
  // (script_read_ahead.cpp's swapCommands binds every member by name: a
  // member added here does not compile there until the read-ahead carries it.)
};

struct Script {
  std::string file;
  std::string text;  // the source, for reports that reproduce a run
  int width = 256, height = 256;  // @framebuffer; 256x256 when absent
  std::optional<std::string> profile;
  std::vector<ScriptCommand> commands;
  std::size_t callCount() const;
  std::size_t probeCount() const;
};

// Parses `text`; `file` names it in error messages. Throws ScriptError.
Script parseScript(std::string_view text, const std::string& file);
// Reads and parses a file; an unreadable file is a ScriptError at 0:0.
// The largest script file read (a regular file only): 1 GiB, about five
// times the trace of the bathroom scene's 2.85 M calls.
inline constexpr std::uint64_t kMaxScriptBytes = std::uint64_t{1} << 30;
Script loadScript(const std::string& path);
// The text of a script file, read within kMaxScriptBytes; ScriptError at 0:0 when unreadable.
std::string readScriptText(const std::string& path);

// A script executed as it is read, in two passes over its text: checkScript
// parses all of it and throws the first ScriptError, keeping no command (the
// Script it returns holds file, size and profile, no commands); streamScript
// then parses it again and hands each command to `sink` as soon as it is
// complete (a probe with its pixels placed, an @expect-picture at its @end).
// The commands and their order are parseScript's; memory does not grow with
// the script's length.
// Each also reads a ScriptText (a file a piece at a time: memory does not
// grow with the script's length either), from its start.
Script checkScript(std::string_view text, const std::string& file);
Script checkScript(ScriptText& text, const std::string& file);
// The header checkScript's Script holds (file, size, profile), from the
// lines before the first call, where @framebuffer and @profile must stand:
// those lines are checked as checkScript checks them, so an error thrown
// here is the script's first error, the one checkScript throws (a script
// without a call is checked whole). What
// streamScript needs to start before the whole script is checked
// (`mpr gl` with more than one thread).
Script scanScriptHeader(std::string_view text, const std::string& file);
Script scanScriptHeader(ScriptText& text, const std::string& file);
void streamScript(std::string_view text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);
void streamScript(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink);
// The same, each call handed to `call` as its parts instead (no command made
// for it: a call line seen before goes on as the arguments kept for its
// bytes), the directives to `sink`. In the order streamScript hands them on.
using ScriptCallSink = std::function<void(GLCall call, int line, std::span<const ScriptArg> args)>;
void streamScript(ScriptText& text, const Script& header, const std::function<void(ScriptCommand&&)>& sink,
                  const ScriptCallSink& call);

}  // namespace mpr

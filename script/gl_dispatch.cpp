#include "script/gl_dispatch.hpp"

#include <array>
#include <span>
#include <tuple>
#include <type_traits>

#include "util/check.hpp"

namespace mpr {
namespace {

// Reads a command's arguments in order as the parameter types ask. The parser
// has checked every count; the cursor checks it again, as an invariant.
class ArgCursor {
 public:
  explicit ArgCursor(std::span<const ScriptArg> args) : args_(args) {}
  const ScriptArg& next() {
    MPR_CHECK_LT(i_, args_.size());
    return args_[i_++];
  }
  std::size_t left() const { return args_.size() - i_; }

 private:
  std::span<const ScriptArg> args_;
  std::size_t i_ = 0;
};

template <class T>
struct Arg {
  T value;
  explicit Arg(ArgCursor& a) {
    const ScriptArg& s = a.next();
    if constexpr (std::is_same_v<T, GLfloat>) value = static_cast<GLfloat>(s.number);
    else if constexpr (std::is_same_v<T, GLdouble>) value = s.number;
    else if constexpr (std::is_same_v<T, GLint>) value = static_cast<GLint>(static_cast<std::int32_t>(s.bits));
    else if constexpr (std::is_same_v<T, GLuint>) value = s.bits;  // GLenum, GLbitfield
    else if constexpr (std::is_same_v<T, GLubyte>) value = static_cast<GLubyte>(s.bits);  // GLboolean too
    else static_assert(sizeof(T) == 0, "a parameter type gl_calls.def does not use");
  }
  T get() const { return value; }
};

// A pointer parameter takes the remaining values (at most 16).
template <class T>
struct Arg<const T*> {
  std::array<T, 16> values{};
  explicit Arg(ArgCursor& a) {
    for (std::size_t i = 0; a.left() > 0 && i < values.size(); ++i) values[i] = static_cast<T>(a.next().number);
  }
  const T* get() const { return values.data(); }
};

template <class... P>
void invoke(GLApi& api, void (GLApi::*fn)(P...), std::span<const ScriptArg> args) {
  ArgCursor cursor(args);
  // Braced initialisation reads the arguments left to right.
  const std::tuple<Arg<P>...> values{Arg<P>(cursor)...};
  std::apply([&](const auto&... a) { (api.*fn)(a.get()...); }, values);
}

}  // namespace

void dispatch(GLApi& api, const ScriptCommand& cmd) {
  switch (cmd.kind) {
    case ScriptCommand::Kind::Snapshot: return;
    // A probe reads the buffers and changes nothing: not a call of the API
    // (a replay on Mesa, or into a trace, passes over it).
    case ScriptCommand::Kind::Probe: return;
    case ScriptCommand::Kind::Pass: return api.pass(cmd.label);
    case ScriptCommand::Kind::WindowMap: {
      if (cmd.args.empty()) return api.windowMap(std::nullopt);
      MPR_CHECK_EQ(cmd.args.size(), 9u);
      glm::mat3 m;
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) m[k][i] = static_cast<float>(cmd.args[static_cast<std::size_t>(3 * k + i)].number);
      return api.windowMap(m);
    }
    case ScriptCommand::Kind::FragmentCount:
      if (cmd.label == "begin") return api.beginFragmentCount();
      api.endFragmentCount();
      return;
    case ScriptCommand::Kind::Call: break;
  }
  dispatchCall(api, cmd.call, cmd.args);
}

void dispatchCall(GLApi& api, GLCall call, std::span<const ScriptArg> callArgs) {
  switch (call) {
#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) \
  case GLCall::Enum: return invoke(api, &GLApi::method, callArgs);
#include "pipeline/gl/gl_calls.def"
  }
}

}  // namespace mpr

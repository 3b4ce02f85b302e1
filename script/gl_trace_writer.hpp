#pragma once
// The GL stream as text (pbrt-v4's FormattingParserTarget): every call and
// directive written as a GL script line (spec/gl-script.md,
// docs/gl-script-directives.md). Numbers are the shortest text that reads
// back to the same value, so `mpr gl` replays a trace to the same bytes while
// the render itself never goes through text.
#include <string>

#include "pipeline/gl/gl_api.hpp"

namespace mpr {

class GLTraceWriter final : public GLApi {
 public:
  // Starts the trace with @framebuffer and @profile.
  GLTraceWriter(int width, int height, std::string_view profile);
  GLTraceWriter() = default;  // no header: lines only

#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) \
  void method params override { line(GLCall::Enum MPR_GL_COMMA_ARGS args); }
#define MPR_GL_COMMA_ARGS(...) __VA_OPT__(, ) __VA_ARGS__
#include "pipeline/gl/gl_calls.def"
#undef MPR_GL_COMMA_ARGS

  void pass(std::string_view label) override;
  void windowMap(const std::optional<glm::mat3>& map) override;
  void beginFragmentCount() override;
  std::uint64_t endFragmentCount() override;  // writes the directive; returns 0

  const std::string& text() const { return out_; }

 private:
  // One line's arguments, each written by its kind letter in the table.
  struct Line {
    std::string& out;
    GLCall call;
    std::string_view kinds;
    std::size_t k = 0;
    std::uint32_t lastEnum = 0;
    char kind() const { return k < kinds.size() ? kinds[k] : '?'; }
    void put(GLuint v);
    void put(GLint v);
    void put(GLubyte v);
    void put(GLfloat v);
    void put(GLdouble v);
    void put(const GLfloat* v) { values(v); }
    void put(const GLdouble* v) { values(v); }
    template <class T>
    void values(const T* v) {
      const int n = valueCount();
      for (int i = 0; i < n; ++i) put(v[i]);
      k = kinds.size();
    }
    int valueCount() const;
  };

  template <class... A>
  void line(GLCall c, const A&... a) {
    out_ += glCallName(c);
    [[maybe_unused]] Line l{out_, c, glCallInfo(c).kinds};
    (l.put(a), ...);
    out_ += '\n';
  }

  std::string out_;
};

}  // namespace mpr

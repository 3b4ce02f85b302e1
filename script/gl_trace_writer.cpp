#include "script/gl_trace_writer.hpp"

#include "pipeline/gl/gl_enums.hpp"
#include "util/check.hpp"
#include "util/number_text.hpp"

namespace mpr {

GLTraceWriter::GLTraceWriter(int width, int height, std::string_view profile) {
  out_ = "@framebuffer " + std::to_string(width) + " " + std::to_string(height) + "\n@profile ";
  out_ += profile;
  out_ += '\n';
}

void GLTraceWriter::Line::put(GLuint v) {
  out += ' ';
  const char kd = kind();
  ++k;
  if (kd == 'b') {
    out += glBufferBitsText(v);
    return;
  }
  if (kd == 'e' || kd == 'p') {
    lastEnum = v;
    const auto name = kd == 'p' ? glPrimitiveName(v) : glEnumName(v);
    if (name) {
      out += *name;
      return;
    }
    // A value without a name cannot be written as an enum argument.
    MPR_CHECK(name.has_value());
  }
  appendInteger(out, v);  // 'i': an unsigned mask
}

void GLTraceWriter::Line::put(GLint v) {
  out += ' ';
  const char kd = kind();
  ++k;
  if (kd == 'n' && lastEnum == GL_FOG_MODE)
    if (const auto name = glEnumName(static_cast<std::uint32_t>(v))) {
      out += *name;
      return;
    }
  appendInteger(out, v);
}

void GLTraceWriter::Line::put(GLubyte v) {
  out += ' ';
  const char kd = kind();
  ++k;
  if (kd == 'z') out += v ? "GL_TRUE" : "GL_FALSE";
  else appendInteger(out, v);
}

void GLTraceWriter::Line::put(GLfloat v) {
  out += ' ';
  ++k;
  appendShortest(out, v);
}

void GLTraceWriter::Line::put(GLdouble v) {
  out += ' ';
  ++k;
  appendShortest(out, v);
}

int GLTraceWriter::Line::valueCount() const {
  if (kind() == 'm') return 16;
  if (kind() == 'v') {
    const int n = glVectorCount(call, lastEnum);
    return n > 0 ? n : 4;  // a pname GL rejects: its 4 values, as a script may give
  }
  return static_cast<int>(kinds.size() - k);
}

void GLTraceWriter::pass(std::string_view label) {
  out_ += "@pass ";
  out_ += label;
  out_ += '\n';
}

void GLTraceWriter::windowMap(const std::optional<glm::mat3>& map) {
  out_ += "@window_map";
  if (!map) out_ += " off";
  for (int k = 0; map && k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      out_ += ' ';
      appendShortest(out_, (*map)[k][i]);
    }
  out_ += '\n';
}

void GLTraceWriter::beginFragmentCount() { out_ += "@count_fragments begin\n"; }

std::uint64_t GLTraceWriter::endFragmentCount() {
  out_ += "@count_fragments end\n";
  return 0;
}

}  // namespace mpr

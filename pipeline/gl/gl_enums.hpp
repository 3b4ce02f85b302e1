#pragma once
// GL enumerant names as a script writes them (spec/gl-script.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mpr {

// The value of a GL enumerant name ("GL_KEEP"), or nothing for an unknown name.
std::optional<std::uint32_t> glEnumValue(std::string_view name);

// The name a trace writes for an enum value: GL_ZERO and GL_ONE for 0 and 1,
// otherwise the table's first name that is neither a bit (..._BIT) nor a
// vendor alias (..._EXT, ..._ARB); nothing for a value without a name.
std::optional<std::string_view> glEnumName(std::uint32_t value);

// A primitive mode's name (GL_POINTS .. GL_POLYGON), nothing outside them.
std::optional<std::string_view> glPrimitiveName(std::uint32_t mode);

// "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT" for a glClear mask (colour,
// depth, stencil, accumulation, then any other bits as one hex number).
std::string glBufferBitsText(std::uint32_t bits);

// "GL_INVALID_ENUM" for 0x0500 and so on.
std::string_view glErrorName(std::uint32_t error);

}  // namespace mpr

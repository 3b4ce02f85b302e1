#pragma once
// GL enumerant names as a script writes them (spec/gl-script.md).
#include <cstdint>
#include <optional>
#include <string_view>

namespace mpr {

// The value of a GL enumerant name ("GL_KEEP"), or nothing for an unknown name.
std::optional<std::uint32_t> glEnumValue(std::string_view name);

// "GL_INVALID_ENUM" for 0x0500 and so on.
std::string_view glErrorName(std::uint32_t error);

}  // namespace mpr

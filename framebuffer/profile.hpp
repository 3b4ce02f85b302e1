#pragma once
// Hardware profiles: the bit widths of every buffer (spec/gl-script.md,
// "Profiles"). Everything that depends on a width (stencil saturation, the
// shadow constants of the 1994 paper, accumulation rounding) reads it here.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mpr {

enum class AccumulationArithmetic {
  Saturating,  // indigo: results clamp to the signed 16-bit range
  MesaWrap,    // mesa: the same truncation and wrap as Mesa's main/accum.c
};

struct HardwareProfile {
  std::string name;
  int colorBits = 8;    // per channel, RGBA
  int depthBits = 24;
  int stencilBits = 8;
  int accumBits = 16;   // per channel, signed
  bool accumHasAlpha = false;
  AccumulationArithmetic accumArithmetic = AccumulationArithmetic::Saturating;

  std::uint32_t stencilMax() const { return (1u << stencilBits) - 1u; }
  std::uint32_t depthMax() const { return (1u << depthBits) - 1u; }
};

// The profiles the spec names. `indigo` is the default.
const HardwareProfile& indigoProfile();
const HardwareProfile& mesaProfile();
std::optional<HardwareProfile> findProfile(std::string_view name);
std::vector<std::string> profileNames();

}  // namespace mpr

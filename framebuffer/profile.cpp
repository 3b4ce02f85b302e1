#include "framebuffer/profile.hpp"

namespace mpr {

const HardwareProfile& indigoProfile() {
  // The paper's machine: 48-bit accumulation as three signed 16-bit words.
  static const HardwareProfile p{"indigo", 8, 24, 8, 16, false, AccumulationArithmetic::Saturating};
  return p;
}

const HardwareProfile& mesaProfile() {
  // What OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, ...) provides.
  static const HardwareProfile p{"mesa", 8, 24, 8, 16, true, AccumulationArithmetic::MesaWrap};
  return p;
}

std::optional<HardwareProfile> findProfile(std::string_view name) {
  if (name == "indigo") return indigoProfile();
  if (name == "mesa") return mesaProfile();
  return std::nullopt;
}

std::vector<std::string> profileNames() { return {"indigo", "mesa"}; }

}  // namespace mpr

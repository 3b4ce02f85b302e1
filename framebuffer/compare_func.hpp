#pragma once
// The eight comparison functions shared by the alpha, stencil and depth tests.
// GL writes them as "incoming OP stored": for the stencil test the incoming
// value is the (masked) reference, so GL_GREATER passes when ref > stored.
#include <cstdint>

namespace mpr {

enum class CompareFunc : std::uint8_t { Never, Less, Equal, Lequal, Greater, Notequal, Gequal, Always };

template <typename T>
constexpr bool compare(CompareFunc f, T incoming, T stored) {
  switch (f) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return incoming < stored;
    case CompareFunc::Equal: return incoming == stored;
    case CompareFunc::Lequal: return incoming <= stored;
    case CompareFunc::Greater: return incoming > stored;
    case CompareFunc::Notequal: return incoming != stored;
    case CompareFunc::Gequal: return incoming >= stored;
    case CompareFunc::Always: return true;
  }
  return false;
}

}  // namespace mpr

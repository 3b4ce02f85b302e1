#include "framebuffer/npy_writer.hpp"

#include <bit>
#include <cstring>

namespace mpr {

static_assert(std::endian::native == std::endian::little, "the .npy dumps are written little-endian");

std::string npyBytes(const std::string& descr, const std::vector<std::size_t>& shape, const void* data,
                     std::size_t dataBytes) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    dict += std::to_string(shape[i]);
    if (shape.size() == 1 || i + 1 < shape.size()) dict += ",";
    if (i + 1 < shape.size()) dict += " ";
  }
  dict += "), }";
  // Magic (6) + version (2) + length (2) + header, padded with blanks and a
  // final newline to a multiple of 64 bytes, as NumPy writes it.
  std::size_t total = 10 + dict.size() + 1;
  const std::size_t padded = (total + 63) / 64 * 64;
  dict.append(padded - total, ' ');
  dict += '\n';
  const auto headerLen = static_cast<std::uint16_t>(dict.size());
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(headerLen & 0xFF);
  out += static_cast<char>(headerLen >> 8);
  out += dict;
  out.append(static_cast<const char*>(data), dataBytes);
  return out;
}

const std::vector<std::string>& framebufferDumpNames() {
  static const std::vector<std::string> names{"color", "depth", "stencil", "accum"};
  return names;
}

std::vector<NamedBytes> framebufferNpyDumps(const Framebuffer& fb) {
  const std::size_t h = static_cast<std::size_t>(fb.height()), w = static_cast<std::size_t>(fb.width());
  const std::vector<std::string>& name = framebufferDumpNames();
  std::vector<NamedBytes> out;
  out.push_back({name[0], npyBytes("|u1", {h, w, 4}, fb.colorData().data(), h * w * 4)});
  out.push_back({name[1], npyBytes("<u4", {h, w}, fb.depthData().data(), h * w * 4)});
  out.push_back({name[2], npyBytes("|u1", {h, w}, fb.stencilData().data(), h * w)});
  out.push_back({name[3], npyBytes("<i2", {h, w, 4}, fb.accumData().data(), h * w * 8)});
  return out;
}

}  // namespace mpr

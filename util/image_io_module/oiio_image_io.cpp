// libmpr_image_io.so: everything MPR asks of OpenImageIO, behind the table
// of util/image_io_table.hpp, so that only a process that reads or writes
// an image loads OpenImageIO (util/image_io.hpp).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "util/image_io_table.hpp"

namespace mpr {
namespace {

std::string write(const std::string& formatPath, const std::string& filePath, int w, int h, int channels,
                  bool isFloat, const void* top, std::ptrdiff_t stride) {
  // The format comes from formatPath's name; the bytes go to filePath.
  auto out = OIIO::ImageOutput::create(formatPath);
  if (!out) return OIIO::geterror();
  const OIIO::TypeDesc type = isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  const OIIO::ImageSpec spec(w, h, channels, type);
  if (!out->open(filePath, spec) || !out->write_image(type, top, OIIO::AutoStride, stride) || !out->close())
    return out->geterror();
  return "";
}

std::string encodePng(int w, int h, int channels, const std::uint8_t* top, std::ptrdiff_t stride, std::string& png) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create("image.png");
  if (!out || !out->set_ioproxy(&proxy)) return OIIO::geterror();
  const OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
  if (!out->open("image.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, top, OIIO::AutoStride, stride) ||
      !out->close())
    return out->geterror();
  png.assign(bytes.begin(), bytes.end());
  return "";
}

std::string read(const std::string& path, DecodedImage& image) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  image.width = spec.width, image.height = spec.height, image.channels = spec.nchannels;
  image.isFloat = spec.format != OIIO::TypeDesc::UINT8;
  const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels;
  const bool ok = image.isFloat ? (image.floats.resize(n), in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                                                                          image.floats.data()))
                                : (image.bytes.resize(n), in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8,
                                                                         image.bytes.data()));
  return ok ? "" : in->geterror();
}

std::string drawCanvas(int w, int h, const std::vector<CanvasOp>& ops, std::string& png) {
  using namespace OIIO;
  ImageBuf b(ImageSpec(w, h, 3, TypeDesc::UINT8));
  const float white[3] = {1, 1, 1};
  ImageBufAlgo::fill(b, white);
  const auto alignX = [](int a) {
    return a < 0 ? ImageBufAlgo::TextAlignX::Left : a == 0 ? ImageBufAlgo::TextAlignX::Center
                                                           : ImageBufAlgo::TextAlignX::Right;
  };
  for (const CanvasOp& op : ops) {
    const cspan<float> c(op.rgb, 3);
    switch (op.kind) {
      case CanvasOp::Kind::Line: ImageBufAlgo::render_line(b, op.x0, op.y0, op.x1, op.y1, c); break;
      case CanvasOp::Kind::Box: ImageBufAlgo::render_box(b, op.x0, op.y0, op.x1, op.y1, c); break;
      case CanvasOp::Kind::FilledBox: ImageBufAlgo::render_box(b, op.x0, op.y0, op.x1, op.y1, c, true); break;
      case CanvasOp::Kind::Text:  // no font: no text, the drawing stays
        ImageBufAlgo::render_text(b, op.x0, op.y0, op.text, op.size, "DejaVuSans", c, alignX(op.align));
        break;
      case CanvasOp::Kind::TextUp: {  // drawn on its own strip, turned a quarter anticlockwise
        ImageBuf strip(ImageSpec(300, 20, 3, TypeDesc::UINT8));
        ImageBufAlgo::fill(strip, white);
        ImageBufAlgo::render_text(strip, 150, 15, op.text, op.size, "DejaVuSans", c, ImageBufAlgo::TextAlignX::Center);
        ImageBuf up = ImageBufAlgo::rotate270(strip);
        ImageBufAlgo::paste(b, op.x0, op.y0, 0, 0, up);
        break;
      }
    }
  }
  std::vector<unsigned char> bytes;
  Filesystem::IOVecOutput proxy(bytes);
  b.set_write_ioproxy(&proxy);
  if (!b.write("canvas.png", TypeDesc::UINT8, "png")) return b.geterror();
  png.assign(bytes.begin(), bytes.end());
  return "";
}

const ImageIoTable kTable{kImageIoTableVersion, &write, &encodePng, &read, &drawCanvas};

}  // namespace
}  // namespace mpr

extern "C" __attribute__((visibility("default"))) const mpr::ImageIoTable* mpr_image_io_table() {
  return &mpr::kTable;
}

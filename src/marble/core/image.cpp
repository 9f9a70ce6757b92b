#include "marble/core/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <ImfArray.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"
#include "marble/core/png_text.h"
#include "marble/core/input_file.h"

namespace marble {

namespace {
// OpenEXR's messages can run over several lines; a marble error is one.
std::string firstLine(std::string what) {
  if (auto nl = what.find('\n'); nl != std::string::npos) what.resize(nl);
  return what;
}
}  // namespace

std::string encodePng(const ImageRGBA8& image) {
  std::string bytes;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(sink, &bytes, image.width, image.height, 4, image.pixels.data(), image.width * 4))
    throw std::runtime_error("PNG encoding failed");
  return bytes;
}

void writePng(const std::filesystem::path& path, const ImageRGBA8& image, const std::vector<PngText>& text) {
  std::string bytes;
  try {
    bytes = encodePng(image);
  } catch (const std::runtime_error& e) {
    throw InputError(path.string(), "", e.what());
  }
  for (const auto& t : text) bytes = insertPngText(bytes, t.keyword, t.text);
  writeFileAtomically(path, bytes);
}

ImageRGBA8 readPng(const std::filesystem::path& path) {
  { InputFile(path, path.string(), "an image file"); }  // a regular file, or a true message
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) throw InputError(path.string(), "", std::string("cannot read image: ") + stbi_failure_reason());
  ImageRGBA8 img{w, h, std::vector<uint8_t>(data, data + static_cast<size_t>(w) * h * 4)};
  stbi_image_free(data);
  return img;
}

std::optional<std::string> readPngText(const std::filesystem::path& path, const std::string& keyword) {
  // The whole file: the text may follow the image data. 1 GiB is far beyond any marble PNG.
  const std::string bytes = InputFile(path, path.string(), "an image file").readAll(1ull << 30);
  try {
    return findPngText(bytes, keyword);
  } catch (const std::invalid_argument& e) {
    throw InputError(path.string(), "", e.what());
  }
}

void flipRows(ImageRGBA8& image) {
  const size_t row = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.pixels.begin() + y * row, image.pixels.begin() + (y + 1) * row,
                     image.pixels.begin() + (image.height - 1 - y) * row);
}

namespace {
// OpenEXR writes to a stream; this one collects the bytes, which then go through the one
// atomic-write routine like every other file.
class MemoryStream : public Imf::OStream {
public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    const size_t end = position_ + static_cast<size_t>(n);
    if (end > bytes.size()) bytes.resize(end);
    std::memcpy(bytes.data() + position_, c, static_cast<size_t>(n));
    position_ = end;
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = static_cast<size_t>(pos); }
  std::string bytes;

private:
  size_t position_ = 0;
};
}  // namespace

std::string encodeExr(const ImageRGBF& image) {
  const size_t n = static_cast<size_t>(image.width) * image.height;
  if (!image.alpha.empty() && image.alpha.size() != n)
    throw std::invalid_argument("encodeExr: alpha has " + std::to_string(image.alpha.size()) + " values for " +
                                std::to_string(n) + " pixels");
  Imf::Array2D<Imf::Rgba> px(image.height, image.width);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = static_cast<size_t>(y) * image.width + x;
      const float* p = &image.pixels[i * 3];
      px[y][x] = Imf::Rgba(p[0], p[1], p[2], image.alpha.empty() ? 1.0f : image.alpha[i]);
    }
  Imf::Header header(image.width, image.height);
  if (!image.alpha.empty()) header.insert(kExrCoverageAttribute, Imf::StringAttribute("coverage"));
  MemoryStream stream;
  {
    Imf::RgbaOutputFile file(stream, header, Imf::WRITE_RGBA);
    file.setFrameBuffer(&px[0][0], 1, static_cast<size_t>(image.width));
    file.writePixels(image.height);
  }  // the file's destructor writes the line offset table
  return std::move(stream.bytes);
}

void writeExr(const std::filesystem::path& path, const ImageRGBF& image) {
  std::string bytes;
  try {
    bytes = encodeExr(image);
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path.string(), "", std::string("cannot encode EXR: ") + firstLine(e.what()));
  }
  writeFileAtomically(path, bytes);
}

ImageRGBF readExr(const std::filesystem::path& path, bool* markedCoverage) {
  try {
    { InputFile(path, path.string(), "an EXR file"); }  // a regular file, or a true message (not a hang on a FIFO)
    Imf::RgbaInputFile file(path.c_str());
    const auto dw = file.dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0) throw std::runtime_error("empty data window");
    Imf::Array2D<Imf::Rgba> px(h, w);
    file.setFrameBuffer(&px[0][0] - dw.min.x - static_cast<ptrdiff_t>(dw.min.y) * w, 1, static_cast<size_t>(w));
    file.readPixels(dw.min.y, dw.max.y);
    // Without an A channel OpenEXR reads alpha as 1; say "no alpha" instead.
    const bool hasAlpha = (file.channels() & Imf::WRITE_A) != 0;
    ImageRGBF img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
    if (hasAlpha) img.alpha.resize(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        float* p = &img.pixels[i * 3];
        p[0] = px[y][x].r; p[1] = px[y][x].g; p[2] = px[y][x].b;
        if (hasAlpha) img.alpha[i] = px[y][x].a;
      }
    if (markedCoverage) {
      const auto* mark = file.header().findTypedAttribute<Imf::StringAttribute>(kExrCoverageAttribute);
      *markedCoverage = hasAlpha && mark && mark->value() == "coverage";
    }
    return img;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path.string(), "", std::string("cannot read EXR: ") + firstLine(e.what()));
  }
}

}  // namespace marble

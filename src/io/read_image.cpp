// Image reading through OpenCV's imgcodecs, with every failure turned into a status and a message.
#include <tessera/io/image.h>

#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <fstream>
#include <iterator>

namespace tessera {
namespace {

// The size an image's header gives, read before OpenCV allocates anything: a huge image is refused
// first. Only PNG, JPEG and BMP are accepted: every other decoder OpenCV carries (TIFF, EXR, GDAL's
// formats, ...) would need its own header check.
enum class Format { png, jpeg, bmp, other };

Format header_size(const std::vector<std::uint8_t>& b, std::size_t& w, std::size_t& h) {
  auto be16 = [&](std::size_t i) { return (std::size_t(b[i]) << 8) | std::size_t(b[i + 1]); };
  auto be32 = [&](std::size_t i) { return (be16(i) << 16) | be16(i + 2); };
  auto le32 = [&](std::size_t i) {
    return std::int32_t(std::uint32_t(b[i]) | (std::uint32_t(b[i + 1]) << 8) |
                        (std::uint32_t(b[i + 2]) << 16) | (std::uint32_t(b[i + 3]) << 24));
  };
  static const std::uint8_t png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() >= 24 && std::equal(png, png + 8, b.begin())) {
    w = be32(16), h = be32(20);
    return Format::png;
  }
  if (b.size() >= 26 && b[0] == 'B' && b[1] == 'M') {
    const std::int64_t bw = le32(18), bh = le32(22);
    w = std::size_t(bw < 0 ? -bw : bw), h = std::size_t(bh < 0 ? -bh : bh);
    return Format::bmp;
  }
  if (b.size() >= 4 && b[0] == 0xff && b[1] == 0xd8) {
    // Markers up to the first start of frame (SOF0-SOF15 less DHT, JPG and DAC), which holds the
    // size; none found gives 0 x 0, refused as undecodable.
    w = h = 0;
    for (std::size_t i = 2; i + 9 < b.size();) {
      if (b[i] != 0xff)
        return Format::jpeg;
      const std::uint8_t m = b[i + 1];
      if (m == 0xff) {
        ++i;
        continue;
      }
      if (m >= 0xc0 && m <= 0xcf && m != 0xc4 && m != 0xc8 && m != 0xcc) {
        h = be16(i + 5), w = be16(i + 7);
        return Format::jpeg;
      }
      if (m == 0xd8 || (m >= 0xd0 && m <= 0xd7) || m == 0x01) {
        i += 2;
        continue;
      }
      i += 2 + be16(i + 2);
    }
    return Format::jpeg;
  }
  return Format::other;
}

// OpenCV logs decoder complaints on stderr; the caller gets them as a message instead.
struct Quiet_opencv {
  cv::utils::logging::LogLevel saved;
  Quiet_opencv() : saved(cv::utils::logging::getLogLevel()) {
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  }
  ~Quiet_opencv() { cv::utils::logging::setLogLevel(saved); }
};

} // namespace

Image_read_result decode_image(const std::vector<std::uint8_t>& bytes,
                               const Image_read_options& options) {
  Image_read_result r;
  if (bytes.empty()) {
    r.status = Image_read_status::empty_file;
    r.message = "the image is empty (0 bytes)";
    return r;
  }
  std::size_t w = 0, h = 0;
  if (header_size(bytes, w, h) == Format::other) {
    r.status = Image_read_status::cannot_decode;
    r.message = "not a PNG, JPEG or BMP image";
    return r;
  }
  if (w == 0 || h == 0 || w > options.max_pixels / std::max<std::size_t>(h, 1)) {
    r.status = w == 0 || h == 0 ? Image_read_status::cannot_decode : Image_read_status::too_large;
    r.message = "the image's header gives a size of " + std::to_string(w) + " x " +
                std::to_string(h) +
                (r.status == Image_read_status::too_large
                     ? " pixels, more than the limit of " + std::to_string(options.max_pixels)
                     : "");
    return r;
  }
  cv::Mat decoded;
  try {
    Quiet_opencv quiet;
    decoded =
        cv::imdecode(cv::Mat(1, int(bytes.size()), CV_8U, const_cast<std::uint8_t*>(bytes.data())),
                     cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    r.status = Image_read_status::cannot_decode;
    r.message = std::string("the image cannot be decoded: ") + e.what();
    return r;
  }
  if (decoded.empty() || decoded.cols <= 0 || decoded.rows <= 0) {
    r.status = Image_read_status::cannot_decode;
    r.message =
        "the image cannot be decoded (corrupt, truncated, or not an image format OpenCV reads)";
    return r;
  }
  if (std::size_t(decoded.cols) * std::size_t(decoded.rows) > options.max_pixels) {
    r.status = Image_read_status::too_large;
    r.message = "the image has " + std::to_string(decoded.cols) + " x " +
                std::to_string(decoded.rows) + " pixels, more than the limit of " +
                std::to_string(options.max_pixels);
    return r;
  }
  cv::Mat rgb;
  cv::cvtColor(decoded, rgb, cv::COLOR_BGR2RGB);
  r.image = Rgb_image(rgb.cols, rgb.rows);
  for (int y = 0; y < rgb.rows; ++y)
    std::copy(rgb.ptr<std::uint8_t>(y), rgb.ptr<std::uint8_t>(y) + 3 * rgb.cols,
              r.image.pixels.begin() + std::ptrdiff_t(3) * rgb.cols * y);
  return r;
}

Image_read_result read_image(const std::string& path, const Image_read_options& options) {
  Image_read_result r;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    r.status = Image_read_status::cannot_open;
    r.message = "cannot open image " + path;
    return r;
  }
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  if (in.bad()) {
    r.status = Image_read_status::cannot_open;
    r.message = "cannot read image " + path;
    return r;
  }
  r = decode_image(bytes, options);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace tessera

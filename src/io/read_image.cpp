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

// PNG keeps its size at a fixed place (the IHDR chunk), so a huge image is refused before OpenCV
// allocates its pixels; other formats rely on OpenCV's own limit (2^30 pixels) and the check after
// decoding.
bool png_size(const std::vector<std::uint8_t>& b, std::size_t& w, std::size_t& h) {
  static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() < 24 || !std::equal(signature, signature + 8, b.begin()))
    return false;
  auto be32 = [&](std::size_t i) {
    return (std::size_t(b[i]) << 24) | (std::size_t(b[i + 1]) << 16) |
           (std::size_t(b[i + 2]) << 8) | std::size_t(b[i + 3]);
  };
  w = be32(16), h = be32(20);
  return true;
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
  if (png_size(bytes, w, h) &&
      (w == 0 || h == 0 || w > options.max_pixels / std::max<std::size_t>(h, 1))) {
    r.status = w == 0 || h == 0 ? Image_read_status::cannot_decode : Image_read_status::too_large;
    r.message = "the PNG header gives a size of " + std::to_string(w) + " x " + std::to_string(h) +
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

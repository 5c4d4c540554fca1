#include "doorplate_localization/maps/map_image.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/maps/map_io.h"

namespace doorplate_localization {
namespace {

constexpr long kMaxSideCells = 1L << 16;  // 65536 cells a side: 3.3 km at 5 cm, far beyond any building

// Reads the header tokens and ASCII pixels of a PGM: numbers separated by whitespace, `#` comments to
// the end of the line.
class PgmTokens {
 public:
  PgmTokens(const std::string& bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  size_t pos() const { return pos_; }
  void set_pos(size_t pos) { pos_ = pos; }

  void SkipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      const unsigned char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else if (std::isspace(c)) {
        ++pos_;
      } else {
        break;
      }
    }
  }

  // The next unsigned decimal number; false at the end of the data. Throws on anything else.
  bool Next(const std::string& field, long* value) {
    SkipSpaceAndComments();
    if (pos_ >= bytes_.size()) return false;
    long v = 0;
    size_t digits = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
      v = v * 10 + (bytes_[pos_] - '0');
      ++pos_;
      if (++digits > 9) throw MapFileError(source_ + ": " + field + ": number too large");
    }
    if (digits == 0) {
      throw MapFileError(source_ + ": " + field + ": expected a number, got '" + bytes_.substr(pos_, 1) + "'");
    }
    *value = v;
    return true;
  }

 private:
  const std::string& bytes_;
  const std::string& source_;
  size_t pos_ = 0;
};

std::uint8_t Rescale(long value, long maxval) {
  return static_cast<std::uint8_t>((value * 255 + maxval / 2) / maxval);
}

// An 8-bit picture decoded by OpenCV (BGR, BGRA, grey or grey + alpha).
MapImage FromOpenCv(const cv::Mat& mat, const std::string& path) {
  if (mat.depth() != CV_8U) throw MapFileError(path + ": only 8-bit images are supported");
  MapImage image;
  image.width = mat.cols;
  image.height = mat.rows;
  const int channels = mat.channels();
  const bool has_alpha = channels == 2 || channels == 4;
  const int colour_channels = has_alpha ? channels - 1 : channels;
  image.gray.resize(static_cast<size_t>(mat.cols) * mat.rows);
  if (has_alpha) image.alpha.resize(image.gray.size());
  for (int r = 0; r < mat.rows; ++r) {
    const std::uint8_t* row = mat.ptr<std::uint8_t>(r);
    for (int c = 0; c < mat.cols; ++c) {
      const std::uint8_t* px = row + static_cast<size_t>(c) * channels;
      int sum = 0;
      for (int k = 0; k < colour_channels; ++k) sum += px[k];
      const size_t i = static_cast<size_t>(r) * mat.cols + c;
      image.gray[i] = static_cast<std::uint8_t>(sum / colour_channels);
      if (has_alpha) image.alpha[i] = px[colour_channels];
    }
  }
  return image;
}

std::uint32_t BigEndian32(const std::string& bytes, size_t at) {
  std::uint32_t v = 0;
  for (size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

// The picture's size as its header states it (PNM: width and height tokens; PNG: the IHDR chunk), checked
// against limits::kMaxMapCells before the file is read whole: a 20000 x 20000 map must not cost 400 MB
// before it is refused. Headers it cannot read are left to the decoders, which report them. Rewinds `in`.
void CheckImageSizeInHeader(std::ifstream& in, const std::string& path) {
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  in.clear();
  in.seekg(0);
  long width = 0, height = 0;
  if (head.size() >= 2 && head[0] == 'P' && std::isdigit(static_cast<unsigned char>(head[1]))) {
    PgmTokens tokens(head, path);
    tokens.set_pos(2);
    try {
      if (!tokens.Next("header: width", &width) || !tokens.Next("header: height", &height)) return;
    } catch (const MapFileError&) {
      return;  // ParsePgm names the problem with the whole file
    }
  } else if (head.size() >= 24 && head.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 && head.compare(12, 4, "IHDR") == 0) {
    width = static_cast<long>(BigEndian32(head, 16));
    height = static_cast<long>(BigEndian32(head, 20));
  } else {
    return;
  }
  const std::string too_big = limits::CheckMapCells(width, height);
  if (!too_big.empty()) throw MapFileError(path + ": header: size " + too_big);
}

}  // namespace

MapImage ParsePgm(const std::string& bytes, const std::string& source) {
  const std::string magic = bytes.substr(0, 2);
  if (magic != "P5" && magic != "P2") {
    throw MapFileError(source + ": not an 8-bit grey PGM image (bad magic '" + magic +
                       "', expected 'P5' or 'P2')");
  }
  PgmTokens tokens(bytes, source);
  tokens.set_pos(2);
  long width = 0, height = 0, maxval = 0;
  if (!tokens.Next("header: width", &width) || !tokens.Next("header: height", &height) ||
      !tokens.Next("header: maxval", &maxval)) {
    throw MapFileError(source + ": header: truncated (needs width, height and maxval)");
  }
  if (width <= 0 || height <= 0 || width > kMaxSideCells || height > kMaxSideCells) {
    throw MapFileError(source + ": header: size " + std::to_string(width) + " x " + std::to_string(height) +
                       " must be 1.." + std::to_string(kMaxSideCells) + " a side");
  }
  const std::string too_big = limits::CheckMapCells(width, height);
  if (!too_big.empty()) throw MapFileError(source + ": header: size " + too_big);
  if (maxval < 1 || maxval > 255) {
    throw MapFileError(source + ": header: maxval " + std::to_string(maxval) +
                       ": only 8-bit PGM (maxval 1..255) is supported");
  }
  MapImage image;
  image.width = static_cast<int>(width);
  image.height = static_cast<int>(height);
  const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
  // Check that the data can hold `count` pixels before allocating them: a 20-byte header claiming
  // 65536 x 65536 must not cost 4 GB (found by fuzz/map_image_fuzz).
  const size_t start = tokens.pos() + 1;  // P5: exactly one whitespace byte after maxval
  const size_t available = bytes.size() > start ? bytes.size() - start : 0;
  if (magic == "P5" && available < count) {
    throw MapFileError(source + ": pixel data: truncated, expected " + std::to_string(count) +
                       " bytes after the header, got " + std::to_string(available));
  }
  if (magic == "P2" && available < count) {  // P2: at least a digit per value
    throw MapFileError(source + ": pixel data: truncated, expected " + std::to_string(count) +
                       " values, got at most " + std::to_string((available + 1) / 2));
  }
  image.gray.resize(count);
  if (magic == "P5") {
    for (size_t i = 0; i < count; ++i) {
      const long v = static_cast<unsigned char>(bytes[start + i]);
      if (v > maxval) {
        throw MapFileError(source + ": pixel data: value " + std::to_string(v) + " at byte " +
                           std::to_string(i) + " exceeds maxval " + std::to_string(maxval));
      }
      image.gray[i] = Rescale(v, maxval);
    }
    return image;
  }
  for (size_t i = 0; i < count; ++i) {
    long v = 0;
    if (!tokens.Next("pixel data", &v)) {
      throw MapFileError(source + ": pixel data: truncated, expected " + std::to_string(count) +
                         " values, got " + std::to_string(i));
    }
    if (v > maxval) {
      throw MapFileError(source + ": pixel data: value " + std::to_string(v) + " at row " +
                         std::to_string(i / width) + ", column " + std::to_string(i % width) +
                         " exceeds maxval " + std::to_string(maxval));
    }
    image.gray[i] = Rescale(v, maxval);
  }
  return image;
}

MapImage ReadMapImage(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MapFileError(path + ": cannot open the map image");
  CheckImageSizeInHeader(in, path);  // before the file (and its pixels) are read whole
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  if (bytes.size() >= 2 && bytes[0] == 'P' && std::isdigit(static_cast<unsigned char>(bytes[1]))) {
    return ParsePgm(bytes, path);  // any PNM: P5/P2 parsed, the others rejected with their magic
  }
  cv::Mat decoded;
  if (!bytes.empty()) {
    const cv::Mat raw(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
    decoded = cv::imdecode(raw, cv::IMREAD_UNCHANGED);
  }
  if (decoded.empty()) {
    std::string magic;
    for (char c : bytes.substr(0, 4)) magic += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    throw MapFileError(path + ": not a PGM or PNG image (bad magic '" + magic + "')");
  }
  return FromOpenCv(decoded, path);
}

std::string EncodePgm(const MapImage& image) {
  std::string out = "P5\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  out.append(image.gray.begin(), image.gray.end());
  return out;
}

}  // namespace doorplate_localization

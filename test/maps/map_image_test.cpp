#include "doorplate_localization/maps/map_image.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/maps/map_io.h"
#include "map_test_util.h"

namespace doorplate_localization {
namespace {

using test::Contains;
using test::ErrorOf;

std::string Binary(const std::string& header, std::initializer_list<int> pixels) {
  std::string bytes = header;
  for (int p : pixels) bytes.push_back(static_cast<char>(p));
  return bytes;
}

TEST(ParsePgm, ReadsBinaryPgmWithCommentsInTheHeader) {
  const MapImage image = ParsePgm(Binary("P5\n# made by hand\n3 2\n# max\n255\n", {0, 1, 2, 253, 254, 255}), "x");
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(image.gray, (std::vector<std::uint8_t>{0, 1, 2, 253, 254, 255}));
  EXPECT_TRUE(image.alpha.empty());
}

TEST(ParsePgm, ReadsAsciiPgmAndRescalesASmallMaxval) {
  const MapImage image = ParsePgm("P2 2 2 15\n0 15\n# comment between rows\n5 10\n", "x");
  EXPECT_EQ(image.gray, (std::vector<std::uint8_t>{0, 255, 85, 170}));
}

TEST(ParsePgm, KeepsBinaryDataThatLooksLikeWhitespaceOrComments) {
  const MapImage image = ParsePgm(Binary("P5 2 1 255\n", {'#', '\n'}), "x");
  EXPECT_EQ(image.gray, (std::vector<std::uint8_t>{'#', '\n'}));
}

TEST(ParsePgm, RejectsOtherNetpbmKindsNamingTheMagic) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P3 1 1 255 0 0 0", "maps/c.pgm"); });
  EXPECT_TRUE(Contains(error, "maps/c.pgm: not an 8-bit grey PGM image (bad magic 'P3'")) << error;
}

TEST(ParsePgm, RejectsTruncatedBinaryData) {
  const std::string error =
      ErrorOf<MapFileError>([] { ParsePgm(Binary("P5\n3 2\n255\n", {1, 2, 3, 4}), "maps/t.pgm"); });
  EXPECT_TRUE(Contains(error, "maps/t.pgm: pixel data: truncated, expected 6 bytes after the header, got 4"))
      << error;
}

TEST(ParsePgm, RejectsTruncatedAsciiData) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P2 2 2 255 1 2 3", "a.pgm"); });
  EXPECT_TRUE(Contains(error, "a.pgm: pixel data: truncated, expected 4 values, got 3")) << error;
}

// Found by fuzz/map_image_fuzz (fuzz/corpus/map_image/regression_huge_header): a 20-byte file claiming
// 65536 x 65536 pixels made the parser allocate 4 GB before noticing the data was missing. The size is now
// checked against the bytes present before any allocation.
// (65536 x 65536 is now refused by the cell limit first: the largest size within it shows the byte check.)
TEST(ParsePgm, RejectsAHugeHeaderWithoutDataBeforeAllocatingItsPixels) {
  const std::string binary = ErrorOf<MapFileError>([] { ParsePgm("P5 10000 10000 255 ", "big.pgm"); });
  EXPECT_TRUE(Contains(binary, "big.pgm: pixel data: truncated, expected 100000000 bytes after the header, got 0"))
      << binary;
  const std::string ascii = ErrorOf<MapFileError>([] { ParsePgm("P2 10000 10000 255 7", "big.pgm"); });
  EXPECT_TRUE(Contains(ascii, "big.pgm: pixel data: truncated, expected 100000000 values, got at most 1"))
      << ascii;
}

// Issue 18: a 20000 x 20000 map (4e8 cells, 400 MB of pixels that ARE present) is refused by its header
// against limits::kMaxMapCells, naming the source and the limit.
TEST(ParsePgm, RejectsMoreCellsThanTheLimitNamingIt) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P5 20000 20000 255 ", "huge.pgm"); });
  EXPECT_TRUE(Contains(error, "huge.pgm: header: size 20000 x 20000 = 4e+08 cells, more than the limit of "
                              "100000000 (limits::kMaxMapCells)"))
      << error;
  const std::string side = ErrorOf<MapFileError>([] { ParsePgm("P5 65536 65536 255 ", "huge.pgm"); });
  EXPECT_TRUE(Contains(side, "limits::kMaxMapCells")) << side;
}

// ReadMapImage checks the size a PGM or PNG header states before reading the file whole: a PNG claiming
// 20000 x 20000 (its IHDR chunk, no pixel data) is refused naming the file and the limit, not decoded.
TEST(ReadMapImage, RefusesAPngOrPgmHeaderAboveTheCellLimitBeforeReadingThePixels) {
  test::TempDir dir;
  std::string png("\x89PNG\r\n\x1a\n", 8);
  png += std::string("\0\0\0\x0d", 4) + "IHDR";
  png += std::string("\0\0\x4e\x20\0\0\x4e\x20", 8);  // 20000 x 20000, big-endian
  png += std::string("\x08\0\0\0\0", 5) + std::string(4, '\0');  // 8-bit grey, CRC (not checked)
  const std::string png_path = dir.Write("huge.png", png);
  const std::string error = ErrorOf<MapFileError>([&] { ReadMapImage(png_path); });
  EXPECT_TRUE(Contains(error, png_path + ": header: size 20000 x 20000 = 4e+08 cells")) << error;
  const std::string pgm_path = dir.Write("huge.pgm", "P5\n# a comment\n20000 20000\n255\n0123");
  const std::string pgm_error = ErrorOf<MapFileError>([&] { ReadMapImage(pgm_path); });
  EXPECT_TRUE(Contains(pgm_error, pgm_path + ": header: size 20000 x 20000")) << pgm_error;
  // Within the limit, the same truncated file is still refused, by the pixel check.
  const std::string small = dir.Write("small.pgm", "P5\n200 200\n255\n0123");
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([&] { ReadMapImage(small); }), "pixel data: truncated"));
}

TEST(ParsePgm, RejectsTruncatedHeader) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P5 4 ", "h.pgm"); });
  EXPECT_TRUE(Contains(error, "h.pgm: header: truncated")) << error;
}

TEST(ParsePgm, RejectsSixteenBitImages) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P2 1 1 65535 7", "w.pgm"); });
  EXPECT_TRUE(Contains(error, "w.pgm: header: maxval 65535: only 8-bit PGM")) << error;
}

TEST(ParsePgm, RejectsZeroSizeAndGarbageInTheHeader) {
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([] { ParsePgm("P5 0 3 255\n", "z.pgm"); }), "z.pgm: header: size 0 x 3"));
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([] { ParsePgm("P5 2 x 255\n", "g.pgm"); }),
                       "g.pgm: header: height: expected a number, got 'x'"));
}

TEST(ParsePgm, RejectsAsciiValuesAboveMaxval) {
  const std::string error = ErrorOf<MapFileError>([] { ParsePgm("P2 2 1 100 5 101", "v.pgm"); });
  EXPECT_TRUE(Contains(error, "v.pgm: pixel data: value 101 at row 0, column 1 exceeds maxval 100")) << error;
}

TEST(EncodePgm, ParsesBackToTheSamePixels) {
  MapImage image;
  image.width = 3;
  image.height = 2;
  image.gray = {0, 10, 205, 254, 255, 32};
  const MapImage back = ParsePgm(EncodePgm(image), "mem");
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.gray, image.gray);
}

TEST(ReadMapImage, ReadsPngAveragingTheColourChannelsAndKeepingAlpha) {
  test::TempDir dir;
  cv::Mat bgra(1, 2, CV_8UC4);
  bgra.at<cv::Vec4b>(0, 0) = {30, 60, 90, 255};
  bgra.at<cv::Vec4b>(0, 1) = {255, 255, 255, 0};
  ASSERT_TRUE(cv::imwrite(dir.Path("m.png"), bgra));
  const MapImage image = ReadMapImage(dir.Path("m.png"));
  EXPECT_EQ(image.gray, (std::vector<std::uint8_t>{60, 255}));
  EXPECT_EQ(image.alpha, (std::vector<std::uint8_t>{255, 0}));
}

TEST(ReadMapImage, RejectsFilesThatAreNoImageNamingThem) {
  test::TempDir dir;
  const std::string path = dir.Write("m.jpgx", "GIF8 not really");
  const std::string error = ErrorOf<MapFileError>([&] { ReadMapImage(path); });
  EXPECT_TRUE(Contains(error, path + ": not a PGM or PNG image (bad magic 'GIF8')")) << error;
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([&] { ReadMapImage(dir.Path("none.pgm")); }),
                       dir.Path("none.pgm") + ": cannot open"));
}

}  // namespace
}  // namespace doorplate_localization

#include "bag_structure.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <bzlib.h>
#include <roslz4/lz4s.h>
#include <rosbag/bag.h>
#include <std_msgs/String.h>

namespace doorplate_localization {
namespace {

std::string TempBag(const std::string& name) { return ::testing::TempDir() + "/bag_structure_" + name + ".bag"; }

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteAll(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::string GoodBag(const std::string& name, rosbag::compression::CompressionType compression) {
  const std::string path = TempBag(name);
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setCompression(compression);
  std_msgs::String text;
  for (int i = 0; i < 3; ++i) {
    text.data = "plate " + std::to_string(i);
    bag.write("/text", ros::Time(1.0 + i), text);
  }
  bag.close();
  return path;
}

std::uint32_t U32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

// The offset of the first top-level record whose header has the field op=<op>.
std::size_t RecordWithOp(const std::string& bytes, char op) {
  for (std::size_t at = 13; at + 4 <= bytes.size();) {
    const std::uint32_t header_length = U32(bytes, at);
    if (bytes.substr(at + 4, header_length).find(std::string("op=") + op) != std::string::npos) return at;
    at += 8 + header_length + U32(bytes, at + 4 + header_length);
  }
  return std::string::npos;
}

TEST(CheckBagStructureTest, AcceptsBagsRosbagWritesAndLeavesOtherFilesToRosbag) {
  EXPECT_EQ(CheckBagStructure(GoodBag("none", rosbag::compression::Uncompressed)), "");
  EXPECT_EQ(CheckBagStructure(GoodBag("bz2", rosbag::compression::BZ2)), "");
  EXPECT_EQ(CheckBagStructure(GoodBag("lz4", rosbag::compression::LZ4)), "");
  const std::string garbage = TempBag("garbage");
  WriteAll(garbage, "no bag at all\n");
  EXPECT_EQ(CheckBagStructure(garbage), "");
  EXPECT_EQ(CheckBagStructure(TempBag("missing")), "");
}

// The fuzzer's find: a connection record whose header length says 2.3 GB; rosbag allocated it.
TEST(CheckBagStructureTest, RefusesARecordLongerThanTheFileNamingItsOffset) {
  const std::string path = GoodBag("long_header", rosbag::compression::Uncompressed);
  std::string bytes = ReadAll(path);
  const std::size_t record = RecordWithOp(bytes, '\x07');  // a connection record
  ASSERT_NE(record, std::string::npos);
  const std::uint32_t huge = 2315255808u;
  std::memcpy(bytes.data() + record, &huge, 4);
  WriteAll(path, bytes);
  const std::string problem = CheckBagStructure(path);
  EXPECT_NE(problem.find("record at byte " + std::to_string(record) + ": header length 2315255808, but only"),
            std::string::npos) << problem;
}

// The fuzzer's second find: ros::Header::parse reads a field as long as its length says, past its header.
TEST(CheckBagStructureTest, RefusesAHeaderFieldRunningPastItsHeader) {
  const std::string path = GoodBag("long_field", rosbag::compression::Uncompressed);
  std::string bytes = ReadAll(path);
  const std::size_t record = RecordWithOp(bytes, '\x07');
  ASSERT_NE(record, std::string::npos);
  const std::uint32_t past_the_header = U32(bytes, record);  // the first field's length: its whole header
  std::memcpy(bytes.data() + record + 4, &past_the_header, 4);
  WriteAll(path, bytes);
  const std::string problem = CheckBagStructure(path);
  EXPECT_NE(problem.find("record at byte " + std::to_string(record) + ": a header field of " +
                         std::to_string(past_the_header) + " bytes overruns its header"),
            std::string::npos) << problem;
}

// The fuzzer's third find: rosbag's version line ends at the first newline, wherever that is ("#ROSBAG V2.0 "
// and more); the records start after it. Formats other than 2.0 are refused.
TEST(CheckBagStructureTest, WalksFromTheEndOfTheVersionLineAsRosbagReadsItAndRefusesOtherVersions) {
  const std::string path = GoodBag("version_line", rosbag::compression::Uncompressed);
  std::string bytes = ReadAll(path);
  bytes.insert(12, " and more");  // "#ROSBAG V2.0 and more\n"
  const std::size_t record = RecordWithOp(bytes.substr(9), '\x07') + 9;  // the walk from the shifted start
  const std::uint32_t huge = 2315255808u;
  std::memcpy(bytes.data() + record, &huge, 4);
  WriteAll(path, bytes);
  EXPECT_NE(CheckBagStructure(path).find("record at byte " + std::to_string(record) + ": header length 2315255808"),
            std::string::npos) << CheckBagStructure(path);
  WriteAll(path, "#ROSBAG V1.2\nold records");
  EXPECT_EQ(CheckBagStructure(path), "bag format version 1.2: only 2.0 (every bag since ROS C Turtle, 2010) is read");
}

// Adds `delta` (modulo 2^64: a negative one too) to every 8-byte position field `name` ("index_pos=",
// "chunk_pos=") of `bytes`, so the positions follow records that moved.
void MovePositions(std::string* bytes, const std::string& name, std::uint64_t delta) {
  for (std::size_t at = bytes->find(name); at != std::string::npos; at = bytes->find(name, at + 1)) {
    std::uint64_t position = 0;
    std::memcpy(&position, bytes->data() + at + name.size(), 8);
    position += delta;
    std::memcpy(bytes->data() + at + name.size(), &position, 8);
  }
}

// `bytes` (a bag) with `spaces` spaces before the version line's newline; the bag header's index position and
// the chunk infos' chunk positions moved with the records, so only the version line differs.
std::string WithSpacesInTheVersionLine(std::string bytes, std::uint64_t spaces) {
  MovePositions(&bytes, "index_pos=", spaces);
  MovePositions(&bytes, "chunk_pos=", spaces);
  return bytes.insert(12, std::string(spaces, ' '));
}

// CI's fuzzer find: rosbag reads the version line with fgets into 1024 bytes, so a line longer than 1023 bytes
// ends there for rosbag, and the next 4 bytes (spaces: 538976288) were read as a header length and allocated.
TEST(CheckBagStructureTest, StartsTheRecordsWhereRosbagStopsReadingALongVersionLine) {
  const std::string path = GoodBag("long_version_line", rosbag::compression::Uncompressed);
  const std::string bytes = ReadAll(path);
  WriteAll(path, WithSpacesInTheVersionLine(bytes, 1100));  // "#ROSBAG V2.0" and 1100 spaces, then its newline
  EXPECT_NE(CheckBagStructure(path).find("record at byte 1023: header length 538976288, but only"), std::string::npos)
      << CheckBagStructure(path);
  WriteAll(path, WithSpacesInTheVersionLine(bytes, 1010));  // 1023 bytes with the newline: rosbag reads it whole
  EXPECT_EQ(CheckBagStructure(path), "");
  rosbag::Bag bag;
  EXPECT_NO_THROW(bag.open(path, rosbag::bagmode::Read));
}

// A record header field's value (the bytes after "<name>=") in the header at `at` (its length first).
std::string FieldOf(const std::string& bytes, std::size_t at, const std::string& name) {
  const std::string header = bytes.substr(at + 4, U32(bytes, at));
  for (std::size_t f = 0; f + 4 <= header.size(); f += 4 + U32(header, f)) {
    const std::string field = header.substr(f + 4, U32(header, f));
    if (field.rfind(name + "=", 0) == 0) return field.substr(name.size() + 1);
  }
  return "";
}

// `bytes` (a bag of one compressed chunk) with that chunk's records changed by `change`, compressed again; the
// chunk's data length and the bag header's index position follow the new compressed length.
std::string WithChunkRecords(const std::string& bytes, const std::function<void(std::string*)>& change) {
  const std::size_t chunk = RecordWithOp(bytes, '\x05');
  const std::size_t length_at = chunk + 4 + U32(bytes, chunk);
  const std::string compression = FieldOf(bytes, chunk, "compression");
  std::string data = bytes.substr(length_at + 4, U32(bytes, length_at));
  std::uint32_t size = 0;
  std::memcpy(&size, FieldOf(bytes, chunk, "size").data(), 4);
  std::string records(size, '\0');
  std::string again(size + size / 50 + 1024, '\0');
  unsigned int records_size = size, again_size = static_cast<unsigned int>(again.size());
  if (compression == "bz2") {
    EXPECT_EQ(BZ2_bzBuffToBuffDecompress(records.data(), &records_size, data.data(), data.size(), 0, 0), BZ_OK);
    change(&records);
    EXPECT_EQ(BZ2_bzBuffToBuffCompress(again.data(), &again_size, records.data(), size, 9, 0, 30), BZ_OK);
  } else {
    EXPECT_EQ(roslz4_buffToBuffDecompress(data.data(), data.size(), records.data(), &records_size), ROSLZ4_OK);
    change(&records);
    EXPECT_EQ(roslz4_buffToBuffCompress(records.data(), size, again.data(), &again_size, 6), ROSLZ4_OK);
  }
  again.resize(again_size);
  std::string out =
      bytes.substr(0, length_at) + std::string(4, '\0') + again + bytes.substr(length_at + 4 + data.size());
  std::memcpy(out.data() + length_at, &again_size, 4);
  MovePositions(&out, "index_pos=", static_cast<std::uint64_t>(again.size()) - data.size());  // after the chunk
  return out;
}

// rosbag reads the records of a decompressed chunk from its buffer without checking their lengths: a message
// header length beyond the chunk would be read past the buffer. Checked in bz2 and lz4 chunks alike.
TEST(CheckBagStructureTest, WalksTheRecordsInsideCompressedChunks) {
  for (const auto compression : {rosbag::compression::BZ2, rosbag::compression::LZ4}) {
    const std::string path = GoodBag("compressed_records", compression);
    const std::string bytes = ReadAll(path);
    WriteAll(path, WithChunkRecords(bytes, [](std::string*) {}));  // recompressed unchanged: still a good bag
    EXPECT_EQ(CheckBagStructure(path), "");
    rosbag::Bag bag;
    EXPECT_NO_THROW(bag.open(path, rosbag::bagmode::Read));
    bag.close();
    WriteAll(path, WithChunkRecords(bytes, [](std::string* records) {
      const std::uint32_t huge = 1u << 30;
      std::memcpy(records->data(), &huge, 4);  // the chunk's first record: its header length
    }));
    const std::string chunk = std::to_string(RecordWithOp(bytes, '\x05'));
    const std::string expected = "chunk at byte " + chunk + ": record at byte 0: header length 1073741824, but only";
    EXPECT_NE(CheckBagStructure(path).find(expected), std::string::npos) << CheckBagStructure(path);
  }
}

TEST(CheckBagStructureTest, RefusesACompressedChunkWhoseDataDoesNotDecompressToItsSize) {
  const std::string path = GoodBag("bad_bz2", rosbag::compression::BZ2);
  std::string bytes = ReadAll(path);
  const std::size_t chunk = RecordWithOp(bytes, '\x05');
  const std::size_t data_at = chunk + 4 + U32(bytes, chunk) + 4;
  bytes[data_at + 20] = static_cast<char>(bytes[data_at + 20] ^ 0x5A);  // inside the bz2 stream
  WriteAll(path, bytes);
  const std::string expected = "record at byte " + std::to_string(chunk) + ": chunk: its bz2 data does not decompress";
  EXPECT_NE(CheckBagStructure(path).find(expected), std::string::npos) << CheckBagStructure(path);
}

// A fuzzing find (bag_reader, seeds 21-22 of 2026-12-06): rosbag reads as many index entries (and chunk info
// entries) as the record's count says, whatever its data length; a count that disagrees leaves it reading the
// next record from inside this one (a 2.3 GB "header" in readConnectionIndexRecord200).
TEST(CheckBagStructureTest, RefusesAnIndexOrChunkInfoCountThatDisagreesWithItsData) {
  for (const std::string& record : {std::string("index data"), std::string("chunk info")}) {
    const std::string path = GoodBag("count", rosbag::compression::Uncompressed);
    std::string bytes = ReadAll(path);
    const std::size_t at = RecordWithOp(bytes, record == "index data" ? '\x04' : '\x06');
    ASSERT_NE(at, std::string::npos);
    const std::string count_field = std::string("\x0a\x00\x00\x00", 4) + "count=";  // length 10
    const std::size_t count_field_at = bytes.find(count_field, at);
    ASSERT_LT(count_field_at, at + 4 + U32(bytes, at));
    const std::size_t count_at = count_field_at + count_field.size();
    std::uint32_t count = U32(bytes, count_at);
    count += 1;
    std::memcpy(bytes.data() + count_at, &count, 4);
    WriteAll(path, bytes);
    const std::string expected = "record at byte " + std::to_string(at) + ": " + record + ": count " +
                                 std::to_string(count) + " (";
    EXPECT_NE(CheckBagStructure(path).find(expected), std::string::npos) << CheckBagStructure(path);
  }
}

// rosbag reads a message at each index entry's offset in the chunk's buffer without checking what is there.
TEST(CheckBagStructureTest, RefusesAnIndexEntryThatIsNotWhereAMessageRecordStarts) {
  const std::string path = GoodBag("entry", rosbag::compression::Uncompressed);
  std::string bytes = ReadAll(path);
  const std::size_t index = RecordWithOp(bytes, '\x04');
  ASSERT_NE(index, std::string::npos);
  const std::size_t data_at = index + 4 + U32(bytes, index) + 4;
  const std::uint32_t inside_a_record = U32(bytes, data_at + 8) + 3;  // the first entry's offset, 3 bytes on
  std::memcpy(bytes.data() + data_at + 8, &inside_a_record, 4);
  WriteAll(path, bytes);
  EXPECT_NE(CheckBagStructure(path).find("index entry offset " + std::to_string(inside_a_record) +
                                         " is not the start of a message record in its chunk"),
            std::string::npos) << CheckBagStructure(path);
}

// rosbag reads an op field, like every numeric field, from the first bytes of a longer value: "op=\x05xy" is a chunk.
TEST(CheckBagStructureTest, ReadsFieldsAsRosbagDoesFromTheFirstBytesOfALongerValue) {
  const std::string path = GoodBag("long_op", rosbag::compression::Uncompressed);
  const std::string bytes = ReadAll(path);
  const std::size_t chunk = RecordWithOp(bytes, '\x05');
  ASSERT_NE(chunk, std::string::npos);
  // Rebuilt with "op=\x05" as "op=\x05xy" (2 bytes longer) and its first inner record's header length huge.
  const std::string op_field = std::string("\x04\x00\x00\x00op=\x05", 8);
  const std::size_t op_at = bytes.find(op_field, chunk);
  ASSERT_LT(op_at, chunk + 4 + U32(bytes, chunk));
  std::string changed = bytes.substr(0, op_at) + std::string("\x06\x00\x00\x00op=\x05xy", 10) +
                        bytes.substr(op_at + op_field.size());
  const std::uint32_t header_length = U32(bytes, chunk) + 2;
  std::memcpy(changed.data() + chunk, &header_length, 4);
  const std::size_t records_at = chunk + 4 + header_length + 4;
  const std::uint32_t huge = 1u << 30;
  std::memcpy(changed.data() + records_at, &huge, 4);
  WriteAll(path, changed);
  EXPECT_NE(CheckBagStructure(path).find("chunk at byte " + std::to_string(chunk) + ": record at byte 0: header length 1073741824"),
            std::string::npos) << CheckBagStructure(path);
}

TEST(CheckBagStructureTest, RefusesACompressedChunkClaimingMoreThanTheLimit) {
  const std::string path = GoodBag("big_chunk", rosbag::compression::BZ2);
  std::string bytes = ReadAll(path);
  const std::string size_field = std::string("\x09\x00\x00\x00size=", 9);
  const std::size_t at = bytes.find(size_field);
  ASSERT_NE(at, std::string::npos);
  const std::uint32_t huge = 0xF0000000u;
  std::memcpy(bytes.data() + at + size_field.size(), &huge, 4);
  WriteAll(path, bytes);
  const std::string problem = CheckBagStructure(path);
  EXPECT_NE(problem.find("chunk of 4026531840 bytes uncompressed, more than the limit of 268435456 (kMaxBagChunkBytes)"),
            std::string::npos) << problem;
}

}  // namespace
}  // namespace doorplate_localization

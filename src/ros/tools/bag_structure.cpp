#include "bag_structure.h"

#include <cstdio>
#include <cstring>
#include <functional>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <bzlib.h>
#include <roslz4/lz4s.h>

namespace doorplate_localization {
namespace {

constexpr std::size_t kBagVersionLineMaxBytes = 1023;  // rosbag's fgets buffer of 1024, less the NUL
constexpr char kOpMessageData = 0x02, kOpBagHeader = 0x03, kOpIndexData = 0x04, kOpChunk = 0x05, kOpChunkInfo = 0x06,
               kOpConnection = 0x07;

template <typename T>
T Read(const std::string& bytes, std::size_t at) {
  T value{};
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  return value;
}

// A record header's fields (name -> value bytes); "" or the problem.
std::string ParseFields(const std::string& header, std::map<std::string, std::string>* fields) {
  std::size_t at = 0;
  while (at < header.size()) {
    if (header.size() - at < 4) return "a header field's length is cut off";
    const std::uint32_t length = Read<std::uint32_t>(header, at);
    at += 4;
    if (length > header.size() - at) return "a header field of " + std::to_string(length) + " bytes overruns its header";
    const std::string field = header.substr(at, length);
    at += length;
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos) return "a header field without '='";
    (*fields)[field.substr(0, eq)] = field.substr(eq + 1);
  }
  return "";
}

// A compressed chunk's records as rosbag decompresses them (bz2: libbz2, lz4: roslz4; rosbag then reads
// their headers from the buffer without checking their lengths): the `size` bytes, or unset with `problem`
// set when the data does not decompress to exactly that many or the compression is none rosbag knows.
std::optional<std::string> Decompressed(const std::string& compression, std::string data, std::uint32_t size,
                                        std::string* problem) {
  std::string out(size, '\0');
  unsigned int out_size = size;
  int status = 0;
  if (compression == "bz2") {
    status = BZ2_bzBuffToBuffDecompress(out.data(), &out_size, data.data(), static_cast<unsigned int>(data.size()),
                                        /*small=*/0, /*verbosity=*/0);
    if (status != BZ_OK) *problem = "its bz2 data does not decompress (libbz2 error " + std::to_string(status) + ")";
  } else if (compression == "lz4") {
    status = roslz4_buffToBuffDecompress(data.data(), static_cast<unsigned int>(data.size()), out.data(), &out_size);
    if (status != ROSLZ4_OK) {
      *problem = "its lz4 data does not decompress (roslz4 error " + std::to_string(status) + ")";
    }
  } else {
    *problem = "compression '" + compression + "', not one rosbag reads (none, bz2, lz4)";
  }
  if (problem->empty() && out_size != size) {
    *problem = "its " + compression + " data decompresses to " + std::to_string(out_size) + " bytes, not its size " +
               std::to_string(size);
  }
  if (!problem->empty()) return std::nullopt;
  return out;
}

// A numeric field as rosbag reads it (Bag::readField): the first sizeof(T) bytes of a value at least that long
// (a longer value is accepted, its rest ignored); unset if missing or shorter (rosbag refuses the bag).
template <typename T>
std::optional<T> FieldAs(const std::map<std::string, std::string>& fields, const char* name) {
  const auto it = fields.find(name);
  if (it == fields.end() || it->second.size() < sizeof(T)) return std::nullopt;
  return Read<T>(it->second, 0);
}

struct Chunk {
  std::uint32_t size = 0;                  // uncompressed bytes
  std::set<std::uint64_t> message_starts;  // offsets of its message data records
};

// Bytes [from, from + n) of what is walked (the file, or a chunk's records, decompressed); n is within its size.
using ReadBytes = std::function<std::string(std::uint64_t from, std::uint32_t n)>;

// What the walk of one sequence of records found (top level: the file; inside: one chunk's records).
struct Walk {
  std::uint64_t index_pos = 0;
  std::set<std::uint64_t> record_starts, chunk_positions, message_starts;
  std::vector<Chunk> chunks;
};

// Walks the records in [begin, end) of `read`; "" or the first problem. `where` names the place of offsets.
std::string WalkRecords(const ReadBytes& read, std::uint64_t begin, std::uint64_t end, const std::string& where,
                        Walk* walk) {
  std::ostringstream problem;
  for (std::uint64_t at = begin; at < end;) {
    walk->record_starts.insert(at);
    const std::uint64_t left = end - at;
    problem << where << "record at byte " << at << ": ";
    if (left < 4) return problem.str() + "cut off";
    const auto header_length = Read<std::uint32_t>(read(at, 4), 0);
    if (header_length > left - 4) {
      problem << "header length " << header_length << ", but only " << left - 4 << " bytes follow";
      return problem.str();
    }
    std::map<std::string, std::string> fields;
    std::string fields_problem = ParseFields(read(at + 4, header_length), &fields);
    if (!fields_problem.empty()) return problem.str() + fields_problem;
    const std::uint64_t data_at = at + 4 + header_length;
    if (end - data_at < 4) return problem.str() + "data length cut off";
    const auto data_length = Read<std::uint32_t>(read(data_at, 4), 0);
    if (data_length > end - data_at - 4) {
      problem << "data length " << data_length << ", but only " << end - data_at - 4 << " bytes follow";
      return problem.str();
    }
    // rosbag takes the first byte of an op field of any length (readField<uint8_t>).
    const std::string& op = fields["op"];
    const char code = op.empty() ? 0 : op[0];
    if (code == kOpMessageData) walk->message_starts.insert(at);
    if (code == kOpBagHeader) {
      walk->index_pos = FieldAs<std::uint64_t>(fields, "index_pos").value_or(~0ull);
    } else if (code == kOpConnection) {  // its data is the connection header, fields as well
      std::map<std::string, std::string> connection;
      fields_problem = ParseFields(read(data_at + 4, data_length), &connection);
      if (!fields_problem.empty()) return problem.str() + "connection header: " + fields_problem;
    } else if (code == kOpChunk) {
      const std::uint64_t size = FieldAs<std::uint32_t>(fields, "size").value_or(~0u);
      const bool compressed = fields["compression"] != "none";
      if (size > kMaxBagChunkBytes || (!compressed && size > data_length)) {
        problem << "chunk of " << size << " bytes uncompressed, more than "
                << (compressed ? "the limit of " + std::to_string(kMaxBagChunkBytes) + " (kMaxBagChunkBytes)"
                               : "its " + std::to_string(data_length) + " bytes of data");
        return problem.str();
      }
      walk->chunks.push_back({static_cast<std::uint32_t>(size), {}});
      // Its records (connections, messages): rosbag parses their headers too.
      std::string records = read(data_at + 4, compressed ? data_length : static_cast<std::uint32_t>(size));
      if (compressed) {
        std::string decompress_problem;
        std::optional<std::string> decompressed =
            Decompressed(fields["compression"], std::move(records), static_cast<std::uint32_t>(size), &decompress_problem);
        if (!decompressed) return problem.str() + "chunk: " + decompress_problem;
        records = std::move(*decompressed);
      }
      Walk inside;
      const std::string inner = WalkRecords([&records](std::uint64_t from, std::uint32_t n) { return records.substr(from, n); },
                                            0, records.size(), where + "chunk at byte " + std::to_string(at) + ": ", &inside);
      if (!inner.empty()) return inner;
      walk->chunks.back().message_starts = std::move(inside.message_starts);
    } else if (code == kOpChunkInfo || code == kOpIndexData) {
      // rosbag reads `count` entries (chunk info: connection id and count, 8 bytes; index data, version 1: time
      // and offset, 12 bytes) whatever the data length says: a count that disagrees with it leaves rosbag reading
      // the next record from the wrong place (a fuzzing find: a 2.3 GB "header" in readConnectionIndexRecord200).
      const std::uint64_t count = FieldAs<std::uint32_t>(fields, "count").value_or(0);
      const std::uint64_t entry_bytes = code == kOpChunkInfo ? 8 : 12;
      if (count * entry_bytes != data_length) {
        problem << (code == kOpChunkInfo ? "chunk info" : "index data") << ": count " << count << " (" << count
                << " × " << entry_bytes << " bytes), but its data has " << data_length << " bytes";
        return problem.str();
      }
      if (code == kOpChunkInfo) {
        walk->chunk_positions.insert(FieldAs<std::uint64_t>(fields, "chunk_pos").value_or(~0ull));
      } else if (!walk->chunks.empty()) {
        // rosbag reads a message at each entry's offset in the chunk before it (its records read from a buffer,
        // their lengths unchecked): each must be where a message data record starts.
        const Chunk& chunk = walk->chunks.back();
        const std::string data = read(data_at + 4, data_length);
        for (std::size_t e = 0; e + 12 <= data.size(); e += 12) {
          const std::uint32_t offset = Read<std::uint32_t>(data, e + 8);
          if (!chunk.message_starts.count(offset)) {
            problem << "index entry offset " << offset << " is not the start of a message record in its chunk of "
                    << chunk.size << " bytes";
            return problem.str();
          }
        }
      }
    }
    problem.str("");
    at = data_at + 4 + data_length;
  }
  return "";
}

}  // namespace

std::string CheckBagStructure(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";  // rosbag names a file it cannot open
  in.seekg(0, std::ios::end);
  const std::uint64_t file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  // The version line exactly as rosbag reads it (ChunkedFile::getline): fgets into 1024 bytes, so at most 1023
  // bytes up to and including the first newline; the records start where fgets stopped reading, which is not
  // after the newline when the line is longer (CI's fuzzer find: 4 spaces of a long line became a header length of
  // 538 976 288 bytes).
  std::string version_line(kBagVersionLineMaxBytes, '\0');
  in.read(version_line.data(), kBagVersionLineMaxBytes);
  version_line.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t newline = version_line.find('\n');
  if (newline != std::string::npos) version_line.resize(newline + 1);
  const std::uint64_t records_at = version_line.size();
  char name[100];
  int major = 0, minor = 0;  // sscanf stops at a NUL byte, as rosbag's does
  if (std::sscanf(version_line.c_str(), "#ROS%99s V%d.%d", name, &major, &minor) != 3) return "";  // rosbag says so
  if (major != 2 || minor != 0) {
    return "bag format version " + std::to_string(major) + "." + std::to_string(minor) +
           ": only 2.0 (every bag since ROS C Turtle, 2010) is read";
  }
  const ReadBytes read = [&in](std::uint64_t from, std::uint32_t n) {
    std::string bytes(n, '\0');
    in.clear();
    in.seekg(static_cast<std::streamoff>(from));
    in.read(bytes.data(), n);
    return bytes;
  };
  Walk walk;
  const std::string problem = WalkRecords(read, records_at, file_size, "", &walk);
  if (!problem.empty()) return problem;
  if (walk.index_pos != 0 && walk.index_pos != file_size && !walk.record_starts.count(walk.index_pos)) {
    return "bag header: index_pos " + std::to_string(walk.index_pos) + " is not the start of a record";
  }
  for (const std::uint64_t pos : walk.chunk_positions) {
    if (!walk.record_starts.count(pos)) return "chunk info: chunk_pos " + std::to_string(pos) + " is not the start of a record";
  }
  return "";
}

}  // namespace doorplate_localization

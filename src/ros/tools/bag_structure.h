// A check of a rosbag's record structure (format 2.0, http://wiki.ros.org/Bags/Format/2.0) before rosbag reads
// it. rosbag's reader allocates what a length field says before it checks that the file holds that much, and
// ros::Header::parse (roscpp's, which rosbag uses for every record header) reads a field as long as its length
// says, past the end of the header (fuzz/bag_reader_fuzz.cpp found both: an 18 kB bag whose connection record
// claims a 2.3 GB header; a header field running past its record). Walks the file's records reading their
// headers, the connection headers, the small index records and the records inside every chunk (compressed
// ones decompressed as rosbag does: bz2, lz4; rosbag reads the records of a decompressed chunk from its
// buffer without checking their lengths). Reading a bag so costs one extra decompression of its chunks.
#pragma once

#include <cstdint>
#include <string>

namespace doorplate_localization {

// The largest uncompressed chunk accepted: rosbag record writes 768 kB chunks by default (--chunksize).
inline constexpr std::uint32_t kMaxBagChunkBytes = 256u << 20;

// "" if every record of the bag at `path` fits in the file or chunk (header and data lengths, every header
// field within its header, a connection record's data fields within its data), every
// chunk's uncompressed size is within kMaxBagChunkBytes (and within its data when uncompressed; a compressed
// chunk's data decompresses to exactly that size), every record inside a chunk fits in it, the bag
// header's index position and every chunk info's chunk position are record starts, every index data and chunk
// info record's `count` matches its data length, and every index entry's offset is where a message record of its
// chunk starts (fields read as rosbag reads them: the first bytes of a longer value); else the first problem,
// e.g. "record at byte 4321: header length 2315255808, but only 13880 bytes follow". The records start where rosbag's reading of the version line stops (after
// the first newline, or after 1023 bytes when the line is longer; "#ROS<name> V<major>.<minor>"); a version
// other than 2.0 is refused (rosbag's readers of the 1.x formats are not checked here); a file without a
// version line is left to rosbag ("" returned: it says so).
std::string CheckBagStructure(const std::string& path);

}  // namespace doorplate_localization

// The MRPT rawlog reader of the offline tools (doorplate_map_rawlog, doorplate_odometry_fit): MRPT's own
// CRawlog, with its failures turned into one error that names the file (issue 18). On a corrupt file MRPT
// prints its exception with a call stack to stderr and keeps what it read so far; on a missing file it
// throws one with a call stack in what(). Neither reaches the user: the stream is captured, its innermost
// message kept. MRPT's reader also crashes (SIGSEGV) on some malformed files: each file is read first in a
// child process (fork), so a crash is an error here too; a good rawlog is read twice. ROS-free; links
// mrpt::obs.
#pragma once

#include <stdexcept>
#include <string>

#include <mrpt/obs/CRawlog.h>

namespace doorplate_localization::tools {

// A rawlog that cannot be used; what() names the file: "x.rawlog: not an MRPT rawlog MRPT can read: entry 0:
// Expecting 0x00 00 00 while parsing old streaming header (...)".
class RawlogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the child process that reads a rawlog first may use (MRPT's reader took 4.4 GB and more than a
// minute on an 875-byte file found by fuzzing, and 2.7 GB on a 4 KB one). 0: from the file's size, generous
// for real rawlogs: 60 s + 1 s per MB of CPU, 2 GB + 200 bytes per byte of address space (not set in
// AddressSanitizer builds, whose shadow memory needs terabytes of it).
struct RawlogReadLimits {
  double cpu_s = 0.0;
  double memory_bytes = 0.0;
};

// Loads the whole of `path` into `rawlog` (cleared first). Throws RawlogError if the file is missing or
// unreadable, if MRPT's reader crashes on it (in the child: "MRPT's reader crashed on it (Segmentation
// fault)", "... ran out of its CPU time limit of 61 s", "... entry 0: std::bad_alloc"), if MRPT fails on any entry (a truncated or corrupt file is refused, not read in part), or if it
// holds no entry.
void LoadRawlog(const std::string& path, mrpt::obs::CRawlog* rawlog, const RawlogReadLimits& limits = {});

// The innermost "Message:" of an MRPT exception text (mrpt::exception_to_str: nested "==== MRPT exception
// ====" blocks with Message, Location and a call stack), trimmed; without one, the first line that is not a
// "==== ... ====" banner ("==== non-MRPT exception ====\nstd::bad_alloc": "std::bad_alloc").
std::string MrptMessage(const std::string& text);

}  // namespace doorplate_localization::tools

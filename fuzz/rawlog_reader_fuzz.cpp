// libFuzzer target: the MRPT rawlog reader of doorplate_map_rawlog and doorplate_odometry_fit
// (src/tools/rawlog_reader.h: MRPT's CRawlog behind LoadRawlog). The input is the file. Any file must load
// or throw RawlogError; what loads is walked as the tools walk it (action-observation pairs, every
// observation's type). MRPT itself is not instrumented for coverage: this finds crashes, hangs and huge
// allocations of MRPT's reader, which LoadRawlog must turn into errors (it reads each file first in a child
// process, here with 2 s of CPU; scripts/fuzz.sh caps the child's allocations through ASAN_OPTIONS).
#include <cstddef>
#include <cstdint>
#include <string>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "fuzz_temp_dir.h"
#include "rawlog_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  const std::string path = fuzz::WriteTempFile("fuzz.rawlog", reinterpret_cast<const char*>(data), size);
  mrpt::obs::CRawlog rawlog;
  try {
    tools::LoadRawlog(path, &rawlog, {2.0, 0.0});  // 2 s of CPU for the child that reads it first
  } catch (const tools::RawlogError&) {
    return 0;  // the documented reaction to bad input
  }
  mrpt::obs::CActionCollection::Ptr actions;
  mrpt::obs::CSensoryFrame::Ptr frame;
  std::size_t entry = 0;
  while (entry < rawlog.size()) {
    if (rawlog.getType(entry) == mrpt::obs::CRawlog::etObservation) {
      const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(rawlog.getAsObservation(entry++));
      if (scan && scan->getScanSize() > 0) (void)scan->getScanRange(scan->getScanSize() - 1);
      continue;
    }
    if (!rawlog.getActionObservationPair(actions, frame, entry)) break;
  }
  return 0;
}

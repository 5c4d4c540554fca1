// A private temporary folder for fuzz targets whose parser only reads files (map YAML + image): created
// once per process under $TMPDIR (default /tmp), removed at exit.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace doorplate_localization::fuzz {

inline const std::string& TempDir() {
  // A heap string that is never freed, so the exit handler below can still read it (a static std::string
  // could be destroyed before the handler runs).
  static const std::string* const dir = [] {
    const char* base = std::getenv("TMPDIR");
    auto* path = new std::string(std::string(base && *base ? base : "/tmp") + "/doorplate_fuzz.XXXXXX");
    if (::mkdtemp(path->data()) == nullptr) std::abort();
    std::atexit([] { std::error_code ignored; std::filesystem::remove_all(TempDir(), ignored); });
    return path;
  }();
  return *dir;
}

// Writes `bytes` to `<TempDir()>/<name>` (plain write: the fuzz input, not a map we keep) and returns the path.
inline std::string WriteTempFile(const std::string& name, const char* bytes, size_t size) {
  const std::string path = TempDir() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes, static_cast<std::streamsize>(size));
  if (!out) std::abort();
  return path;
}

}  // namespace doorplate_localization::fuzz

#pragma once
// The readers take a path: each fuzz input is written to one file per process first.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace bpm::fuzz {

inline std::string write_input(const std::uint8_t* data, std::size_t size, const char* extension) {
  const std::string path = "/tmp/bpmkit_fuzz_" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                static_cast<std::streamsize>(size));
  return path;
}

}  // namespace bpm::fuzz

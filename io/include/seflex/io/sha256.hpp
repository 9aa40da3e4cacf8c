#pragma once
// SHA-256 (FIPS 180-4) for file integrity (superelement files) and source-model hashes, computed by
// nettle (Debian's nettle-dev; io/src/sha256.cpp), which uses the x86 SHA extensions where the CPU
// has them.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace seflex::io {

class Sha256 {
 public:
  Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(const void* data, std::size_t size);
  void update(std::string_view s) { update(s.data(), s.size()); }
  std::array<std::uint8_t, 32> digest();  ///< finishes the hash; the object must not be updated afterwards
  std::string hex_digest();               ///< lowercase hex of digest()

 private:
  alignas(8) unsigned char state_[128];  ///< nettle's struct sha256_ctx (size checked in sha256.cpp)
};

/// Hex SHA-256 of a byte string.
std::string sha256_hex(std::string_view data);

/// Hex SHA-256 of a file's bytes; throws InputError if it cannot be read.
std::string sha256_file_hex(const std::filesystem::path& path);

/// Adds a file's bytes to h; throws InputError naming the file with `why` if it cannot be opened.
void update_from_file(Sha256& h, const std::filesystem::path& path, const char* why = "cannot open file to hash it");

}  // namespace seflex::io

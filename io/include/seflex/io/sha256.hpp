#pragma once
// SHA-256 (FIPS 180-4) for file integrity (superelement files) and source-model hashes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace seflex::io {

class Sha256 {
 public:
  /// Hardware: the x86 SHA extensions where the CPU has them (about 10x the portable code), else the
  /// portable code. Portable: always the portable code (the tests compare the two).
  enum class Implementation { Hardware, Portable };
  explicit Sha256(Implementation impl = Implementation::Hardware);
  /// True when this machine runs the SHA extensions path.
  static bool hardware_available();
  void update(const void* data, std::size_t size);
  void update(std::string_view s) { update(s.data(), s.size()); }
  std::array<std::uint8_t, 32> digest();   ///< finishes the hash; the object must not be updated afterwards
  std::string hex_digest();                 ///< lowercase hex of digest()

 private:
  void blocks(const std::uint8_t* p, std::size_t count);  ///< compresses count 64-byte blocks
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buf_{};
  std::size_t buf_len_ = 0;
  std::uint64_t total_ = 0;
  bool hardware_;
};

/// Hex SHA-256 of a byte string.
std::string sha256_hex(std::string_view data);

/// Hex SHA-256 of a file's bytes; throws InputError if it cannot be read.
std::string sha256_file_hex(const std::filesystem::path& path);

}  // namespace seflex::io

// SHA-256 by nettle (sha2.h): seflex keeps only the interface of io/sha256.hpp.
#include "seflex/io/sha256.hpp"

#include <nettle/sha2.h>

#include <fstream>
#include <new>

#include "seflex/common/error.hpp"

namespace seflex::io {
namespace {
static_assert(sizeof(sha256_ctx) <= 128 && alignof(sha256_ctx) <= 8, "Sha256::state_ cannot hold nettle's sha256_ctx");
}  // namespace

Sha256::Sha256() { sha256_init(new (state_) sha256_ctx); }

void Sha256::update(const void* data, std::size_t size) {
  sha256_update(std::launder(reinterpret_cast<sha256_ctx*>(state_)), size, static_cast<const std::uint8_t*>(data));
}

std::array<std::uint8_t, 32> Sha256::digest() {
  std::array<std::uint8_t, 32> out;
  sha256_digest(std::launder(reinterpret_cast<sha256_ctx*>(state_)), out.size(), out.data());
  return out;
}

std::string Sha256::hex_digest() {
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (std::uint8_t b : digest()) {
    s += hex[b >> 4];
    s += hex[b & 15];
  }
  return s;
}

std::string sha256_hex(std::string_view data) {
  Sha256 h;
  h.update(data);
  return h.hex_digest();
}

void update_from_file(Sha256& h, const std::filesystem::path& path, const char* why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceRef{path.string(), 0}, why);
  std::array<char, 1 << 16> buf;
  while (in) {
    in.read(buf.data(), buf.size());
    h.update(buf.data(), static_cast<std::size_t>(in.gcount()));
  }
}

std::string sha256_file_hex(const std::filesystem::path& path) {
  Sha256 h;
  update_from_file(h, path);
  return h.hex_digest();
}

}  // namespace seflex::io

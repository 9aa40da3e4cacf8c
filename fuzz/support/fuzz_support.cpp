#include "fuzz_support.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <typeinfo>

#include "seflex/common/error.hpp"
#include "seflex/io/sha256.hpp"

namespace seflex::fuzz {

namespace {

struct Scratch {
  std::filesystem::path dir;
  Scratch() {
    std::error_code ec;
    std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec) base = "/tmp";
    std::string pattern = (base / "seflex-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      std::perror("seflex fuzz: mkdtemp");
      std::abort();
    }
    dir = pattern;
  }
  ~Scratch() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

}  // namespace

const std::filesystem::path& scratch_dir() {
  static Scratch s;
  return s.dir;
}

std::filesystem::path write_scratch(const std::string& name, std::string_view bytes) {
  const std::filesystem::path p = scratch_dir() / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    std::fprintf(stderr, "seflex fuzz: cannot write %s\n", p.c_str());
    std::abort();
  }
  return p;
}

void run(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError&) {
    // the expected way to refuse bad input
  } catch (const std::exception& e) {
    std::fprintf(stderr, "seflex fuzz: not an InputError: %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "seflex fuzz: not an InputError: a non-std exception\n");
    std::abort();
  }
}

std::string with_sha256_trailer(const std::string& body) {
  io::Sha256 h;
  h.update(body);
  const auto digest = h.digest();
  std::string out = body;
  out.append("SEFLXEND", 8);
  out.append(reinterpret_cast<const char*>(digest.data()), digest.size());
  return out;
}

bool contains_nocase(std::string_view text, std::string_view word) {
  if (word.empty()) return true;
  auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; };
  for (std::size_t i = 0; i + word.size() <= text.size(); ++i) {
    std::size_t k = 0;
    while (k < word.size() && lower(text[i + k]) == lower(word[k])) ++k;
    if (k == word.size()) return true;
  }
  return false;
}

}  // namespace seflex::fuzz

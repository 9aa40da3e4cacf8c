#pragma once
// Helpers shared by the libFuzzer harnesses (fuzz/fuzz_*.cpp).
//
// Each harness feeds its bytes to one reader and accepts exactly two outcomes: the input reads, or the
// reader throws seflex::InputError. Anything else (another exception, a crash, a sanitizer report, a
// hang or a leak) is a finding: fuzz::run() aborts on an unexpected exception so libFuzzer saves it.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace seflex::fuzz {

/// A private folder for this process (created on first use under $TMPDIR, removed at exit). Harnesses
/// that need files write them only here.
const std::filesystem::path& scratch_dir();

/// Write `bytes` to scratch_dir()/name and return the path.
std::filesystem::path write_scratch(const std::string& name, std::string_view bytes);

/// Call `read`; return normally if it returns or throws seflex::InputError, abort otherwise (with the
/// exception's type and message on stderr).
void run(const std::function<void()>& read);

/// `body` followed by a valid superelement trailer ("SEFLXEND" + SHA-256 of `body`).
std::string with_sha256_trailer(const std::string& body);

/// True if `text` contains `word`, ignoring ASCII case.
bool contains_nocase(std::string_view text, std::string_view word);

}  // namespace seflex::fuzz

// Robustness: random mutations of the validation decks (byte flips, truncations, deleted and
// duplicated lines, swapped fields) must each either read or throw InputError - never crash, hang or
// throw anything else. A fixed seed keeps the run reproducible; CI runs it under ASan + UBSan too.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran.hpp"
#include "test_support.hpp"

using namespace seflex;

namespace {

std::vector<std::string> validation_decks() {
  std::vector<std::string> decks;
  for (const char* rel : {"mystran_cbar_cantilever_and_freefree_modes/BAR-CC-GIV.DAT",
                          "mystran_cbar_cantilever_and_freefree_modes/BAR-FF-GIV.DAT",
                          "mystran_craig_bampton_cbar_frame/CB-EXAMPLE-12.DAT",
                          "mystran_mixed_cbar_crod_cquad4_ctria3_celas_modes/ALL-ELEM-TEST-GIV.DAT"})
    decks.push_back(test::read_file(test::validation_dir() / rel));
  return decks;
}

std::vector<std::size_t> line_starts(const std::string& s) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == '\n') starts.push_back(i + 1);
  return starts;
}

std::string mutate(const std::string& deck, std::mt19937& rng) {
  std::string s = deck;
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  static const std::string alphabet = std::string("0123456789.+-*,$ \t\nEDTHRUGRIDCBAR'\"=") + '\0' + '\r' + "\xff\x01";
  const int kind = static_cast<int>(pick(6));
  const int edits = 1 + static_cast<int>(pick(4));
  for (int e = 0; e < edits && !s.empty(); ++e) {
    switch (kind) {
      case 0:  // byte flips
        s[pick(s.size())] = alphabet[pick(alphabet.size())];
        break;
      case 1:  // truncation
        s.resize(pick(s.size()));
        break;
      case 2: {  // delete a line
        const auto starts = line_starts(s);
        const std::size_t l = pick(starts.size());
        const std::size_t end = l + 1 < starts.size() ? starts[l + 1] : s.size();
        s.erase(starts[l], end - starts[l]);
        break;
      }
      case 3: {  // duplicate a line
        const auto starts = line_starts(s);
        const std::size_t l = pick(starts.size());
        const std::size_t end = l + 1 < starts.size() ? starts[l + 1] : s.size();
        s.insert(starts[l], s.substr(starts[l], end - starts[l]));
        break;
      }
      case 4: {  // swap two 8-column fields of a line
        const auto starts = line_starts(s);
        const std::size_t l = pick(starts.size());
        const std::size_t end = l + 1 < starts.size() ? starts[l + 1] - 1 : s.size();
        if (end - starts[l] < 24) break;
        const std::size_t nf = (end - starts[l]) / 8;
        const std::size_t a = starts[l] + 8 * pick(nf), b = starts[l] + 8 * pick(nf);
        for (std::size_t k = 0; k < 8; ++k) std::swap(s[a + k], s[b + k]);
        break;
      }
      default: {  // insert random bytes
        const std::size_t at = pick(s.size());
        std::string junk;
        for (std::size_t k = 0, n = 1 + pick(12); k < n; ++k) junk += alphabet[pick(alphabet.size())];
        s.insert(at, junk);
        break;
      }
    }
  }
  return s;
}

}  // namespace

TEST(NastranFuzz, MutatedValidationDecksReadOrThrowInputError) {
  const auto decks = validation_decks();
  ASSERT_EQ(decks.size(), 4u);
  for (const auto& d : decks) {
    ASSERT_GT(d.size(), 1000u);  // read_file gives "" for a missing file, and "" reads without error
    EXPECT_NO_THROW(io::read_nastran_text(d, "deck.dat"));
  }
  std::mt19937 rng(20261121);
  int read = 0, rejected = 0;
  constexpr int kMutations = 3000;
  for (int i = 0; i < kMutations; ++i) {
    const std::string text = mutate(decks[static_cast<std::size_t>(i) % decks.size()], rng);
    try {
      io::read_nastran_text(text, "deck.dat");
      ++read;
    } catch (const InputError& e) {
      ++rejected;
      // every message says where: the deck name, and a line number whenever one is known
      ASSERT_EQ(std::string(e.what()).rfind("deck.dat", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      FAIL() << "mutation " << i << " threw a non-input error: " << e.what() << "\n--- deck ---\n" << text;
    }
  }
  // Both outcomes occur: the mutations are neither all harmless nor all fatal.
  EXPECT_GT(read, kMutations / 20);
  EXPECT_GT(rejected, kMutations / 20);
  std::printf("fuzz: %d mutated decks read, %d rejected with InputError\n", read, rejected);
}

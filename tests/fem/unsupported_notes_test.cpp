// fem::UnsupportedNotes (model.hpp): the one add-or-count of Model::unsupported by name that the
// Nastran reader, finalize and the part assembly share.
#include <gtest/gtest.h>

#include "seflex/fem/model.hpp"

namespace seflex::fem {
namespace {

TEST(UnsupportedNotes, CountsByNameInOrderOfFirstNoteKeepingTheFirstCard) {
  std::vector<UnsupportedCard> list;
  UnsupportedNotes notes(list);
  notes.add("DEQATN", {0, 12});
  notes.add("PBEND RC/ZC", {1, 3});
  notes.add("DEQATN", {0, 40});
  notes.add("PBEND RC/ZC", {2, 7}, 5).members.push_back({9, {2, 7}});
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].name, "DEQATN");
  EXPECT_EQ(list[0].count, 2u);
  EXPECT_EQ(list[0].first.file, 0u);
  EXPECT_EQ(list[0].first.line, 12u);  // the first note's card, not the last
  EXPECT_EQ(list[1].name, "PBEND RC/ZC");
  EXPECT_EQ(list[1].count, 6u);  // 1 + 5
  EXPECT_EQ(list[1].first.line, 3u);
  ASSERT_EQ(list[1].members.size(), 1u);
  EXPECT_EQ(list[1].members[0].sid, 9);
  EXPECT_EQ(notes.find("DEQATN"), &list[0]);
  EXPECT_EQ(notes.find("GRAV"), nullptr);
  // a count of zero makes the entry (finalize's notes set the count themselves)
  EXPECT_EQ(notes.add("MAT1 NU above 0.5", {0, 1}, 0).count, 0u);
  EXPECT_EQ(list.size(), 3u);
}

TEST(UnsupportedNotes, ContinuesAListMadeBefore) {
  // a list read from a deck (names unique), then noted to by a later step: the existing entries count on
  std::vector<UnsupportedCard> list{{"DEQATN", 3, {0, 5}, {}}, {"'+ABC'", 1, {0, 9}, {}}};
  UnsupportedNotes notes(list);
  notes.add("'+ABC'", {0, 20});
  notes.add("CONROD on MAT4 (left out)", {0, 30});
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[1].count, 2u);
  EXPECT_EQ(list[1].first.line, 9u);
  EXPECT_EQ(list[2].name, "CONROD on MAT4 (left out)");
  EXPECT_EQ(list[2].count, 1u);
  EXPECT_EQ(list[0].count, 3u);
}

}  // namespace
}  // namespace seflex::fem

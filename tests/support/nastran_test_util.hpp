#pragma once
// Helpers for the Nastran reader tests: writing fixed-format lines column by column, reading decks
// from text, and checking error messages.
#include <gtest/gtest.h>

#include <cstdio>
#include <initializer_list>
#include <string>

#include "seflex/common/error.hpp"
#include "seflex/io/nastran.hpp"

namespace seflex::test {

/// A fixed-format line: field 1 and the data fields padded to `width` columns (8 small, 16 large);
/// `field10` lands in columns 73-80.
inline std::string fixed_line(std::initializer_list<std::string> fields, std::size_t width = 8,
                              const std::string& field10 = "") {
  std::string line;
  bool first = true;
  for (const auto& f : fields) {
    const std::size_t w = first ? 8 : width;
    std::string s = f.substr(0, w);
    s.resize(w, ' ');
    line += s;
    first = false;
  }
  if (!field10.empty()) {
    line.resize(72, ' ');
    line += field10;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line + "\n";
}

/// A real number for a free-field bulk-data line, exact to the last bit ("%.17g", with a decimal
/// point so that it reads as a real).
inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s(buf);
  if (s.find_first_of(".e") == std::string::npos) s += ".";
  return s;
}

inline fem::Model read_deck(const std::string& text, const std::string& name = "deck.bdf") {
  return io::read_nastran_text(text, name);
}

/// The InputError message of `read()` ("" and a test failure if it returns; the message and a test
/// failure if it throws anything else).
template <class F>
std::string input_error(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "read without error";
  return "";
}

/// The InputError message reading `text` gives ("" and a test failure if it reads).
inline std::string read_error(const std::string& text, const std::string& name = "deck.bdf") {
  return input_error([&] { io::read_nastran_text(text, name); });
}

/// Every part appears in the message.
inline ::testing::AssertionResult mentions(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& p : parts)
    if (message.find(p) == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks \"" << p << "\": " << message;
  return ::testing::AssertionSuccess();
}

/// Minimal valid bulk data around a card under test (material, shell property, four grids).
inline std::string base_deck() {
  return "MAT1,1,2.1+11,,0.3,7800.\n"
         "PSHELL,1,1,0.002,1\n"
         "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n";
}

}  // namespace seflex::test

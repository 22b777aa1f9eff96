#pragma once
// What a test of bad input compares: the message of the error that a piece of
// code throws, as the user would read it, or "no error" when it throws none
// (so that a missing error fails the comparison with a readable diff).

#include <string>

namespace hemiroll::test {

template <class Error, class Code>
std::string messageOf(Code&& code) {
  try {
    code();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace hemiroll::test

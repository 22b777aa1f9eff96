#include "tests/support/XmlCheck.h"

#include <expat.h>

namespace hemiroll::test {

std::string xmlProblem(const std::string& text) {
  XML_Parser parser = XML_ParserCreate("UTF-8");
  if (parser == nullptr) return "cannot create an XML parser";
  std::string problem;
  if (XML_Parse(parser, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_ERROR) {
    problem = "line " + std::to_string(XML_GetCurrentLineNumber(parser)) + ", column " +
              std::to_string(XML_GetCurrentColumnNumber(parser)) + ": " + XML_ErrorString(XML_GetErrorCode(parser));
  }
  XML_ParserFree(parser);
  return problem;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace hemiroll::test

#include "engine/script/LevelSourceMap.h"

#include "engine/script/LevelFieldChecks.h"

#include <cctype>
#include <cstddef>
#include <cstring>
#include <string_view>

namespace hemiroll::script {

namespace {

enum class Kind { Name, String, Number, Op, End };

// A token's text is a view into the source (names, numbers, operators; a
// short string's contents as written, escapes not undone): the map of a
// 4 MiB file must not cost hundreds of megabytes (issue 33).
struct Token {
  Kind kind;
  std::string_view text;
  int line;
};

// The map is for error messages; its cost is bounded whatever the text: past
// these it stops reading or building, and lines it did not reach fall back
// to the return's line (or line 1). A few tens of megabytes at most.
constexpr std::size_t kMaxTokens = 1'000'000;
constexpr std::size_t kMaxConstructors = 100'000;
constexpr std::size_t kMaxFields = 500'000;

// Level of a long bracket "[==[" starting at i ('[' at i), or -1.
int longBracketLevel(std::string_view s, std::size_t i) {
  std::size_t j = i + 1;
  while (j < s.size() && s[j] == '=') ++j;
  return j < s.size() && s[j] == '[' ? static_cast<int>(j - i - 1) : -1;
}

// Skips a long bracket body from just after its opening; counts lines.
std::size_t skipLong(std::string_view s, std::size_t i, int level, int& line) {
  while (i < s.size()) {
    if (s[i] == '\n') ++line;
    if (s[i] == ']') {
      std::size_t j = i + 1;
      while (j < s.size() && s[j] == '=') ++j;
      if (j < s.size() && s[j] == ']' && static_cast<int>(j - i - 1) == level) return j + 1;
    }
    ++i;
  }
  return i;
}

// The end of a short string whose text starts at i (after its opening
// quote): the index of the closing quote, of a line break the string may not
// hold, or s.size(). Escapes are skipped; line counts the lines they span.
std::size_t shortStringEnd(std::string_view s, std::size_t i, char quote, int& line) {
  while (i < s.size() && s[i] != quote && s[i] != '\n') {
    if (s[i] == '\\' && i + 1 < s.size()) {
      // "\z" skips the white space after it, line breaks included; a
      // backslash before a line break continues the string on the next
      // line. Both move the line count on (issue 33: after a "\z" every
      // error pointed at line 1).
      if (s[i + 1] == 'z') {
        i += 2;
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) line += s[i++] == '\n';
        continue;
      }
      if (s[i + 1] == '\n' || s[i + 1] == '\r') {
        ++line;
        i += 2;
        if (i < s.size() && (s[i] == '\n' || s[i] == '\r') && s[i] != s[i - 1]) ++i;  // \r\n or \n\r
        continue;
      }
      i += 2;
      continue;
    }
    ++i;
  }
  return i;
}

// The end of a numeral starting at i (hex, exponents with their signs).
std::size_t numberEnd(std::string_view s, std::size_t i) {
  std::size_t j = i;
  while (j < s.size()) {
    const char d = s[j];
    const bool exponentSign = (d == '+' || d == '-') && j > i && std::strchr("eEpP", s[j - 1]) != nullptr;
    if (!(std::isalnum(static_cast<unsigned char>(d)) || d == '.' || exponentSign)) break;
    ++j;
  }
  return j;
}

// Operators: the two- and three-character ones matter only so that "=="
// is never read as "=".
std::size_t operatorLength(std::string_view s, std::size_t i) {
  static const char* const kLong[] = {"...", "==", "~=", "<=", ">=", "//", "::", "<<", ">>", ".."};
  std::size_t length = 1;
  for (const char* candidate : kLong)
    if (s.substr(i, std::strlen(candidate)) == candidate) { length = std::strlen(candidate); break; }
  return length;
}

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  while (i < s.size() && out.size() < kMaxTokens) {
    const char c = s[i];
    if (c == '\n') { ++line; ++i; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (c == '-' && i + 1 < s.size() && s[i + 1] == '-') {
      i += 2;
      if (i < s.size() && s[i] == '[') {
        const int level = longBracketLevel(s, i);
        if (level >= 0) { i = skipLong(s, i + static_cast<std::size_t>(level) + 2, level, line); continue; }
      }
      while (i < s.size() && s[i] != '\n') ++i;
      continue;
    }
    if (c == '[') {
      const int level = longBracketLevel(s, i);
      if (level >= 0) {
        const int startLine = line;
        i = skipLong(s, i + static_cast<std::size_t>(level) + 2, level, line);
        out.push_back({Kind::String, "", startLine});
        continue;
      }
    }
    if (c == '"' || c == '\'') {
      const int startLine = line;
      const std::size_t start = ++i;
      i = shortStringEnd(s, i, c, line);
      out.push_back({Kind::String, s.substr(start, std::min(i, s.size()) - start), startLine});
      ++i;
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      out.push_back({Kind::Name, s.substr(i, j - i), line});
      i = j;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      const std::size_t j = numberEnd(s, i);
      out.push_back({Kind::Number, s.substr(i, j - i), line});
      i = j;
      continue;
    }
    const std::size_t length = operatorLength(s, i);
    out.push_back({Kind::Op, s.substr(i, length), line});
    i += length;
  }
  out.push_back({Kind::End, "", line});
  return out;
}

bool isOp(const Token& t, const char* op) { return t.kind == Kind::Op && t.text == op; }
bool isName(const Token& t, const char* name) { return t.kind == Kind::Name && t.text == name; }
int blockDelta(const Token& t) {
  if (t.kind != Kind::Name) return 0;
  if (t.text == "function" || t.text == "do" || t.text == "if" || t.text == "repeat") return 1;
  if (t.text == "end" || t.text == "until") return -1;
  return 0;
}

}  // namespace

struct LevelSourceMap::Constructor {
  struct Field {
    std::string key;  // a name or string key; "[n]" for positions and integer keys
    int line;
    const Constructor* child;  // the value's constructor, when it is one
  };
  int line = 1;
  std::vector<Field> fields;
};

namespace {

using Constructor = LevelSourceMap::Constructor;

class Builder {
 public:
  Builder(const std::vector<Token>& tokens, std::vector<std::unique_ptr<Constructor>>& all)
      : tokens_(tokens), all_(all) {}

  // tokens[i] is '{'; returns the index after the matching '}'. Lua refuses
  // sources nested deeper than ~200 levels before any line is asked for;
  // the guard keeps the recursion bounded for any text.
  std::size_t parse(std::size_t i, const Constructor** made, int depth = 0) {
    if (depth > kMaxDepth || all_.size() >= kMaxConstructors) return skipConstructor(i);
    auto node = std::make_unique<Constructor>();
    Constructor* self = node.get();
    all_.push_back(std::move(node));
    if (made != nullptr) *made = self;
    self->line = t_(i).line;
    ++i;
    long long position = 0;
    bool entryStart = true;
    int nesting = 0;  // (), [] and blocks inside the current entry
    while (t_(i).kind != Kind::End) {
      const Token& tok = t_(i);
      if (nesting == 0 && isOp(tok, "}")) return i + 1;
      if (nesting == 0 && (isOp(tok, ",") || isOp(tok, ";"))) { entryStart = true; ++i; continue; }
      if (entryStart) {
        entryStart = false;
        std::string key;
        std::size_t value = i;
        if (tok.kind == Kind::Name && isOp(t_(i + 1), "=") && blockDelta(tok) == 0) {
          key = std::string(tok.text);
          value = i + 2;
        } else if (isOp(tok, "[") && t_(i + 2).kind != Kind::End && isOp(t_(i + 2), "]") && isOp(t_(i + 3), "=")) {
          key = t_(i + 1).kind == Kind::Number ? bracketed(std::string(t_(i + 1).text)) : std::string(t_(i + 1).text);
          value = i + 4;
        } else {
          key = positionKey(++position);
        }
        const Constructor* child = nullptr;
        if (isOp(t_(value), "{")) {
          const bool kept = addField(*self, key, tok.line);
          const std::size_t after = parse(value, &child, depth + 1);
          if (kept) self->fields.back().child = child;
          i = after;
          continue;
        }
        addField(*self, key, tok.line);
        i = value;
        continue;
      }
      if (isOp(tok, "{")) { i = parse(i, nullptr, depth + 1); continue; }
      if (isOp(tok, "(") || isOp(tok, "[")) ++nesting;
      if ((isOp(tok, ")") || isOp(tok, "]")) && nesting > 0) --nesting;
      nesting += blockDelta(tok);
      if (nesting < 0) nesting = 0;
      ++i;
    }
    return i;
  }

 private:
  static constexpr int kMaxDepth = 400;

  bool addField(Constructor& c, const std::string& key, int line) {
    if (fields_ >= kMaxFields) return false;
    ++fields_;
    c.fields.push_back({key, line, nullptr});
    return true;
  }
  std::size_t fields_ = 0;

  // Past the '}' matching the '{' at i, without building anything.
  std::size_t skipConstructor(std::size_t i) const {
    int open = 0;
    for (; t_(i).kind != Kind::End; ++i) {
      if (isOp(t_(i), "{")) ++open;
      if (isOp(t_(i), "}") && --open == 0) return i + 1;
    }
    return i;
  }
  // Token k, or the final End token past the end.
  const Token& t_(std::size_t k) const { return k < tokens_.size() ? tokens_[k] : tokens_.back(); }

  const std::vector<Token>& tokens_;
  std::vector<std::unique_ptr<Constructor>>& all_;
};

// Splits "a.b[2].c" into "a", "b", "[2]", "c".
std::vector<std::string> splitPath(std::string_view path) {
  std::vector<std::string> out;
  std::string current;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    if (c == '.') {
      if (!current.empty()) out.push_back(current);
      current.clear();
    } else if (c == '[') {
      if (!current.empty()) out.push_back(current);
      current.assign(1, '[');
    } else if (c == ']') {
      out.push_back(current + "]");
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

}  // namespace

LevelSourceMap::LevelSourceMap(std::string_view source) {
  const std::vector<Token> tokens = tokenize(source);
  Builder builder(tokens, constructors_);
  // Top-level constructors, the last top-level `return` and what it returns,
  // and `name = {` assignments at the top level.
  int depth = 0;
  const Constructor* returned = nullptr;
  std::string returnedName;
  std::vector<std::pair<std::string, const Constructor*>> assigned;
  const auto at = [&](std::size_t k) -> const Token& { return k < tokens.size() ? tokens[k] : tokens.back(); };
  for (std::size_t i = 0; tokens[i].kind != Kind::End;) {
    const Token& tok = tokens[i];
    if (depth == 0 && isName(tok, "return")) {
      fallbackLine_ = tok.line;
      returned = nullptr;
      returnedName.clear();
      if (isOp(at(i + 1), "{")) {
        i = builder.parse(i + 1, &returned);
        continue;
      }
      if (at(i + 1).kind == Kind::Name) returnedName = std::string(at(i + 1).text);
    }
    if (isOp(tok, "{")) {
      const Constructor* made = nullptr;
      const bool assignment = i >= 2 && isOp(tokens[i - 1], "=") && tokens[i - 2].kind == Kind::Name;
      const std::size_t after = builder.parse(i, &made);
      if (assignment && depth == 0) assigned.emplace_back(std::string(tokens[i - 2].text), made);
      i = after;
      continue;
    }
    depth += blockDelta(tok);
    if (depth < 0) depth = 0;
    ++i;
  }
  if (returned == nullptr && !returnedName.empty())
    for (const auto& [name, made] : assigned)
      if (name == returnedName) returned = made;  // the last assignment wins
  root_ = returned;
  if (root_ != nullptr) fallbackLine_ = root_->line;
}

LevelSourceMap::~LevelSourceMap() = default;
LevelSourceMap::LevelSourceMap(LevelSourceMap&&) noexcept = default;
LevelSourceMap& LevelSourceMap::operator=(LevelSourceMap&&) noexcept = default;

int LevelSourceMap::lineOf(std::string_view path) const {
  int line = fallbackLine_;
  const Constructor* node = root_;
  for (const std::string& segment : splitPath(path)) {
    if (node == nullptr) break;
    const Constructor::Field* found = nullptr;
    for (const auto& field : node->fields)
      if (field.key == segment) found = &field;  // a repeated key: Lua keeps the last
    if (found == nullptr) break;
    line = found->line;
    node = found->child;
  }
  return line;
}

}  // namespace hemiroll::script

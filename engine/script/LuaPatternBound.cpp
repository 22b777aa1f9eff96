#include "engine/script/LuaPatternBound.h"

#include <cmath>
#include <deque>

namespace hemiroll::script {

namespace {

// The end of the single-character class that starts at `i` (one past it),
// as the matcher's classEnd finds it; npos for a malformed class.
constexpr std::size_t kMalformed = std::string_view::npos;

std::size_t classEnd(std::string_view p, std::size_t i) {
  if (p[i] == '%') return i + 1 < p.size() ? i + 2 : kMalformed;
  if (p[i] == '[') {
    std::size_t j = i + 1;
    if (j < p.size() && p[j] == '^') ++j;
    // The first character of a set is a member even when it is ']'.
    do {
      if (j >= p.size()) return kMalformed;
      if (p[j] == '%') ++j;
      ++j;
    } while (j < p.size() && p[j] != ']');
    return j < p.size() ? j + 1 : kMalformed;
  }
  return i + 1;
}

bool isSuffix(char c) { return c == '*' || c == '+' || c == '-' || c == '?'; }

// W as coefficients of C(m+d, d), scaled: a_d = scale * coefficient[d].
class Bound {
 public:
  void addConstant(double c) { coefficient(0) += c / scale_; }
  void addLinear(double c) { coefficient(1) += c / scale_; }  // c (m+1)
  void twice() { scale_ *= 2.0; }
  void sumOverLengths() { coefficients_.push_front(0.0); }  // sum_{j<=m} W(j)
  double valueAt(double m) const {
    double total = 0.0, binomial = 1.0;  // C(m+d, d)
    for (std::size_t d = 0; d < coefficients_.size(); ++d) {
      if (d > 0) binomial *= (m + static_cast<double>(d)) / static_cast<double>(d);
      total += coefficients_[d] * binomial;
      if (!std::isfinite(total)) return HUGE_VAL;
    }
    return total * scale_;
  }

 private:
  double& coefficient(std::size_t d) {
    if (coefficients_.size() <= d) coefficients_.resize(d + 1, 0.0);
    return coefficients_[d];
  }
  std::deque<double> coefficients_{1.0};  // the end of the pattern: 1 step
  double scale_ = 1.0;
};

enum class Kind { Step, Scan, Class };
struct Item {
  Kind kind;
  double length = 1.0;  // the class's text
  char suffix = '\0';
};

}  // namespace

int repeatedItems(std::string_view p) {
  int repeats = 0;
  std::size_t i = !p.empty() && p[0] == '^' ? 1 : 0;
  while (i < p.size()) {
    if (p[i] == '(' || p[i] == ')') {
      ++i;
      continue;
    }
    const bool special = p[i] == '%' && i + 1 < p.size() && (p[i + 1] == 'b' || p[i + 1] == 'f');
    const std::size_t end = classEnd(p, i);
    if (end == kMalformed) break;
    i = end;
    if (!special && i < p.size() && isSuffix(p[i])) {
      ++repeats;
      ++i;
    }
  }
  return repeats;
}

double patternStepBound(std::string_view pattern, std::size_t subjectLength, PatternUse use) {
  const double n = static_cast<double>(subjectLength);
  const bool anchored = use != PatternUse::Gmatch && !pattern.empty() && pattern[0] == '^';
  std::string_view p = anchored ? pattern.substr(1) : pattern;

  // The items in order, as match() walks them.
  std::deque<Item> items;
  for (std::size_t i = 0; i < p.size();) {
    const char c = p[i];
    if (c == '(') {
      items.push_back({Kind::Step});
      i += i + 1 < p.size() && p[i + 1] == ')' ? 2 : 1;
    } else if (c == ')' || (c == '$' && i + 1 == p.size())) {
      items.push_back({Kind::Step});
      ++i;
    } else if (c == '%' && i + 1 < p.size() && p[i + 1] == 'b') {
      items.push_back({Kind::Scan});
      i += 4;
    } else if (c == '%' && i + 1 < p.size() && p[i + 1] == 'f') {
      const std::size_t end = i + 2 < p.size() ? classEnd(p, i + 2) : kMalformed;
      if (end == kMalformed) return static_cast<double>(pattern.size());
      items.push_back({Kind::Class, static_cast<double>(end - i)});
      i = end;
    } else if (c == '%' && i + 1 < p.size() && p[i + 1] >= '0' && p[i + 1] <= '9') {
      items.push_back({Kind::Scan});
      i += 2;
    } else {
      const std::size_t end = classEnd(p, i);
      if (end == kMalformed) return static_cast<double>(pattern.size());
      Item item{Kind::Class, static_cast<double>(end - i)};
      i = end;
      if (i < p.size() && isSuffix(p[i])) item.suffix = p[i++];
      items.push_back(item);
    }
  }

  Bound w;
  for (auto item = items.rbegin(); item != items.rend(); ++item) {
    switch (item->kind) {
      case Kind::Step: w.addConstant(1.0); break;
      case Kind::Scan:
        w.addConstant(1.0);
        w.addLinear(1.0);
        break;
      case Kind::Class:
        if (item->suffix == '?') {
          w.twice();
        } else if (item->suffix != '\0') {  // '*', '+', '-'
          w.sumOverLengths();
          w.addLinear(item->length);
          break;
        }
        w.addConstant(item->length);
        break;
    }
  }
  const double starts = anchored ? 1.0 : (use == PatternUse::FindOrMatch ? n + 1.0 : 2.0 * (n + 1.0));
  return starts * w.valueAt(n);
}

}  // namespace hemiroll::script

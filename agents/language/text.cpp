#include "agents/language/text.hpp"

#include <cctype>
#include <charconv>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace chatsim::agents::text {
namespace {

const std::map<std::string, std::string>& spellings() {
  static const std::map<std::string, std::string> m{
      {"metres", "meters"}, {"metre", "meter"}, {"kilometres", "kilometers"}, {"kilometre", "kilometer"},
      {"centimetres", "centimeters"}, {"centimetre", "centimeter"}, {"colour", "color"}, {"grey", "gray"},
      {"towards", "toward"}, {"kph", "km/h"}, {"kmh", "km/h"}, {"kmph", "km/h"}, {"mins", "minutes"},
      {"centre", "center"}, {"recolour", "recolor"}, {"kerb", "curb"}, {"kerbs", "curbs"}, {"lorry", "truck"},
      {"lorries", "trucks"}, {"tyre", "tire"}, {"u", "you"}, {"pls", "please"}, {"plz", "please"},
      {"fwd", "forward"}, {"thx", "thanks"}, {"bkwd", "backward"}, {"lhs", "left side"}, {"rhs", "right side"},
      {"w/", "with"}, {"w/o", "without"}, {"veh", "vehicle"}, {"vehs", "vehicles"}, {"approx", "about"},
      {"yd", "yards"}, {"yds", "yards"}, {"ped", "pedestrian"}, {"peds", "pedestrians"}, {"del", "delete"},
      {"rm", "remove"}};
  return m;
}

const std::map<std::string, double>& number_words() {
  static const std::map<std::string, double> m{
      {"zero", 0},      {"one", 1},        {"two", 2},        {"three", 3},     {"four", 4},
      {"five", 5},      {"six", 6},        {"seven", 7},      {"eight", 8},     {"nine", 9},
      {"ten", 10},      {"eleven", 11},    {"twelve", 12},    {"thirteen", 13}, {"fourteen", 14},
      {"fifteen", 15},  {"sixteen", 16},   {"seventeen", 17}, {"eighteen", 18}, {"nineteen", 19},
      {"twenty", 20},   {"thirty", 30},    {"forty", 40},     {"fifty", 50},    {"sixty", 60},
      {"seventy", 70},  {"eighty", 80},    {"ninety", 90},    {"hundred", 100}, {"dozen", 12},
      {"a", 1},         {"an", 1},         {"single", 1},     {"half", 0.5},    {"couple", 2},
      {"pair", 2},      {"few", 3},        {"several", 4},    {"thousand", 1000}};
  return m;
}

std::optional<double> parse_digits(const std::string& s) {
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.' || s[0] == '-')) return std::nullopt;
  double v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

// Accented Latin letters as their plain letter ("Škoda" -> "Skoda"), typographic quotes and
// dashes as ASCII, and the degree sign as a word: users write all of these.
std::string fold_characters(std::string_view s) {
  static const std::vector<std::pair<std::string_view, std::string_view>> table{
      {"à", "a"}, {"á", "a"}, {"â", "a"}, {"ã", "a"}, {"ä", "a"}, {"å", "a"}, {"À", "a"}, {"Á", "a"},
      {"Â", "a"}, {"Ã", "a"}, {"Ä", "a"}, {"Å", "a"}, {"ç", "c"}, {"č", "c"}, {"ć", "c"}, {"Ç", "c"},
      {"Č", "c"}, {"Ć", "c"}, {"è", "e"}, {"é", "e"}, {"ê", "e"}, {"ë", "e"}, {"ě", "e"}, {"È", "e"},
      {"É", "e"}, {"Ê", "e"}, {"Ë", "e"}, {"Ě", "e"}, {"ì", "i"}, {"í", "i"}, {"î", "i"}, {"ï", "i"},
      {"Ì", "i"}, {"Í", "i"}, {"Î", "i"}, {"Ï", "i"}, {"ñ", "n"}, {"ń", "n"}, {"ň", "n"}, {"Ñ", "n"},
      {"Ń", "n"}, {"Ň", "n"}, {"ò", "o"}, {"ó", "o"}, {"ô", "o"}, {"õ", "o"}, {"ö", "o"}, {"ø", "o"},
      {"Ò", "o"}, {"Ó", "o"}, {"Ô", "o"}, {"Õ", "o"}, {"Ö", "o"}, {"Ø", "o"}, {"ù", "u"}, {"ú", "u"},
      {"û", "u"}, {"ü", "u"}, {"ů", "u"}, {"Ù", "u"}, {"Ú", "u"}, {"Û", "u"}, {"Ü", "u"}, {"Ů", "u"},
      {"ý", "y"}, {"ÿ", "y"}, {"Ý", "y"}, {"š", "s"}, {"ś", "s"}, {"Š", "s"}, {"Ś", "s"}, {"ž", "z"},
      {"ź", "z"}, {"ż", "z"}, {"Ž", "z"}, {"Ź", "z"}, {"Ż", "z"}, {"ř", "r"}, {"Ř", "r"}, {"ł", "l"},
      {"Ł", "l"}, {"ğ", "g"}, {"Ğ", "g"}, {"ß", "ss"}, {"°", " degrees "}, {"–", " "}, {"—", " "}, {"’", "'"},
      {"‘", "'"}, {"“", " "}, {"”", " "}};
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    bool replaced = false;
    if (static_cast<unsigned char>(s[i]) >= 0x80)
      for (const auto& [from, to] : table)
        if (s.substr(i, from.size()) == from) {
          out += to;
          i += from.size();
          replaced = true;
          break;
        }
    if (!replaced) out += s[i++];
  }
  return out;
}

constexpr const char* kOrdinals[] = {"first", "second", "third", "fourth", "fifth",
                                     "sixth", "seventh", "eighth", "ninth", "tenth"};

// "2nd", "3rd" (split as "2" "nd" above) -> "second", "third": one spelling for every reader.
void ordinals_to_words(std::vector<std::string>& w) {
  for (size_t i = 0; i + 1 < w.size(); ++i) {
    const auto& suffix = w[i + 1];
    if (suffix != "st" && suffix != "nd" && suffix != "rd" && suffix != "th") continue;
    int n = 0;
    const auto [ptr, ec] = std::from_chars(w[i].data(), w[i].data() + w[i].size(), n);
    if (ec != std::errc() || ptr != w[i].data() + w[i].size() || n < 1 || n > 10) continue;
    w[i] = kOrdinals[n - 1];
    w.erase(w.begin() + long(i) + 1);
  }
}

}  // namespace

int ordinal_value(const std::string& w) {
  for (int i = 0; i < 10; ++i)
    if (w == kOrdinals[i]) return i + 1;
  return 0;
}

std::vector<std::string> words(std::string_view s_in) {
  const std::string folded = fold_characters(s_in);
  const std::string_view s = folded;
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    while (!cur.empty() && cur.back() == '.') cur.pop_back();
    while (!cur.empty() && cur.front() == '.' && (cur.size() < 2 || !std::isdigit(static_cast<unsigned char>(cur[1]))))
      cur.erase(cur.begin());
    if (!cur.empty()) {
      const auto it = spellings().find(cur);
      if (it == spellings().end()) {
        out.push_back(cur);
      } else {  // "lhs" -> "left side": an abbreviation may stand for several words
        for (size_t from = 0; from <= it->second.size();) {
          const size_t space = std::min(it->second.find(' ', from), it->second.size());
          out.push_back(it->second.substr(from, space - from));
          from = space + 1;
        }
      }
    }
    cur.clear();
  };
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    // '-' joins only a sign to a number ("-3"); "front-left" is two words.
    const bool sign = c == '-' && cur.empty() && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]));
    if (std::isalnum(c) || c == '.' || sign || c == '/' || c >= 0x80) {
      // "5m" and "30km/h" split into number and unit.
      if (!cur.empty() && std::isalpha(c) && std::isdigit(static_cast<unsigned char>(cur.back()))) flush();
      cur.push_back(char(std::tolower(c)));
    } else if (c == '&') {  // "delete the truck & move the camera"
      flush();
      out.push_back("and");
    } else if (c == '\'' && !cur.empty()) {
      // "don't" -> "dont"; "car's" -> "car"
      if (i + 1 < s.size() && (s[i + 1] == 's' || s[i + 1] == 'S') &&
          (i + 2 >= s.size() || !std::isalpha(static_cast<unsigned char>(s[i + 2])))) {
        ++i;
        flush();
      }
    } else {
      flush();
    }
  }
  flush();
  ordinals_to_words(out);
  // "m/s" stays one word; "km/h" too.
  return out;
}

std::set<std::string> capitalised_words(std::string_view sentence) {
  std::set<std::string> out;
  const size_t first = sentence.find_first_not_of(" \t\"'(");
  for (size_t i = 0; i < sentence.size(); ++i) {
    const auto c = static_cast<unsigned char>(sentence[i]);
    if (!std::isalpha(c) || (i > 0 && std::isalnum(static_cast<unsigned char>(sentence[i - 1])))) continue;
    size_t end = i;
    while (end < sentence.size() && std::isalnum(static_cast<unsigned char>(sentence[end]))) ++end;
    if (std::isupper(c) && i != first && end - i > 1) {
      std::string word(sentence.substr(i, end - i));
      for (auto& ch : word) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      out.insert(word);
    }
    i = end;
  }
  return out;
}

std::string join(const std::vector<std::string>& w, size_t begin, size_t end) {
  std::string out;
  for (size_t i = begin; i < std::min(end, w.size()); ++i) {
    if (!out.empty()) out += ' ';
    out += w[i];
  }
  return out;
}

size_t find_phrase(const std::vector<std::string>& w, std::string_view phrase, size_t from) {
  return find_words(w, words(phrase), from);
}

size_t find_words(const std::vector<std::string>& w, const std::vector<std::string>& p, size_t from) {
  if (p.empty()) return std::string::npos;
  for (size_t i = from; i + p.size() <= w.size(); ++i) {
    bool match = true;
    for (size_t k = 0; k < p.size() && match; ++k) match = w[i + k] == p[k];
    if (match) return i;
  }
  return std::string::npos;
}

bool has_phrase(const std::vector<std::string>& w, std::string_view phrase) {
  return find_phrase(w, phrase) != std::string::npos;
}

bool has_any(const std::vector<std::string>& w, std::initializer_list<std::string_view> phrases) {
  for (auto p : phrases)
    if (has_phrase(w, p)) return true;
  return false;
}

size_t find_any(const std::vector<std::string>& w, std::initializer_list<std::string_view> phrases, size_t* length) {
  size_t best = std::string::npos;
  for (auto p : phrases) {
    const size_t at = find_phrase(w, p);
    if (at < best) {
      best = at;
      if (length) *length = words(p).size();
    }
  }
  return best;
}

bool is_number_word(const std::string& w) { return number_words().count(w) > 0 || parse_digits(w).has_value(); }

std::optional<double> number_at(const std::vector<std::string>& w, size_t i, size_t* used) {
  if (i >= w.size()) return std::nullopt;
  if (auto d = parse_digits(w[i])) {
    if (used) *used = 1;
    // "1 and a half"
    if (i + 3 < w.size() && w[i + 1] == "and" && w[i + 2] == "a" && w[i + 3] == "half") {
      if (used) *used = 4;
      return *d + 0.5;
    }
    return d;
  }
  const auto& nw = number_words();
  auto it = nw.find(w[i]);
  if (it == nw.end()) return std::nullopt;
  double v = it->second;
  size_t n = 1;
  if (w[i] == "half" && i + 1 < w.size() && (w[i + 1] == "a" || w[i + 1] == "an")) n = 2;   // "half a meter"
  if ((w[i] == "a" || w[i] == "an") && i + 1 < w.size()) {
    const auto next = nw.find(w[i + 1]);
    if (w[i + 1] == "half") {  // "a half meter"
      v = 0.5;
      n = 2;
    } else if (next != nw.end() && next->second > 1) {  // "a dozen", "a couple of", "a few"
      v = next->second;
      n = 2;
    }
  }
  if (v >= 20 && v < 100 && i + n < w.size()) {  // "twenty five"
    const auto unit = nw.find(w[i + n]);
    if (unit != nw.end() && unit->second >= 1 && unit->second < 10 && w[i + n] != "a" && w[i + n] != "an") {
      v += unit->second;
      ++n;
    }
  }
  if (i + n < w.size() && (w[i + n] == "hundred" || w[i + n] == "thousand") && v < 100) {
    v *= nw.at(w[i + n]);
    ++n;
  }
  if (v >= 1 && i + n + 2 < w.size() && w[i + n] == "and" && w[i + n + 1] == "a" && w[i + n + 2] == "half") {
    v += 0.5;  // "one and a half", "seven and a half"
    n += 3;
  }
  if (i + n < w.size() && w[i + n] == "of") ++n;  // "a couple of"
  if (used) *used = n;
  return v;
}

std::vector<Quantity> quantities(const std::vector<std::string>& w, std::initializer_list<std::string_view> units) {
  return quantities(w, std::vector<std::string_view>(units));
}

const std::vector<std::string_view>& length_units() {
  static const std::vector<std::string_view> kUnits{"meters", "meter", "m", "feet", "foot", "ft", "yards", "yard",
                                                    "km", "kilometers", "kilometer", "miles", "mile", "centimeters",
                                                    "cm", "car lengths", "car length", "bus lengths",
                                                    "bus length", "lane widths", "lane width"};
  return kUnits;
}

std::optional<double> meters_per(std::string_view unit) {
  static const std::map<std::string_view, double> kMeters{
      {"meters", 1.0},     {"meter", 1.0},         {"m", 1.0},          {"feet", 0.3048},  {"foot", 0.3048},
      {"ft", 0.3048},      {"yards", 0.9144},      {"yard", 0.9144},    {"km", 1000.0},    {"kilometers", 1000.0},
      {"kilometer", 1000.0}, {"miles", 1609.344}, {"mile", 1609.344}, {"centimeters", 0.01}, {"cm", 0.01},
      // "two car lengths ahead": a typical car (4.5 m), bus (12 m) and lane (3.5 m).
      {"car lengths", 4.5}, {"car length", 4.5}, {"bus lengths", 12.0}, {"bus length", 12.0},
      {"lane widths", 3.5}, {"lane width", 3.5}};
  const auto it = kMeters.find(unit);
  return it == kMeters.end() ? std::nullopt : std::optional<double>(it->second);
}

std::vector<Quantity> quantities(const std::vector<std::string>& w, const std::vector<std::string_view>& units) {
  std::vector<Quantity> out;
  for (size_t i = 0; i < w.size(); ++i) {
    size_t used = 0;
    const auto v = number_at(w, i, &used);
    if (!v) continue;
    size_t j = i + used;
    for (auto u : units) {
      const auto uw = words(u);
      bool match = j + uw.size() <= w.size();
      for (size_t k = 0; k < uw.size() && match; ++k) match = w[j + k] == uw[k];
      if (match) {
        size_t end = j + uw.size();
        double value = *v;
        // "a metre and a half": the half comes after the unit.
        if (end + 3 <= w.size() && w[end] == "and" && (w[end + 1] == "a" || w[end + 1] == "one") && w[end + 2] == "half") {
          value += 0.5;
          end += 3;
        }
        out.push_back({value, i, end, std::string(u)});
        i = end - 1;
        break;
      }
    }
  }
  return out;
}

void turns_to_degrees(std::vector<std::string>& w) {
  static const std::pair<const char*, const char*> kTurns[] = {
      {"a quarter of a turn", "90"}, {"a quarter turn", "90"}, {"quarter turn", "90"}, {"half a turn", "180"},
      {"a half turn", "180"},        {"half turn", "180"},      {"a right angle", "90"}, {"a full turn", "360"}};
  for (const auto& [phrase, degrees] : kTurns)
    for (size_t at = find_phrase(w, phrase); at != std::string::npos; at = find_phrase(w, phrase)) {
      const size_t n = words(phrase).size();
      w.erase(w.begin() + long(at), w.begin() + long(at + n));
      w.insert(w.begin() + long(at), {degrees, "degrees"});
    }
  // "turn it a quarter to the left", "a quarter right": a quarter turn that way.
  for (size_t i = 0; i + 1 < w.size(); ++i) {
    if (w[i] != "quarter" || !(w[i + 1] == "left" || w[i + 1] == "right" || w[i + 1] == "to" ||
                               w[i + 1] == "clockwise" || w[i + 1] == "anticlockwise" || w[i + 1] == "counterclockwise"))
      continue;
    const size_t from = i > 0 && (w[i - 1] == "a" || w[i - 1] == "one") ? i - 1 : i;
    w.erase(w.begin() + long(from), w.begin() + long(i + 1));
    w.insert(w.begin() + long(from), {"90", "degrees"});
    i = from + 1;
  }
}

void bare_turns_to_degrees(std::vector<std::string>& w) {
  bool turning = false;
  for (size_t i = 0; i < w.size(); ++i) {
    size_t used = 0;
    if (turning && number_at(w, i, &used)) {  // first: "one and a half" is one number
      const size_t after = i + used;
      if (after == w.size() || has_any({w[after]}, {"and", "then", "to", "left", "right", "up", "down", "clockwise",
                                                    "counterclockwise", "anticlockwise"}))
        w.insert(w.begin() + long(after), "degrees");
      i = after;
      continue;
    }
    if (has_any({w[i]}, {"and", "then", "but", "while"})) turning = false;
    if (has_any({w[i]}, {"rotate", "rotated", "rotating", "pan", "panned", "yaw", "swivel", "spin", "tilt", "tilted"}))
      turning = true;
  }
}

}  // namespace chatsim::agents::text
